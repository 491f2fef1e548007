#include "client/cli_flag_values.h"

#include <cmath>
#include <limits>

#include "client/points_reader.h"
#include "common/flags/flag_value.h"
#include "common/str_cat.h"
#include "common/text_fields.h"

namespace locator {

namespace {

// A flag that takes several numbers: which numbers it accepts, said as the
// accepted form of each.
struct NumbersFlag {
  const char* flag;
  const char* form;
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

constexpr NumbersFlag kTe{"te", "a number (XMIN YMIN XMAX YMAX)", 4, AnyNumber};
constexpr NumbersFlag kOutsize{
    "outsize", "a whole number from 1 to 4294967295 (WIDTH HEIGHT)", 2,
    WholeCount};
constexpr NumbersFlag kTr{"tr", "a positive number (XRES YRES)", 2,
                          PositiveFinite};

// The numbers of `words`. InvalidArgument "--FLAG 'WORD': must be FORM" for
// the first word that is not a number the flag accepts, or for another
// count of words.
Status ParseNumbers(const NumbersFlag& flag,
                    const std::vector<std::string>& words,
                    std::vector<double>* numbers) {
  const std::string form = StrCat({"must be ", flag.form});
  if (words.size() != flag.count) {
    return FlagError(flag.flag,
                     StrCat({std::to_string(words.size()), " words"}), form);
  }
  numbers->clear();
  for (const std::string& word : words) {
    double number = 0;
    if (!ParseDouble(word, &number) || !flag.accepts(number)) {
      return FlagError(flag.flag, word, form);
    }
    numbers->push_back(number);
  }
  return Status::OK();
}

}  // namespace

Status ParseGridFlags(const GridFlagWords& words, GridSettings* grid) {
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
    return FlagError("tr", StrCat({words.tr[0], " ", words.tr[1]}),
                     "the Grid RPC renders square cells: XRES must equal YRES");
  } else {
    grid->cell_size = numbers[0];
  }
  if (words.a_nodata.has_value() && words.nodata.has_value()) {
    return Status::InvalidArgument("give --a_nodata or --nodata, not both");
  }
  const bool by_nodata = words.nodata.has_value();
  const std::optional<std::string>& nodata =
      by_nodata ? words.nodata : words.a_nodata;
  if (nodata.has_value()) {
    double value = 0;
    if (!ParseDouble(*nodata, &value)) {
      return FlagError(by_nodata ? "nodata" : "a_nodata", *nodata,
                       "must be a number or nan");
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
