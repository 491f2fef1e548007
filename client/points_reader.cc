#include "client/points_reader.h"

#include <charconv>
#include <cmath>
#include <utility>

namespace locator {
namespace {

constexpr std::string_view kWhitespace = " \t\r\v\f";

std::string_view Trim(std::string_view text) {
  const size_t begin = text.find_first_not_of(kWhitespace);
  if (begin == std::string_view::npos) return {};
  const size_t end = text.find_last_not_of(kWhitespace);
  return text.substr(begin, end - begin + 1);
}

// The first two fields of `line` (fewer if it has fewer); the rest of the
// line is never looked at.
std::vector<std::string_view> LeadingFields(std::string_view line) {
  std::vector<std::string_view> fields;
  const bool comma_separated = line.find(',') != std::string_view::npos;
  while (fields.size() < 2 && !line.empty()) {
    size_t end;
    if (comma_separated) {
      end = line.find(',');
      fields.push_back(Trim(line.substr(0, end)));
    } else {
      end = line.find_first_of(kWhitespace);
      fields.push_back(line.substr(0, end));
    }
    if (end == std::string_view::npos) break;
    line = comma_separated ? line.substr(end + 1) : Trim(line.substr(end));
  }
  return fields;
}

}  // namespace

bool ParseDouble(std::string_view text, double* value) {
  // from_chars does not take the leading '+' that strtod (and people) allow.
  if (text.starts_with('+') && !text.substr(1).starts_with('-')) {
    text.remove_prefix(1);
  }
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, *value);
  return error == std::errc() && stop == end && !text.empty();
}

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
  line = Trim(line.substr(0, line.find('#')));
  if (line.empty()) return Status::OK();
  const bool may_be_header = before_first_row_;
  before_first_row_ = false;

  const std::vector<std::string_view> fields = LeadingFields(line);
  const std::string where = path_ + ":" + std::to_string(line_number_) + ": ";
  double coordinates[2];
  for (size_t i = 0; i < 2; ++i) {
    if (i == fields.size()) {
      return Status::InvalidArgument(where + "expected x and y, found " +
                                     std::to_string(fields.size()) + " field");
    }
    const std::string field(fields[i]);
    if (!ParseDouble(field, &coordinates[i])) {
      if (i == 0 && may_be_header) return Status::OK();
      return Status::InvalidArgument(where + "'" + field + "' is not a number");
    }
    if (!std::isfinite(coordinates[i])) {
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
