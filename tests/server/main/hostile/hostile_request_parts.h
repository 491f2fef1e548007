// Pieces the hostile request draws share (hostile_requests.h): the dataset
// and CRS a request names, benign and hostile points, the interpolation,
// and what each of them allows the call to answer.
//
// Thread-safety: free functions over their arguments.

#ifndef LOCATOR_TESTS_SERVER_HOSTILE_REQUEST_PARTS_H_
#define LOCATOR_TESTS_SERVER_HOSTILE_REQUEST_PARTS_H_

#include <string>
#include <vector>

#include "locator/geometry.h"
#include "locator/v1/locator.pb.h"
#include "tests/server/main/hostile/hostile_expect.h"
#include "tests/server/main/hostile/hostile_oracle.h"
#include "tests/server/main/hostile/hostile_server.h"
#include "tests/server/main/hostile/hostile_values.h"

namespace locator::test {

// The words a refusal of a query point may name it by.
inline const std::vector<std::string> kPointNames = {"point"};
// ... of a request CRS, or of a point that it cannot transform.
inline const std::vector<std::string> kCrsNames = {"crs", "point", "transform"};

// A request's dataset and CRS, as drawn.
struct Target {
  std::string dataset;                    // as sent
  const DatasetOracle* oracle = nullptr;  // null: a dataset nobody serves
  const RequestCrs* crs = nullptr;        // null: none
  BoundingBox frame;  // where benign points are drawn, in the request CRS
  // The request's points are in the dataset's coordinates (no CRS, or the
  // dataset's own), so that CGAL can check the answers.
  bool points_known = false;
  std::string summary;
};

// Draws the dataset and (with `with_crs`) the CRS of a request, and adds
// what they allow to *expect: a dataset nobody serves makes it NOT_FOUND
// and nothing else (admission comes first); over HTTP, where the name is
// in the path, a path too long for the server may also get 414 or 431.
Target DrawTarget(CaseDraw& draw, const HostileServer& server, bool with_crs,
                  Transport transport, Expectation* expect);

// A benign point: in or around the frame, now and then a dataset vertex or
// the midpoint of two.
Point2 BenignPoint(CaseDraw& draw, const Target& target);
// Replaces p's x and y by hostile coordinates where the draw says so;
// returns their description ("" for none).
std::string DrawHostilePoint(CaseDraw& draw, Point2* p);
// Adds what the point `p` allows: a non-finite coordinate must be refused
// (naming one of `names`); through a CRS, a finite one may be refused.
void ExpectPoint(const Point2& p, const Target& target,
                 const std::vector<std::string>& names, Expectation* expect);
// A benign interpolation, or (kFieldInterpolation) an unknown one, which
// must be refused.
v1::Interpolation DrawInterpolation(CaseDraw& draw, const Target& target,
                                    Expectation* expect, std::string* summary);
inline constexpr size_t kHostileInterpolations = 3;

// "x=NaN y=1" for a summary.
std::string PointText(const Point2& p);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HOSTILE_REQUEST_PARTS_H_
