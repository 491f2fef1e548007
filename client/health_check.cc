#include "client/health_check.h"

#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/io/zero_copy_stream_impl_lite.h>
#include <google/protobuf/wire_format_lite.h>

#include <cstdint>
#include <future>
#include <utility>
#include <vector>

namespace locator {
namespace {

using google::protobuf::internal::WireFormatLite;

constexpr char kCheckMethod[] = "/grpc.health.v1.Health/Check";
// Both messages keep their one field at number 1.
constexpr int kOnlyField = 1;

grpc::ByteBuffer ToByteBuffer(const std::string& wire) {
  grpc::Slice slice(wire);
  return grpc::ByteBuffer(&slice, 1);
}

bool ToString(const grpc::ByteBuffer& buffer, std::string* wire) {
  std::vector<grpc::Slice> slices;
  if (!buffer.Dump(&slices).ok()) return false;
  wire->clear();
  for (const grpc::Slice& slice : slices) {
    wire->append(reinterpret_cast<const char*>(slice.begin()), slice.size());
  }
  return true;
}

}  // namespace

std::string_view HealthStatusName(HealthStatus status) {
  switch (status) {
    case HealthStatus::kUnknown:
      return "UNKNOWN";
    case HealthStatus::kServing:
      return "SERVING";
    case HealthStatus::kNotServing:
      return "NOT_SERVING";
    case HealthStatus::kServiceUnknown:
      return "SERVICE_UNKNOWN";
  }
  return "UNKNOWN";
}

std::string EncodeHealthCheckRequest(std::string_view service) {
  std::string wire;
  // proto3 leaves a default (empty) string off the wire.
  if (service.empty()) return wire;
  google::protobuf::io::StringOutputStream raw(&wire);
  google::protobuf::io::CodedOutputStream out(&raw);
  WireFormatLite::WriteString(kOnlyField, std::string(service), &out);
  return wire;
}

bool DecodeHealthCheckResponse(std::string_view wire, HealthStatus* status) {
  google::protobuf::io::CodedInputStream in(
      reinterpret_cast<const uint8_t*>(wire.data()),
      static_cast<int>(wire.size()));
  uint32_t value = 0;  // absent means the default, UNKNOWN
  while (const uint32_t tag = in.ReadTag()) {
    if (tag ==
        WireFormatLite::MakeTag(kOnlyField, WireFormatLite::WIRETYPE_VARINT)) {
      if (!in.ReadVarint32(&value)) return false;
    } else if (!WireFormatLite::SkipField(&in, tag)) {
      return false;
    }
  }
  if (!in.ConsumedEntireMessage()) return false;
  // proto3 enums are open: a status newer than this client is UNKNOWN here.
  *status = value <= static_cast<uint32_t>(HealthStatus::kServiceUnknown)
                ? static_cast<HealthStatus>(value)
                : HealthStatus::kUnknown;
  return true;
}

HealthChecker::HealthChecker(std::shared_ptr<grpc::Channel> channel)
    : stub_(std::move(channel)) {}

grpc::Status HealthChecker::Check(grpc::ClientContext* context,
                                  std::string_view service,
                                  HealthStatus* status) {
  const grpc::ByteBuffer request =
      ToByteBuffer(EncodeHealthCheckRequest(service));
  grpc::ByteBuffer response;
  std::promise<grpc::Status> finished;
  stub_.UnaryCall(context, kCheckMethod, grpc::StubOptions(), &request,
                  &response, [&finished](grpc::Status rpc_status) {
                    finished.set_value(std::move(rpc_status));
                  });
  const grpc::Status rpc_status = finished.get_future().get();
  if (!rpc_status.ok()) return rpc_status;
  std::string wire;
  if (!ToString(response, &wire) || !DecodeHealthCheckResponse(wire, status)) {
    return grpc::Status(grpc::StatusCode::INTERNAL,
                        "malformed grpc.health.v1.HealthCheckResponse");
  }
  return grpc::Status::OK;
}

}  // namespace locator
