// The values of the `locator` CLI's flags that need more than the flag
// parser (common/flags): `grid`'s GDAL-style --te, --outsize, --tr,
// --a_nodata (--nodata), --of and --co, which go together.
//
// Thread-safety: stateless functions.

#ifndef LOCATOR_CLIENT_CLI_FLAG_VALUES_H_
#define LOCATOR_CLIENT_CLI_FLAG_VALUES_H_

#include <optional>
#include <string>
#include <vector>

#include "client/cli_commands.h"
#include "locator/status.h"
#include "locator/v1/locator.pb.h"

namespace locator {

// `grid`'s flags as the command line gave them (empty or absent: not given),
// each with its number of words (the flag parser sees to that).
struct GridFlagWords {
  std::vector<std::string> te;       // XMIN YMIN XMAX YMAX
  std::vector<std::string> outsize;  // WIDTH HEIGHT
  std::vector<std::string> tr;       // XRES YRES
  std::optional<std::string> a_nodata;
  std::optional<std::string> nodata;  // the same as a_nodata
  std::vector<std::string> co;        // NAME=VALUE each
};

// Converts `words` into `grid`, whose `out` and `format.driver` the flag
// parser has set (an empty driver becomes gis::DefaultRasterDriver()).
// InvalidArgument naming the flag, as FlagError words it: a word that is
// not a number, --outsize not whole numbers from 1, --tr not positive and
// finite or not square; and --outsize and --tr both or neither, --a_nodata
// and --nodata both, no --out, and a format gis::CheckRasterFormat rejects.
Status ParseGridFlags(const GridFlagWords& words, GridSettings* grid);

}  // namespace locator

#endif  // LOCATOR_CLIENT_CLI_FLAG_VALUES_H_
