#include "client/points_reader.h"

#include <utility>

#include "common/text_fields.h"

namespace locator {

Status PointsReader::Open(const std::string& path,
                          std::unique_ptr<PointsReader>* reader) {
  std::ifstream file(path);
  if (!file) return Status::NotFound("cannot open points file " + path);
  reader->reset(new PointsReader(path, std::move(file)));
  return Status::OK();
}

PointsReader::PointsReader(std::string path, std::ifstream file)
    : path_(std::move(path)), file_(std::move(file)) {}

Status PointsReader::ReadChunk(size_t max_points, std::vector<double>* xs,
                               std::vector<double>* ys) {
  xs->clear();
  ys->clear();
  std::string line;
  while (xs->size() < max_points && std::getline(file_, line)) {
    ++line_number_;
    Point2 point;
    bool has_point = false;
    Status status = ParseLine(line, &point, &has_point);
    if (!status.ok()) return status;
    if (!has_point) continue;
    xs->push_back(point.x);
    ys->push_back(point.y);
  }
  if (file_.bad()) return Status::IOError("error reading " + path_);
  return Status::OK();
}

Status PointsReader::ParseLine(std::string_view line, Point2* point,
                               bool* has_point) {
  *has_point = false;
  TextFields fields;
  if (!SplitFields(line, &fields)) return Status::OK();
  const bool may_be_header = before_first_row_;
  before_first_row_ = false;

  const std::string where = path_ + ":" + std::to_string(line_number_) + ": ";
  double coordinates[2];
  for (size_t i = 0; i < 2; ++i) {
    if (i == fields.count) {
      return Status::InvalidArgument(where + "expected x and y, found " +
                                     std::to_string(fields.count) + " field");
    }
    // An empty x or y reads as the empty field it is, not as the next one.
    const std::string field(i < fields.first_empty ? fields.field[i] : "");
    switch (ParseNumber(field, &coordinates[i])) {
      case NumberKind::kFinite:
        break;
      case NumberKind::kNotANumber:
        if (i == 0 && may_be_header) return Status::OK();
        return Status::InvalidArgument(where + "'" + field +
                                       "' is not a number");
      case NumberKind::kNonFinite:
        return Status::InvalidArgument(where + "'" + field +
                                       "' is not a finite number");
    }
  }
  *point = Point2{coordinates[0], coordinates[1]};
  *has_point = true;
  return Status::OK();
}

Status ReadAllPoints(const std::string& path, std::vector<Point2>* points) {
  std::unique_ptr<PointsReader> reader;
  Status status = PointsReader::Open(path, &reader);
  if (!status.ok()) return status;
  constexpr size_t kChunk = 1 << 16;
  std::vector<double> xs, ys;
  points->clear();
  do {
    status = reader->ReadChunk(kChunk, &xs, &ys);
    if (!status.ok()) return status;
    for (size_t i = 0; i < xs.size(); ++i) points->push_back({xs[i], ys[i]});
  } while (!xs.empty());
  if (points->empty()) {
    return Status::InvalidArgument(path + ": no points in the file");
  }
  return Status::OK();
}

}  // namespace locator
