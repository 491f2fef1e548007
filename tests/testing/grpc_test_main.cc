// The main() of every test that makes gRPC objects: GoogleTest's, run inside
// a GrpcLifetime (common/grpc_lifetime.h). gRPC then shuts down on the main
// thread before the process exits, and OpenSSL does no exit-time cleanup
// that could race a gRPC thread still finishing TLS work (ASAN saw that
// race as a double free in a gRPC thread of a test process).

#include <gtest/gtest.h>

#include "common/grpc_lifetime.h"

int main(int argc, char** argv) {
  const locator::GrpcLifetime grpc;
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
