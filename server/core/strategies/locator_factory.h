// MakePointLocator: builds a strategy by name.

#ifndef LOCATOR_CORE_LOCATOR_FACTORY_H_
#define LOCATOR_CORE_LOCATOR_FACTORY_H_

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "locator/status.h"
#include "locator/status_or.h"
#include "locator/tuning_options.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/strategies/point_locator.h"

namespace locator {

// Builds the strategy `name` (see StrategyNames()) over `mesh`, which must
// outlive it. InvalidArgument naming the valid strategies for an unknown
// name, or for tuning options out of range.
StatusOr<std::unique_ptr<PointLocator>> MakePointLocator(
    std::string_view name, const ServingMesh& mesh,
    const TuningOptions& options);

}  // namespace locator

#endif  // LOCATOR_CORE_LOCATOR_FACTORY_H_
