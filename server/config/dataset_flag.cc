#include "server/config/dataset_flag.h"

#include <algorithm>

#include "common/flags/flag_value.h"

namespace locator {
namespace {

bool IsNameChar(char c, bool first) {
  const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                     (c >= '0' && c <= '9') || c == '_';
  return alnum || (!first && (c == '.' || c == '-'));
}

}  // namespace

bool IsValidDatasetName(std::string_view name) {
  if (name.empty() || name.size() > kMaxDatasetNameLength) return false;
  for (size_t i = 0; i < name.size(); ++i) {
    if (!IsNameChar(name[i], i == 0)) return false;
  }
  return true;
}

Status ParseDatasetFlag(std::string_view text, DatasetConfig* out) {
  DatasetConfig config;
  config.spec = std::string(text);
  const size_t equals = text.find('=');
  if (equals != std::string_view::npos &&
      IsValidDatasetName(text.substr(0, equals))) {
    config.name = std::string(text.substr(0, equals));
    config.spec = std::string(text.substr(equals + 1));
    config.named = true;
  }
  if (config.spec.empty()) {
    return FlagError("dataset", text, "the dataset spec must not be empty");
  }
  *out = std::move(config);
  return Status::OK();
}

Status ParseDatasetFlags(const std::vector<std::string>& texts,
                         std::vector<DatasetConfig>* out) {
  std::vector<DatasetConfig> datasets;
  for (const std::string& text : texts) {
    DatasetConfig config;
    if (Status status = ParseDatasetFlag(text, &config); !status.ok()) {
      return status;
    }
    if (!config.named && !datasets.empty()) {
      return FlagError("dataset", text,
                       "only the first --dataset may omit NAME= (it is the "
                       "default dataset, named \"default\"); name this one "
                       "NAME=SPEC");
    }
    const bool repeated = std::any_of(
        datasets.begin(), datasets.end(),
        [&](const DatasetConfig& d) { return d.name == config.name; });
    if (repeated) {
      return FlagError("dataset", text,
                       "the name '" + config.name + "' is given twice");
    }
    datasets.push_back(std::move(config));
  }
  *out = std::move(datasets);
  return Status::OK();
}

}  // namespace locator
