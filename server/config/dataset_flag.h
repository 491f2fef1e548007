// DatasetConfig: one --dataset flag of locatord, a named dataset spec.
//
// `--dataset NAME=SPEC` names a dataset; `--dataset SPEC` is the dataset
// named "default". The flag is NAME=SPEC exactly when the text before its
// first '=' is a valid dataset name: [A-Za-z0-9_][A-Za-z0-9_.-]* (at most
// kMaxNameLength characters). No spec locatord reads starts that way by
// accident: generators have ':' before any '=' (uniform:N), and options
// come after '?' (x.gpkg?layer=a, dem.tif?max_error=0.5). A file whose path
// does start with such a text ("a=b.csv") is given as "./a=b.csv" or
// "default=a=b.csv".
//
// Thread-safety: plain values and free functions.

#ifndef LOCATOR_SERVER_DATASET_FLAG_H_
#define LOCATOR_SERVER_DATASET_FLAG_H_

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "locator/status.h"

namespace locator {

// The name of the dataset a bare --dataset SPEC gives.
inline constexpr std::string_view kDefaultDatasetName = "default";

struct DatasetConfig {
  std::string name = std::string(kDefaultDatasetName);
  // A file path, generator spec, OGR source, raster or LAS file, with
  // options (see LoadServedDataset).
  std::string spec;
  // Whether the flag named it (NAME=SPEC) rather than being a bare SPEC.
  bool named = false;

  bool operator==(const DatasetConfig&) const = default;
};

inline constexpr size_t kMaxDatasetNameLength = 64;

// Whether `name` is a valid dataset name (see above).
bool IsValidDatasetName(std::string_view name);

// Parses one --dataset flag value. InvalidArgument for an empty spec.
Status ParseDatasetFlag(std::string_view text, DatasetConfig* out);

// Parses every --dataset flag, in order: the first is the default dataset.
// InvalidArgument naming the problem for an empty spec, a repeated name, or
// a bare SPEC that is not the first and only unnamed one (it is the default,
// so it comes first).
Status ParseDatasetFlags(const std::vector<std::string>& texts,
                         std::vector<DatasetConfig>* out);

}  // namespace locator

#endif  // LOCATOR_SERVER_DATASET_FLAG_H_
