// The main() of every test that makes gRPC objects: GoogleTest's, run inside
// a GrpcLifetime (common/grpc_lifetime.h), as locatord's and the clients'
// mains are. gRPC then shuts down on the main thread before the process
// exits, and OpenSSL does no exit-time cleanup that could race a gRPC
// thread still finishing TLS work: the likeliest source of the ASAN "double
// free in thread T7" that CI runs reported from processes they did not name
// (grpc/grpc pull request 42608 proposes the same for this race).

#include <gtest/gtest.h>

#include "common/grpc_lifetime.h"

int main(int argc, char** argv) {
  const locator::GrpcLifetime grpc;
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
