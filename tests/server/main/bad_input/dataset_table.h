// The bad-dataset table's harness: a row is a dataset an operator can hand
// locatord (its files or a generator spec, and flags) and the outcome. A
// refused dataset makes locatord exit 1 with a message naming the file (and
// the line, where one line is at fault) and the problem; a served one must
// answer a normal Locate and pass the row's check. The rows are in
// bad_dataset_table_test.cc (point files, limits, GIS sources) and
// bad_domain_table_test.cc (breaklines, domains and meshes).
//
// Thread-safety: one test owns a DatasetTableTest.

#ifndef LOCATOR_TESTS_SERVER_DATASET_TABLE_H_
#define LOCATOR_TESTS_SERVER_DATASET_TABLE_H_

#include <gtest/gtest.h>

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {

// A file written for a row, into a directory of its own.
struct DatasetFile {
  std::string name;
  std::string contents;
};

struct DatasetRow {
  std::string name;
  // What the dataset is, for the failure message.
  std::string input;
  // The file's name and contents; with an empty name, `contents` is passed
  // to --dataset as it is (a generator spec or a path that does not exist).
  std::string file_name;
  std::string contents;
  // Flags, with "{file}" and "{dir}" expanded.
  std::vector<std::string> flags = {};
  // 1: locatord refuses the dataset; 0: it serves it.
  int exit_code = 0;
  // Refused: a substring of stderr; "{file}" stands for the file's path and
  // "{dir}" for the directory of the row's files.
  std::string message = "";
  // Served: what else must hold (GetStats, answers against CGAL); `dataset`
  // is the --dataset argument.
  std::function<void(const ServerProcess&, const std::string& dataset)> check =
      nullptr;
  // Files written beside the row's file (a .node for a .ele, a .wkt).
  std::vector<DatasetFile> more_files = {};
  // The --dataset argument when it is not the file's path, with "{file}"
  // and "{dir}" expanded, e.g. "{file}+{dir}/lake.wkt".
  std::string spec = "";
  // Makes the row's file at the path it is given instead of writing
  // `contents` (a binary file made with a tool at test time).
  std::function<void(const std::string& path)> make_file = nullptr;
};

void PrintTo(const DatasetRow& row, std::ostream* out);

// "NAME" of a row, for INSTANTIATE_TEST_SUITE_P.
std::string RowName(const ::testing::TestParamInfo<DatasetRow>& info);

// Lines 0..count-1 of a text, each made by `line`.
std::string Lines(int count, const std::function<std::string(int)>& line);

class DatasetTableTest : public ::testing::TestWithParam<DatasetRow> {
 protected:
  // Writes the row's files, starts locatord on them and checks the outcome.
  void RunRow(const DatasetRow& row);

 private:
  // Replaces "{file}" and "{dir}" in `text`.
  std::string Expand(std::string text) const;

  ScratchDir dir_;
  std::string file_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_DATASET_TABLE_H_
