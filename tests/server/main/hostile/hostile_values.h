// The hostile values of the hostile-input property test (issue 26), and the
// seeded generator that draws requests from them.
//
// Values: the coordinates every coordinate field gets (signed zeros,
// denormals, tiny and huge magnitudes, the largest finite doubles, NaN and
// the infinities), the request CRS strings (valid ones and ones that name
// files, devices or FIFOs, operations instead of CRSs, unknown codes,
// garbage and 1 MiB strings), dataset names and Reload specs.
//
// Drawing: every request field has a list of hostile values. Coverage()
// lists every (field, value) pair of a request kind, shuffled by the seed,
// once per repeat; each pair is the focus of one case, whose other fields a
// CaseDraw fills with benign values or, now and then, other hostile ones. So
// every value appears in every field on its own at least once, and in
// random company besides. A case is reproducible from the seed and its
// index alone. The costliest values (megabytes to send) come last in their
// lists and are drawn only as a focus.
//
// Thread-safety: the lists are immutable; a CaseDraw belongs to one thread.

#ifndef LOCATOR_TESTS_SERVER_HOSTILE_VALUES_H_
#define LOCATOR_TESTS_SERVER_HOSTILE_VALUES_H_

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace locator::test {

// ±0, ±4.9e-324, ±2.2e-308, ±1e-300, ±1e150, ±1e160, ±1e300, ±DBL_MAX,
// NaN, ±inf.
const std::vector<double>& HostileCoordinates();

// A readable name of `v` (-0, 4.9e-324, NaN, ...), for failure messages.
std::string DoubleName(double v);

// What a request CRS is, hence what a request with it may get.
enum class CrsKind {
  kDatasetOwn,  // the utm dataset's own CRS: answers agree with CGAL
  kLonLat,      // a valid geographic CRS: answered, or a point refused
  kMaybe,       // may be accepted as lon/lat or refused, naming the crs
  kRefused,     // must be refused (INVALID_ARGUMENT or PERMISSION_DENIED):
                // PROJ cannot make it without reading a file, or it is no
                // CRS
  kHuge,        // 1 MiB: refused, with a short message
};

struct RequestCrs {
  std::string label;  // for failure messages
  std::string text;
  CrsKind kind;
};

// Every request CRS the test sends; the first is "EPSG:32633", the third
// "EPSG:4326", the last kCostlyRequestCrs are 1 MiB long. `fifo` is a FIFO
// (nobody writes it) and `secret` a file outside every data directory, both
// made by the test.
inline constexpr size_t kCostlyRequestCrs = 2;
std::vector<RequestCrs> RequestCrsList(const std::string& fifo,
                                       const std::string& secret,
                                       const std::string& utm_wkt2,
                                       const std::string& lon_lat_wkt2);

// Dataset names no server has: unknown, path-like, with control
// characters, non-ASCII and (the last kCostlyDatasetNames) 1 MiB long.
inline constexpr size_t kCostlyDatasetNames = 1;
std::vector<std::string> HostileDatasetNames();

// The index of a (field, value) pair: the focus of one case.
struct Focus {
  int field = 0;
  size_t value = 0;
};

// Every (field, value) pair for `values_per_field` (field f has
// values_per_field[f] values), `repeats` times, shuffled by `seed`.
std::vector<Focus> Coverage(std::span<const size_t> values_per_field,
                            int repeats, uint64_t seed);

// Draws one case around its focus.
class CaseDraw {
 public:
  // Probability that a field other than the focus gets a hostile value.
  static constexpr double kCompanyRate = 0.1;

  // The draw of case `case_index` of the run seeded `seed`; fields other
  // than the focus are hostile with probability `company_rate`.
  CaseDraw(uint64_t seed, size_t case_index, Focus focus,
           double company_rate = kCompanyRate);

  // The hostile value index for `field` (of `count` values), or nullopt
  // for a benign one: the focus's value for the focus field, a random one
  // with probability company_rate for the others. (So a field whose costly
  // values come last can keep them for its own focus by passing a smaller
  // count.)
  std::optional<size_t> Hostile(int field, size_t count);

  bool Chance(double p);
  // Uniform in [0, n).
  size_t Below(size_t n);
  double Uniform(double lo, double hi);
  // One of HostileCoordinates().
  double HostileCoordinate();

  const Focus& focus() const { return focus_; }

 private:
  Focus focus_;
  double company_rate_;
  std::mt19937_64 rng_;
};

// The test's seed: LOCATOR_HOSTILE_SEED if set, else a fixed one.
uint64_t HostileSeed();
// How many times Coverage() lists each pair: LOCATOR_HOSTILE_REPEATS if set,
// else once (CI runs the test in three builds; a longer run with other
// seeds is LOCATOR_HOSTILE_SEED and LOCATOR_HOSTILE_REPEATS away).
int HostileRepeats();

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HOSTILE_VALUES_H_
