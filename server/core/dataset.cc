#include "server/core/dataset.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <system_error>
#include <type_traits>
#include <utility>

#include "server/core/file_io.h"

namespace locator {
namespace {

constexpr uint64_t kDefaultSeed = 1;

// Concatenates strings and integers, for messages.
template <typename... Parts>
std::string Cat(const Parts&... parts) {
  std::string out;
  const auto append = [&out](const auto& part) {
    if constexpr (std::is_integral_v<std::decay_t<decltype(part)>>) {
      out += std::to_string(part);
    } else {
      out += part;
    }
  };
  (append(parts), ...);
  return out;
}

std::string Quoted(std::string_view s) { return Cat("'", s, "'"); }

// A position in the input, for "file:line: what" messages.
struct Where {
  std::string_view file;
  size_t line;

  std::string Prefix() const { return Cat(file, ":", line); }
  Status Error(std::string_view what) const {
    return Status::InvalidArgument(Cat(Prefix(), ": ", what));
  }
};

Status EmptyDataset(std::string_view file) {
  return Status::InvalidArgument(Cat(file, ": empty dataset (no points)"));
}

// `where` is "file:line" or a generator spec.
Status TooManyPoints(std::string_view where, size_t limit) {
  return Status::ResourceExhausted(
      Cat(where, ": more than ", limit, " points (max_points limit)"));
}

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// The fields of one content line. Fields are separated by whitespace and/or
// one comma; two commas in a row (or a leading/trailing comma) make an empty
// field, which is an error rather than a silent shift of the columns.
struct Fields {
  // Enough for "index x y value" of a .node line; later ones are only counted.
  static constexpr size_t kStored = 4;
  std::array<std::string_view, kStored> field;
  size_t count = 0;
  bool has_empty = false;
};

// Iterates over the lines of a text that carry content: '#' comments (whole
// line or trailing), the CR of CRLF and blanks are dropped, and lines left
// empty are skipped. Line numbers count every line, so errors point at the
// line the user sees in an editor.
class FieldReader {
 public:
  explicit FieldReader(std::string_view text) : text_(text) {}

  // Splits the next content line into *f; false at end of text.
  bool Next(Fields* f) {
    while (pos_ < text_.size()) {
      size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_number_;
      line = line.substr(0, line.find('#'));
      size_t i = 0;
      while (i < line.size() && IsSpace(line[i])) ++i;
      if (i == line.size()) continue;
      f->count = 0;
      f->has_empty = false;
      while (i < line.size()) {
        const size_t start = i;
        while (i < line.size() && !IsSpace(line[i]) && line[i] != ',') ++i;
        if (f->count < Fields::kStored) {
          f->field[f->count] = line.substr(start, i - start);
        }
        ++f->count;
        const bool empty = i == start;
        int commas = 0;
        while (i < line.size() && (IsSpace(line[i]) || line[i] == ',')) {
          commas += line[i++] == ',';
        }
        if (empty || commas > 1 || (commas == 1 && i == line.size())) {
          f->has_empty = true;
        }
      }
      return true;
    }
    return false;
  }

  // 1-based number of the line last returned (after the end: the last line).
  size_t line_number() const { return line_number_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  size_t line_number_ = 0;
};

enum class NumberKind { kFinite, kNonFinite, kNotANumber };

NumberKind ParseDouble(std::string_view s, double* value) {
  // from_chars rejects a leading '+', which other tools do write.
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, *value);
  if (ptr != end || ec == std::errc::invalid_argument) {
    return NumberKind::kNotANumber;
  }
  if (ec == std::errc::result_out_of_range) {
    // from_chars reports overflow and underflow alike and leaves *value
    // untouched; strtod tells them apart (an underflow is a fine ~0). This is
    // the rare path, so the copy does not matter.
    *value = std::strtod(std::string(s).c_str(), nullptr);
  }
  return std::isfinite(*value) ? NumberKind::kFinite : NumberKind::kNonFinite;
}

// Parses a finite double; `noun` names the field in the error message.
Status ParseFinite(std::string_view s, std::string_view noun,
                   const Where& where, double* value) {
  const NumberKind kind = ParseDouble(s, value);
  if (kind == NumberKind::kFinite) return Status::OK();
  return where.Error(kind == NumberKind::kNonFinite
                         ? Cat("non-finite ", noun, " ", Quoted(s))
                         : Cat(Quoted(s), " is not a number"));
}

template <typename Int>
bool ParseInteger(std::string_view s, Int* value) {
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, *value);
  return ec == std::errc() && ptr == end && !s.empty();
}

// Appends the point in fields [first, first + 1] of `f` and, if
// `with_value`, the value in field first + 2.
Status ParsePoint(const Fields& f, size_t first, bool with_value,
                  const Where& where, Dataset* ds) {
  std::array<double, 3> v;
  const size_t n = with_value ? 3 : 2;
  for (size_t i = 0; i < n; ++i) {
    Status s = ParseFinite(f.field[first + i], i < 2 ? "coordinate" : "value",
                           where, &v[i]);
    if (!s.ok()) return s;
  }
  ds->points.push_back({v[0], v[1]});
  if (with_value) ds->values.push_back(v[2]);
  return Status::OK();
}

Status BadSpec(std::string_view spec, std::string_view what) {
  return Status::InvalidArgument(
      Cat("bad dataset spec ", Quoted(spec), ": ", what));
}

// Runs a "uniform:N[:SEED]" or "clusters:N:K[:SEED]" spec; `parts` is the
// spec split on ':' (parts[0] is the generator name).
Status RunGenerator(const std::string& spec,
                    const std::vector<std::string_view>& parts,
                    const DatasetLimits& limits, Dataset* out) {
  const bool clusters = parts[0] == "clusters";
  const size_t required = clusters ? 3 : 2;
  if (parts.size() != required && parts.size() != required + 1) {
    return BadSpec(spec, clusters ? "expected clusters:N:K[:SEED]"
                                  : "expected uniform:N[:SEED]");
  }
  size_t n = 0;
  if (!ParseInteger(parts[1], &n) || n == 0) {
    return BadSpec(spec, "N must be a positive integer");
  }
  size_t k = 1;
  if (clusters && (!ParseInteger(parts[2], &k) || k == 0)) {
    return BadSpec(spec, "K must be a positive integer");
  }
  if (k > n) return BadSpec(spec, "K must not exceed N");
  uint64_t seed = kDefaultSeed;
  if (parts.size() == required + 1 && !ParseInteger(parts.back(), &seed)) {
    return BadSpec(spec, "SEED must be an unsigned 64-bit integer");
  }
  if (n > limits.max_points) return TooManyPoints(spec, limits.max_points);
  *out = clusters ? GenerateClusters(n, k, seed) : GenerateUniform(n, seed);
  return Status::OK();
}

std::vector<std::string_view> SplitOnColon(std::string_view s) {
  std::vector<std::string_view> parts;
  size_t start = 0;
  for (size_t colon; (colon = s.find(':', start)) != s.npos;
       start = colon + 1) {
    parts.push_back(s.substr(start, colon - start));
  }
  parts.push_back(s.substr(start));
  return parts;
}

// How many points to reserve room for: one per line of `text`, but never more
// than `at_most`. Reserving up front avoids the 2x peak of vector doubling on
// multi-gigabyte inputs; bounding by the lines keeps a small file from
// reserving for a count it merely declares.
size_t ReserveEstimate(std::string_view text, size_t at_most) {
  return std::min<size_t>(std::count(text.begin(), text.end(), '\n') + 1,
                          at_most);
}

}  // namespace

bool IsGeneratorSpec(std::string_view spec) {
  return spec.starts_with("uniform:") || spec.starts_with("clusters:");
}

Status LoadDataset(const std::string& spec, Dataset* out,
                   const DatasetLimits& limits) {
  Dataset ds;
  Status status;
  if (IsGeneratorSpec(spec)) {
    status = RunGenerator(spec, SplitOnColon(spec), limits, &ds);
  } else {
    std::string text;
    status = ReadWholeFile(spec, "dataset", &text);
    if (status.ok()) {
      status = spec.ends_with(".node") ? ParseNodeText(text, spec, &ds, limits)
                                       : ParseXyzText(text, spec, &ds, limits);
    }
  }
  if (!status.ok()) return status;
  ds.source = spec;
  *out = std::move(ds);
  return Status::OK();
}

Status ParseXyzText(std::string_view text, std::string_view filename,
                    Dataset* out, const DatasetLimits& limits) {
  const size_t estimate = ReserveEstimate(text, limits.max_points);
  Dataset ds;
  ds.points.reserve(estimate);
  FieldReader reader(text);
  Fields f;
  size_t columns = 0;
  size_t columns_line = 0;
  bool first_line = true;
  while (reader.Next(&f)) {
    const Where where{filename, reader.line_number()};
    if (f.has_empty) return where.Error("empty field");
    double unused;
    if (std::exchange(first_line, false) &&
        ParseDouble(f.field[0], &unused) == NumberKind::kNotANumber) {
      continue;  // a header such as "x,y,z"
    }
    if (f.count != 2 && f.count != 3) {
      return where.Error(Cat("expected 2 or 3 columns, got ", f.count));
    }
    if (columns == 0) {
      columns = f.count;
      columns_line = where.line;
      if (columns == 3) ds.values.reserve(estimate);
    } else if (f.count != columns) {
      return where.Error(Cat("expected ", columns, " columns like line ",
                             columns_line, ", got ", f.count));
    }
    if (ds.points.size() == limits.max_points) {
      return TooManyPoints(where.Prefix(), limits.max_points);
    }
    if (Status s = ParsePoint(f, 0, columns == 3, where, &ds); !s.ok()) {
      return s;
    }
  }
  if (ds.points.empty()) return EmptyDataset(filename);
  *out = std::move(ds);
  return Status::OK();
}

Status ParseNodeText(std::string_view text, std::string_view filename,
                     Dataset* out, const DatasetLimits& limits) {
  FieldReader reader(text);
  Fields f;
  if (!reader.Next(&f)) return EmptyDataset(filename);
  const Where header{filename, reader.line_number()};
  if (f.has_empty || f.count != 4) {
    return header.Error(
        "expected header '<#points> <dim> <#attributes> <#markers>'");
  }
  std::array<size_t, 4> h;
  for (size_t i = 0; i < h.size(); ++i) {
    if (!ParseInteger(f.field[i], &h[i])) {
      return header.Error(
          Cat(Quoted(f.field[i]), " is not a non-negative integer"));
    }
  }
  const auto [num_points, dim, num_attributes, num_markers] = h;
  if (dim != 2) return header.Error(Cat("dimension must be 2, got ", dim));
  if (num_markers > 1) {
    return header.Error(
        Cat("boundary marker count must be 0 or 1, got ", num_markers));
  }
  if (num_points == 0) return EmptyDataset(filename);
  if (num_points > limits.max_points) {
    return TooManyPoints(header.Prefix(), limits.max_points);
  }
  const std::string declared =
      Cat("the ", num_points, " points declared on line ", header.line);
  const bool with_value = num_attributes > 0;
  const size_t estimate = ReserveEstimate(text, num_points);
  Dataset ds;
  ds.points.reserve(estimate);
  if (with_value) ds.values.reserve(estimate);
  while (ds.points.size() < num_points) {
    const bool more = reader.Next(&f);
    const Where where{filename, reader.line_number()};
    if (!more) {
      return where.Error(
          Cat("found only ", ds.points.size(), " of ", declared));
    }
    if (f.has_empty) return where.Error("empty field");
    // Written as a subtraction so that a huge declared attribute count
    // cannot overflow into a match.
    if (f.count < 3 + num_markers ||
        f.count - 3 - num_markers != num_attributes) {
      return where.Error(Cat(
          "expected ", 3 + num_attributes + num_markers, " fields (index x y, ",
          num_attributes, " attribute(s), ", num_markers,
          " marker(s)) as declared on line ", header.line, ", got ", f.count));
    }
    long long index;
    if (!ParseInteger(f.field[0], &index)) {
      return where.Error(Cat(Quoted(f.field[0]), " is not an integer index"));
    }
    // Further attributes and the marker are not used, so not validated.
    if (Status s = ParsePoint(f, 1, with_value, where, &ds); !s.ok()) return s;
  }
  if (reader.Next(&f)) {
    return Where{filename, reader.line_number()}.Error(
        Cat("more than ", declared));
  }
  *out = std::move(ds);
  return Status::OK();
}

}  // namespace locator
