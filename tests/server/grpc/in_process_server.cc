#include "tests/server/grpc/in_process_server.h"

#include <gtest/gtest.h>

namespace locator::test {

InProcessServer::InProcessServer(grpc::Service* service) {
  grpc::ServerBuilder builder;
  builder.RegisterService(service);
  server_ = builder.BuildAndStart();
  EXPECT_NE(server_, nullptr) << "the in-process server did not start";
}

std::unique_ptr<v1::Locator::Stub> InProcessServer::NewStub() const {
  return v1::Locator::NewStub(
      server_->InProcessChannel(grpc::ChannelArguments()));
}

void InProcessServer::Shutdown() {
  if (server_ == nullptr) return;
  server_->Shutdown();
  server_->Wait();
  server_.reset();
}

}  // namespace locator::test
