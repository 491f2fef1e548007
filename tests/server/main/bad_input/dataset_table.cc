#include "tests/server/main/bad_input/dataset_table.h"

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>

#include <chrono>
#include <fstream>
#include <memory>

namespace locator::test {
namespace {

constexpr auto kExitTimeout = std::chrono::seconds(60);

void ReplaceAll(std::string* text, const std::string& from,
                const std::string& to) {
  for (size_t at = text->find(from); at != std::string::npos;
       at = text->find(from, at + to.size())) {
    text->replace(at, from.size(), to);
  }
}

}  // namespace

void PrintTo(const DatasetRow& row, std::ostream* out) { *out << row.input; }

std::string RowName(const ::testing::TestParamInfo<DatasetRow>& info) {
  return info.param.name;
}

std::string Lines(int count, const std::function<std::string(int)>& line) {
  std::string text;
  for (int i = 0; i < count; ++i) text += line(i) + "\n";
  return text;
}

std::string DatasetTableTest::Expand(std::string text) const {
  ReplaceAll(&text, "{file}", file_);
  ReplaceAll(&text, "{dir}", dir_.path());
  return text;
}

void DatasetTableTest::RunRow(const DatasetRow& row) {
  file_ =
      row.file_name.empty() ? row.contents : dir_.path() + "/" + row.file_name;
  if (row.make_file) {
    row.make_file(file_);
  } else if (!row.file_name.empty()) {
    std::ofstream(file_, std::ios::binary) << row.contents;
  }
  for (const DatasetFile& file : row.more_files) {
    std::ofstream(dir_.path() + "/" + file.name, std::ios::binary)
        << file.contents;
  }
  const std::string dataset = row.spec.empty() ? file_ : Expand(row.spec);
  std::vector<std::string> args = {"--dataset", dataset, "--listen",
                                   "127.0.0.1:0"};
  for (const std::string& flag : row.flags) args.push_back(Expand(flag));
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(ServerProcess::Spawn(LOCATORD_PATH, args, &server).ok());
  // It listens first, whatever the dataset, then loads it.
  ASSERT_TRUE(server->WaitForListening().ok()) << row.input;
  if (row.exit_code != 0) {
    EXPECT_EQ(server->WaitForExit(kExitTimeout), row.exit_code) << row.input;
    EXPECT_THAT(server->StderrText(), ::testing::HasSubstr(Expand(row.message)))
        << row.input;
    return;
  }
  const Status serving = server->WaitUntilServing();
  ASSERT_TRUE(serving.ok()) << row.input << ": " << serving.ToString();
  auto stub = NewStub(*server);
  v1::LocateResponse response;
  const grpc::Status status = LocateOne(*stub, {0.5, 0.25}, &response);
  EXPECT_TRUE(status.ok()) << status.error_message();
  row.check(*server, dataset);
}

}  // namespace locator::test
