// PointsReader: reads query points (x, y) from a text file in chunks, so a
// file of any size goes through in bounded memory.
//
// Format: the dataset text format of locator/dataset_sources.h, read as
// queries, line by line as the core reads a dataset (common/text_fields.h:
// fields separated by whitespace and/or one comma, '#' comments, blank
// lines skipped). The first two fields are x and y and must not be empty;
// further fields are ignored (empty ones too), so a dataset file or the CSV
// that `locator batch` writes replays as it is. The first non-comment line
// is a header, and is skipped, when its first field is not a number. Every
// error is InvalidArgument "file:line: what" (not a number, not finite, one
// field).
//
// Owns the open file. Thread-safety: not thread-safe; one reader per thread.

#ifndef LOCATOR_CLIENT_POINTS_READER_H_
#define LOCATOR_CLIENT_POINTS_READER_H_

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"

namespace locator {

class PointsReader {
 public:
  // Opens `path`; NotFound when it cannot be opened.
  static Status Open(const std::string& path,
                     std::unique_ptr<PointsReader>* reader);

  // Replaces xs and ys with the next (up to) max_points points of the file;
  // both come back empty at the end of the file.
  Status ReadChunk(size_t max_points, std::vector<double>* xs,
                   std::vector<double>* ys);

 private:
  PointsReader(std::string path, std::ifstream file);

  // Parses the current line; sets *has_point false for a line with none.
  Status ParseLine(std::string_view line, Point2* point, bool* has_point);

  const std::string path_;
  std::ifstream file_;
  uint64_t line_number_ = 0;
  // Until the first non-comment line, which may be a header.
  bool before_first_row_ = true;
};

// Reads every point of `path` (for replaying a recorded query file).
// InvalidArgument when the file has no points.
Status ReadAllPoints(const std::string& path, std::vector<Point2>* points);

}  // namespace locator

#endif  // LOCATOR_CLIENT_POINTS_READER_H_
