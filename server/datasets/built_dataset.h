// BuiltDataset: what building a dataset yields, published as one value so
// that a call never sees an engine with another build's tiles.
//
// Thread-safety: a plain value; its parts are immutable and shared.

#ifndef LOCATOR_SERVER_DATASETS_BUILT_DATASET_H_
#define LOCATOR_SERVER_DATASETS_BUILT_DATASET_H_

#include <memory>

#include "locator/engine.h"
#include "server/datasets/shard_tiles.h"

namespace locator {

struct BuiltDataset {
  std::shared_ptr<Engine> engine;
  // The tiles served, for a tile set; null for any other dataset (which
  // serves every point).
  std::shared_ptr<const ShardTiles> tiles;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_DATASETS_BUILT_DATASET_H_
