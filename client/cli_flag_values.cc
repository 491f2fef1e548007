#include "client/cli_flag_values.h"

#include <cmath>
#include <limits>

#include "client/points_reader.h"
#include "common/str_cat.h"

namespace locator {

Status ParseInterpolation(const std::string& name,
                          v1::Interpolation* interpolation) {
  if (name == "linear") {
    *interpolation = v1::INTERPOLATION_LINEAR;
  } else if (name == "natural-neighbor") {
    *interpolation = v1::INTERPOLATION_NATURAL_NEIGHBOR;
  } else if (name == "nearest") {
    *interpolation = v1::INTERPOLATION_NEAREST;
  } else {
    return Status::InvalidArgument(
        "--interpolation must be linear, natural-neighbor or nearest, not '" +
        name + "'");
  }
  return Status::OK();
}

namespace {

// The words of a flag that takes several numbers: what it takes, and which
// numbers it accepts.
struct NumbersFlag {
  const char* flag;
  const char* takes;
  size_t count;
  bool (*accepts)(double number);
};

bool AnyNumber(double) { return true; }

bool WholeCount(double number) {
  return number >= 1 && number <= std::numeric_limits<uint32_t>::max() &&
         number == std::floor(number);
}

bool PositiveFinite(double number) {
  return number > 0 && std::isfinite(number);
}

constexpr NumbersFlag kTe{"te", "XMIN YMIN XMAX YMAX", 4, AnyNumber};
constexpr NumbersFlag kOutsize{"outsize", "WIDTH HEIGHT, whole numbers from 1",
                               2, WholeCount};
constexpr NumbersFlag kTr{"tr", "XRES YRES, positive numbers", 2,
                          PositiveFinite};

// The numbers of `words`. InvalidArgument "--FLAG takes WHAT: ..." for
// another count of words (the flag given twice, or too few at the end of
// the line), a word that is not a number, or a number the flag does not
// accept.
Status ParseNumbers(const NumbersFlag& flag,
                    const std::vector<std::string>& words,
                    std::vector<double>* numbers) {
  const std::string problem =
      StrCat({"--", flag.flag, " takes ", flag.takes, ": "});
  if (words.size() != flag.count) {
    return Status::InvalidArgument(
        StrCat({problem, std::to_string(flag.count), " values, once, not ",
                std::to_string(words.size())}));
  }
  numbers->clear();
  for (const std::string& word : words) {
    double number = 0;
    if (!ParseDouble(word, &number)) {
      return Status::InvalidArgument(
          StrCat({problem, "'", word, "' is not a number"}));
    }
    if (!flag.accepts(number)) {
      return Status::InvalidArgument(StrCat({problem, "not '", word, "'"}));
    }
    numbers->push_back(number);
  }
  return Status::OK();
}

}  // namespace

Status ParseGridFlags(const GridFlagWords& words, GridSettings* grid) {
  // The numbers first: a flag's value may have swallowed --out.
  std::vector<double> numbers;
  if (!words.te.empty()) {
    if (Status status = ParseNumbers(kTe, words.te, &numbers); !status.ok()) {
      return status;
    }
    grid->box = BoundingBox{numbers[0], numbers[1], numbers[2], numbers[3]};
  }
  const bool outsize = !words.outsize.empty();
  if (outsize == !words.tr.empty()) {
    return Status::InvalidArgument(
        outsize ? "give --outsize or --tr, not both"
                : "grid needs --outsize WIDTH HEIGHT or --tr XRES YRES");
  }
  if (Status status = outsize ? ParseNumbers(kOutsize, words.outsize, &numbers)
                              : ParseNumbers(kTr, words.tr, &numbers);
      !status.ok()) {
    return status;
  }
  if (outsize) {
    grid->width = static_cast<uint32_t>(numbers[0]);
    grid->height = static_cast<uint32_t>(numbers[1]);
  } else if (numbers[0] != numbers[1]) {
    return Status::InvalidArgument(
        "--tr: the Grid RPC renders square cells; give XRES equal to YRES");
  } else {
    grid->cell_size = numbers[0];
  }
  if (words.a_nodata.has_value() && words.nodata.has_value()) {
    return Status::InvalidArgument("give --a_nodata or --nodata, not both");
  }
  const std::optional<std::string>& nodata =
      words.nodata.has_value() ? words.nodata : words.a_nodata;
  if (nodata.has_value()) {
    double value = 0;
    if (!ParseDouble(*nodata, &value)) {
      return Status::InvalidArgument("--a_nodata takes a number, not '" +
                                     *nodata + "'");
    }
    grid->nodata = value;
  }
  if (grid->out.empty()) {
    return Status::InvalidArgument("grid needs --out FILE");
  }
  if (grid->format.driver.empty()) {
    grid->format.driver = gis::DefaultRasterDriver();
  }
  grid->format.creation_options = words.co;
  return gis::CheckRasterFormat(grid->format);
}

}  // namespace locator
