#include "server/core/surface/profile_trace.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/input_text.h"
#include "common/str_cat.h"
#include "server/core/geometry/wide_math.h"
#include "server/core/mesh/mesh_walk.h"
#include "server/core/surface/profile_walk.h"
#include "server/core/surface/surface_value.h"

namespace locator {

namespace {

// A point of the trace, reported or not.
struct Stop {
  ProfilePoint point;
  // For a line vertex, an in-domain face whose closed triangle holds it.
  uint32_t own_face = ServingMesh::kNoFace;
};

// Traces the line into stops and the stretches between them
// (stretches_[i] runs from stops_[i] to stops_[i + 1]), then derives the
// profile from them.
class ProfileBuilder {
 public:
  ProfileBuilder(const ServingMesh& mesh, std::span<const Point2> line,
                 const ProfileOptions& options)
      : mesh_(mesh), line_(line), options_(options) {}

  // The length of every segment and where it starts along the line.
  // InvalidArgument when the line is longer than the largest double: its
  // distances could not be represented.
  Status Measure() {
    double offset = 0;
    Wide total = 0;
    for (size_t s = 0; s + 1 < line_.size(); ++s) {
      const Wide length = Distance(line_[s], line_[s + 1]);
      total += length;
      segment_start_.push_back(offset);
      segment_length_.push_back(Narrow(length));
      offset += segment_length_.back();
      if (total > kMaxDouble || !std::isfinite(offset)) {
        return Status::InvalidArgument(StrCat(
            {"profile: the line up to line point ", std::to_string(s + 1),
             " is longer than the largest double, ",
             NumberText(std::numeric_limits<double>::max()),
             ": distances along it cannot be represented; the line's length "
             "must stay within that"}));
      }
    }
    return Status::OK();
  }

  Status Trace(uint32_t start) {
    uint32_t hint = start;
    for (size_t s = 0; s + 1 < line_.size(); ++s) {
      const Point2& p = line_[s];
      const Point2& q = line_[s + 1];
      const double offset = segment_start_[s];
      const double length = segment_length_[s];
      MeshWalkOutcome at;
      Status status = WalkTo(hint, p, s, offset, &at);
      if (!status.ok()) return status;
      if (p.x == q.x && p.y == q.y) {
        stretches_.push_back(RegionAt(at));
        hint = at.face;
        continue;
      }
      SegmentTrace trace;
      status =
          WalkSegment(mesh_, at, p, q, options_.max_faces, &faces_, &trace);
      if (!status.ok()) return status;
      for (const SegmentStop& stop : trace.stops) {
        stretches_.push_back(stop.before);
        AddStop(stop.kind, stop.point, offset + stop.t * length, s,
                ServingMesh::kNoFace);
      }
      stretches_.push_back(trace.last);
      hint = trace.end_face;
    }
    MeshWalkOutcome at;
    return WalkTo(hint, line_.back(), line_.size() - 2,
                  segment_start_.back() + segment_length_.back(), &at);
  }

  void Finish(Profile* out) {
    out->length = stops_.back().point.distance;
    for (size_t j = 0; j < stops_.size(); ++j) {
      constexpr uint32_t none = ServingMesh::kNoFace;
      const uint32_t before = j > 0 ? stretches_[j - 1].face : none;
      const uint32_t after = j < stretches_.size() ? stretches_[j].face : none;
      ProfilePoint& point = stops_[j].point;
      // Crossings inside a gap are walked through silently.
      if (before == none && after == none &&
          point.kind != ProfilePointKind::kLineVertex) {
        continue;
      }
      const uint32_t face = before != none  ? before
                            : after != none ? after
                                            : stops_[j].own_face;
      if (face != none) {
        if (mesh_.has_values()) {
          point.has_value = true;
          point.value =
              ValueAt(mesh_, face, point.point, options_.interpolation);
        }
        // The last point has no stretch after it: the face it ends in.
        point.triangle_id = j < stretches_.size()
                                ? (after == none ? -1 : int64_t{after})
                                : int64_t{face};
      }
      out->breakpoints.push_back(point);
      if (point.kind != ProfilePointKind::kLineVertex) ++out->crossings;
    }
    AddGaps(out);
    AddSamples(out);
  }

 private:
  // Walks to the line vertex `v` of segment `s` and records it.
  Status WalkTo(uint32_t hint, const Point2& v, size_t s, double distance,
                MeshWalkOutcome* at) {
    *at = Walk(mesh_, hint, v);
    if (stops_.empty()) first_face_ = at->face;
    faces_ += at->faces_visited;
    if (faces_ > options_.max_faces) return TooManyFaces(options_.max_faces);
    AddStop(ProfilePointKind::kLineVertex, v, distance, s,
            ClosedDomainFace(mesh_, *at));
    return Status::OK();
  }

  void AddStop(ProfilePointKind kind, const Point2& point, double distance,
               size_t segment, uint32_t own_face) {
    Stop stop;
    stop.point.kind = kind;
    stop.point.point = point;
    stop.point.distance =
        stops_.empty() ? distance
                       : std::max(distance, stops_.back().point.distance);
    stop.point.segment = static_cast<uint32_t>(segment);
    stop.own_face = own_face;
    stops_.push_back(stop);
  }

  // The zero-length stretch of a repeated line vertex.
  ProfileRegion RegionAt(const MeshWalkOutcome& at) const {
    const uint32_t face = ClosedDomainFace(mesh_, at);
    if (face != ServingMesh::kNoFace) return {face, LocationType::kFace};
    return {face, at.type == LocationType::kOutsideConvexHull
                      ? LocationType::kOutsideConvexHull
                      : LocationType::kOutsideDomain};
  }

  void AddGaps(Profile* out) const {
    for (size_t j = 0; j < stretches_.size(); ++j) {
      const ProfileRegion& r = stretches_[j];
      if (r.face != ServingMesh::kNoFace) continue;
      const double from = stops_[j].point.distance;
      const double to = stops_[j + 1].point.distance;
      if (!out->gaps.empty() && out->gaps.back().reason == r.type &&
          out->gaps.back().to_distance >= from) {
        out->gaps.back().to_distance = to;
      } else {
        out->gaps.push_back({from, to, r.type});
      }
    }
  }

  // The point at `distance` along the line, and the segment it belongs to.
  Point2 PointAt(double distance, uint32_t* segment) const {
    const size_t s = std::upper_bound(segment_start_.begin(),
                                      segment_start_.end(), distance) -
                     segment_start_.begin() - 1;
    *segment = static_cast<uint32_t>(s);
    const double f =
        segment_length_[s] > 0
            ? std::clamp((distance - segment_start_[s]) / segment_length_[s],
                         0.0, 1.0)
            : 0.0;
    return Lerp(line_[s], line_[s + 1], f);
  }

  // Each sample is located on its own, by a walk from the previous one's
  // face: where the distances cannot tell the line's stops apart (a 1e160
  // long line over unit triangles puts them all at one distance), the
  // stretches could not say which one a sample is in.
  void AddSamples(Profile* out) const {
    const uint32_t n = options_.samples;
    uint32_t hint = first_face_;
    for (uint32_t i = 0; i < n; ++i) {
      ProfilePoint sample;
      sample.kind = ProfilePointKind::kSample;
      // In Wide, where length * i cannot overflow.
      sample.distance =
          i == 0       ? 0
          : i == n - 1 ? out->length
                       : static_cast<double>(Wide{out->length} * i / (n - 1));
      sample.point = PointAt(sample.distance, &sample.segment);
      if (n > 1 && i == n - 1) sample.point = line_.back();
      const MeshWalkOutcome at = Walk(mesh_, hint, sample.point);
      hint = at.face;
      // On the domain's boundary, the defined side.
      const uint32_t face = ClosedDomainFace(mesh_, at);
      if (face != ServingMesh::kNoFace) {
        sample.triangle_id = face;
        if (mesh_.has_values()) {
          sample.has_value = true;
          sample.value =
              ValueAt(mesh_, face, sample.point, options_.interpolation);
        }
      }
      out->samples.push_back(sample);
    }
  }

  const ServingMesh& mesh_;
  const std::span<const Point2> line_;
  const ProfileOptions& options_;
  uint64_t faces_ = 0;
  // Where the walk to the line's first vertex ended.
  uint32_t first_face_ = 0;
  std::vector<Stop> stops_;
  std::vector<ProfileRegion> stretches_;
  // Per segment: the distance where it starts, and its length.
  std::vector<double> segment_start_;
  std::vector<double> segment_length_;
};

}  // namespace

Status TraceProfile(const ServingMesh& mesh, uint32_t start,
                    std::span<const Point2> line, const ProfileOptions& options,
                    Profile* out) {
  *out = Profile();
  if (line.size() < 2) {
    return Status::InvalidArgument(
        StrCat({"profile: the line has ", std::to_string(line.size()),
                " points; it needs at least 2"}));
  }
  for (size_t i = 0; i < line.size(); ++i) {
    if (!IsFinite(line[i])) {
      return Status::InvalidArgument(StrCat(
          {"profile: line point ", std::to_string(i), " is not finite"}));
    }
  }
  ProfileBuilder builder(mesh, line, options);
  Status status = builder.Measure();
  if (status.ok()) status = builder.Trace(start);
  if (!status.ok()) return status;
  builder.Finish(out);
  return Status::OK();
}

}  // namespace locator
