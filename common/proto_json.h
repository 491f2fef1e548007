// ProtoJson: the one way locator prints a proto message as JSON — protobuf's
// canonical mapping, with the .proto field names and every field present
// (zeros included), as `locator --json` and the HTTP API both show it.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_COMMON_PROTO_JSON_H_
#define LOCATOR_COMMON_PROTO_JSON_H_

#include <google/protobuf/message.h>

#include <string>

namespace locator {

// `message` as one JSON object, without a trailing newline.
std::string ProtoJson(const google::protobuf::Message& message);

}  // namespace locator

#endif  // LOCATOR_COMMON_PROTO_JSON_H_
