#include "common/gis/ogr_dataset_spec.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

#include "common/input_text.h"

namespace locator::gis {
namespace {

constexpr std::string_view kOgrPrefix = "ogr:";
constexpr std::array<std::string_view, 9> kOgrExtensions = {
    ".gpkg", ".shp", ".geojson", ".json", ".fgb",
    ".gml",  ".kml", ".sqlite",  ".gpx"};

std::string Lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return out;
}

bool EndsWith(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() &&
         s.substr(s.size() - suffix.size()) == suffix;
}

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Decodes %XX escapes of one option; false on a malformed escape.
bool PercentDecode(std::string_view in, std::string* out) {
  out->clear();
  for (size_t i = 0; i < in.size(); ++i) {
    if (in[i] != '%') {
      *out += in[i];
      continue;
    }
    if (i + 2 >= in.size()) return false;
    const int high = HexDigit(in[i + 1]);
    const int low = HexDigit(in[i + 2]);
    if (high < 0 || low < 0) return false;
    *out += static_cast<char>(high * 16 + low);
    i += 2;
  }
  return true;
}

}  // namespace

bool IsOgrDatasetSpec(std::string_view spec) {
  if (spec.starts_with(kOgrPrefix)) return true;
  const std::string path = Lower(spec.substr(0, spec.find('?')));
  return std::any_of(
      kOgrExtensions.begin(), kOgrExtensions.end(),
      [&path](std::string_view ext) { return EndsWith(path, ext); });
}

OgrSpecParts SplitOgrDatasetSpec(std::string_view spec) {
  OgrSpecParts parts;
  parts.source = spec;
  if (spec.starts_with(kOgrPrefix)) {
    parts.prefix = spec.substr(0, kOgrPrefix.size());
    parts.source.remove_prefix(kOgrPrefix.size());
  }
  if (const size_t query = parts.source.find('?');
      query != std::string_view::npos) {
    parts.options = parts.source.substr(query);
    parts.source = parts.source.substr(0, query);
  }
  return parts;
}

Status ParseOgrDatasetSpec(std::string_view spec, OgrDatasetSpec* out) {
  *out = OgrDatasetSpec();
  const auto error = [spec](std::string_view what) {
    return Status::InvalidArgument("dataset spec " + QuotedInput(spec) + ": " +
                                   std::string(what));
  };
  const OgrSpecParts parts = SplitOgrDatasetSpec(spec);
  out->source = std::string(parts.source);
  if (out->source.empty()) return error("no source before the options");
  if (parts.options.empty()) return Status::OK();

  std::string_view options = parts.options.substr(1);  // after '?'
  while (!options.empty()) {
    const size_t amp = options.find('&');
    const std::string_view option = options.substr(0, amp);
    options = amp == std::string_view::npos ? std::string_view()
                                            : options.substr(amp + 1);
    if (option.empty()) continue;
    const size_t eq = option.find('=');
    if (eq == std::string_view::npos) {
      return error("option " + QuotedInput(option) + " has no '=VALUE'");
    }
    const std::string name(option.substr(0, eq));
    std::string value;
    if (!PercentDecode(option.substr(eq + 1), &value)) {
      return error("option " + QuotedInput(name) + " has a malformed %-escape");
    }
    if (name == "oo") {
      if (value.find('=') == std::string::npos) {
        return error("open option " + QuotedInput(value) +
                     " is not NAME=VALUE");
      }
      out->open_options.push_back(std::move(value));
      continue;
    }
    std::string* field = nullptr;
    if (name == "layer") field = &out->layer;
    if (name == "z") field = &out->z_field;
    if (name == "where") field = &out->where;
    if (name == "breaklines") field = &out->breaklines_layer;
    if (name == "domain") field = &out->domain_layer;
    if (name == "a_srs") field = &out->assigned_crs;
    if (name == "driver") field = &out->driver;
    if (field == nullptr) {
      return error("unknown option " + QuotedInput(name) +
                   " (known: layer, z, where, breaklines, domain, a_srs, "
                   "oo, driver)");
    }
    // `name` is one of the known options above.
    if (!field->empty()) return error("option '" + name + "' given twice");
    if (value.empty()) return error("option '" + name + "' is empty");
    *field = std::move(value);
  }
  return Status::OK();
}

}  // namespace locator::gis
