#include "client/cli_flag_values.h"

#include <cmath>
#include <limits>

#include "client/points_reader.h"

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

// The `count` numbers of a flag that takes several words. InvalidArgument
// "--FLAG takes WHAT: ..." for a word that is not a number, or another
// count of words (the flag given twice, or too few at the end of the line).
Status ParseNumbers(const std::string& flag, const std::string& takes,
                    size_t count, const std::vector<std::string>& words,
                    std::vector<double>* numbers) {
  const std::string problem = "--" + flag + " takes " + takes + ": ";
  if (words.size() != count) {
    return Status::InvalidArgument(problem + std::to_string(count) +
                                   " values, once, not " +
                                   std::to_string(words.size()));
  }
  numbers->clear();
  for (const std::string& word : words) {
    double number = 0;
    if (!ParseDouble(word, &number)) {
      return Status::InvalidArgument(problem + "'" + word +
                                     "' is not a number");
    }
    numbers->push_back(number);
  }
  return Status::OK();
}

// --outsize WIDTH HEIGHT: whole numbers from 1 to 2^32 - 1.
Status ParseOutsize(const std::vector<std::string>& words, GridSettings* grid) {
  constexpr char kTakes[] = "WIDTH HEIGHT, whole numbers from 1";
  std::vector<double> size;
  if (Status status = ParseNumbers("outsize", kTakes, 2, words, &size);
      !status.ok()) {
    return status;
  }
  for (size_t i = 0; i < size.size(); ++i) {
    if (!(size[i] >= 1 && size[i] <= std::numeric_limits<uint32_t>::max() &&
          size[i] == std::floor(size[i]))) {
      return Status::InvalidArgument(std::string("--outsize takes ") + kTakes +
                                     ": not '" + words[i] + "'");
    }
  }
  grid->width = static_cast<uint32_t>(size[0]);
  grid->height = static_cast<uint32_t>(size[1]);
  return Status::OK();
}

// --tr XRES YRES: one positive cell size, as the Grid RPC renders square
// cells.
Status ParseResolution(const std::vector<std::string>& words,
                       GridSettings* grid) {
  constexpr char kTakes[] = "XRES YRES, positive numbers";
  std::vector<double> resolution;
  if (Status status = ParseNumbers("tr", kTakes, 2, words, &resolution);
      !status.ok()) {
    return status;
  }
  for (size_t i = 0; i < resolution.size(); ++i) {
    if (!(resolution[i] > 0) || !std::isfinite(resolution[i])) {
      return Status::InvalidArgument(std::string("--tr takes ") + kTakes +
                                     ": not '" + words[i] + "'");
    }
  }
  if (resolution[0] != resolution[1]) {
    return Status::InvalidArgument(
        "--tr: the Grid RPC renders square cells; give XRES equal to YRES");
  }
  grid->cell_size = resolution[0];
  return Status::OK();
}

}  // namespace

Status ParseGridFlags(const GridFlagWords& words, GridSettings* grid) {
  // The numbers first: a flag's value may have swallowed --out.
  if (!words.te.empty()) {
    std::vector<double> box;
    if (Status status =
            ParseNumbers("te", "XMIN YMIN XMAX YMAX", 4, words.te, &box);
        !status.ok()) {
      return status;
    }
    grid->box = BoundingBox{box[0], box[1], box[2], box[3]};
  }
  const bool outsize = !words.outsize.empty();
  if (outsize == !words.tr.empty()) {
    return Status::InvalidArgument(
        outsize ? "give --outsize or --tr, not both"
                : "grid needs --outsize WIDTH HEIGHT or --tr XRES YRES");
  }
  Status status = outsize ? ParseOutsize(words.outsize, grid)
                          : ParseResolution(words.tr, grid);
  if (!status.ok()) return status;
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
