// DatasetOracle: what the hostile-input test knows of one dataset the server
// serves, to check the answers it gets OK: CGAL's own triangulation of the
// same points (Reference), the dataset's values, and the id bounds the
// server reports.
//
// A Locate answer (or batch row) for a point the test knows in the
// dataset's coordinates must agree with CGAL: the same location type, the
// same triangle for a face, corners that contain the point, a value as the
// interpolation says (linear: CGAL's; natural neighbour: exact on the plane
// dataset, within the values' range otherwise; nearest: one corner's
// value). Where the point went through a CRS transform the test does not
// repeat, the answer must be well formed: a known type, ids in range,
// barycentric weights summing to 1, a value within the values' range.
// Profiles and grids are checked for shape (counts, order, finite numbers)
// and values the same way, and grid cells against CGAL's hull.
//
// Immutable after SetServedTriangles(); thread-safe for reading.

#ifndef LOCATOR_TESTS_SERVER_HOSTILE_ORACLE_H_
#define LOCATOR_TESTS_SERVER_HOSTILE_ORACLE_H_

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>

#include "locator/v1/locator.pb.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {

// Which parts of a location an answer carries.
struct AnswerParts {
  bool hull_edge = true;  // the nearest hull edge (Locate; not batch rows)
  bool vertex_ids = true;
  bool barycentric = true;
  bool value = true;
};

class DatasetOracle {
 public:
  // The dataset requests name `name`, triangulated by CGAL in `reference`;
  // `plane`: its values are TestValue(p), so interpolants are exact.
  DatasetOracle(std::string name, std::unique_ptr<Reference> reference,
                bool plane);

  const std::string& name() const { return name_; }
  const Reference& reference() const { return *reference_; }
  // A point well inside the hull, for benign requests.
  Point2 Inside(double u, double v) const;
  // The bounding box of the dataset's points.
  const BoundingBox& box() const { return box_; }

  // The triangle count GetStats reports (ids are below it).
  void SetServedTriangles(uint64_t triangles) { triangles_ = triangles; }

  // "" or what is wrong with `got`, the answer for the query `q` (nullopt
  // when the test does not know it in the dataset's coordinates) with
  // interpolation `how`, which carries `parts`.
  std::string CheckLocation(const std::optional<Point2>& q,
                            v1::Interpolation how, const LocateResult& got,
                            const AnswerParts& parts) const;
  // "" or what is wrong with a Profile answer to `request`.
  std::string CheckProfile(const v1::ProfileRequest& request,
                           const v1::ProfileResponse& response) const;
  // "" or what is wrong with a whole Grid answer (header and every row) to
  // `request`.
  std::string CheckGrid(const v1::GridRequest& request,
                        const v1::GridResponse& response) const;

 private:
  // "" or what is wrong with `value`, interpolated with `how` at `p` (known
  // in the dataset's coordinates or not).
  std::string CheckValue(const std::optional<Point2>& p, v1::Interpolation how,
                         double value) const;
  std::string CheckStructure(const LocateResult& got,
                             const AnswerParts& parts) const;

  std::string name_;
  std::unique_ptr<Reference> reference_;
  bool plane_;
  BoundingBox box_;
  double min_value_ = 0, max_value_ = 0;
  std::unordered_set<double> values_;
  uint64_t triangles_ = 0;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HOSTILE_ORACLE_H_
