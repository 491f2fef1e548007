// EngineTestPeer: what a test may reach inside an Engine: its strategy, to
// watch what the engine asks of it.
//
// Thread-safety: call before the engine serves.

#ifndef LOCATOR_TESTS_CORE_ENGINE_TEST_PEER_H_
#define LOCATOR_TESTS_CORE_ENGINE_TEST_PEER_H_

#include <memory>
#include <utility>

#include "locator/engine.h"
#include "server/core/strategies/point_locator.h"

namespace locator {

class EngineTestPeer {
 public:
  // Puts wrap(strategy) in place of `engine`'s strategy.
  template <typename Wrap>
  static void WrapStrategy(Engine& engine, Wrap wrap) {
    engine.locator_ = wrap(std::move(engine.locator_));
  }
};

}  // namespace locator

#endif  // LOCATOR_TESTS_CORE_ENGINE_TEST_PEER_H_
