// locatord's engine flags: the strategy and its tuning (--strategy, --grid,
// --warmup, --retune-every, --budget), the periodic work
// (--stats-interval-s, --retune-interval-s) and the directories the engine
// keeps files in (--state-dir, --mesh-cache).
//
// Thread-safety: free functions over plain values.

#ifndef LOCATOR_SERVER_CONFIG_ENGINE_FLAGS_H_
#define LOCATOR_SERVER_CONFIG_ENGINE_FLAGS_H_

#include "common/flags/flag_set.h"
#include "locator/status.h"
#include "server/config/server_config.h"

namespace locator {

// Declares the engine flags on `flags`, into `config` (whose values are the
// defaults); `config` must outlive the parse.
void AddEngineFlags(ServerConfig* config, FlagSet* flags);

// The checks that need the whole line: the directories exist (locatord
// makes none) and only the self-tuning strategy has a state to keep.
// InvalidArgument naming the flag otherwise.
Status CheckEngineFlags(const ServerConfig& config);

}  // namespace locator

#endif  // LOCATOR_SERVER_CONFIG_ENGINE_FLAGS_H_
