#include "server/core/tiling/open_edges.h"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>

#include "common/status_macros.h"

namespace locator {
namespace {

uint64_t Ends(const OpenEdge& e) {
  return uint64_t{std::min(e.start, e.end)} << 32 | std::max(e.start, e.end);
}

Status Fault(std::string_view what, const std::string& message) {
  return Status::Internal(std::string(what) + ": " + message);
}

// Orders `hull` into *ring (see MatchOpenEdges).
Status LinkRing(std::string_view what, const std::vector<OpenEdge>& hull,
                const std::function<Status(uint32_t, uint32_t*)>& id_of,
                std::vector<OpenEdge>* ring) {
  const size_t h = hull.size();
  // (end vertex, index in hull), to find the edge that ends where one
  // starts.
  std::vector<std::pair<uint32_t, uint32_t>> by_end(h);
  size_t start = 0;
  uint32_t start_id = 0;
  for (size_t k = 0; k < h; ++k) {
    by_end[k] = {hull[k].end, static_cast<uint32_t>(k)};
    uint32_t id;
    RETURN_IF_ERROR(id_of(hull[k].end, &id));
    if (k == 0 || id < start_id) {
      start = k;
      start_id = id;
    }
  }
  std::sort(by_end.begin(), by_end.end());
  for (size_t k = 1; k < h; ++k) {
    if (by_end[k].first == by_end[k - 1].first) {
      return Fault(what, "hull vertex " + std::to_string(by_end[k].first) +
                             " ends two hull edges");
    }
  }
  ring->clear();
  ring->reserve(h);
  size_t k = start;
  for (size_t n = 0; n < h; ++n) {
    if (n > 0 && k == start)
      return Fault(what, "the hull is more than one ring");
    const OpenEdge& e = hull[k];
    ring->push_back(e);
    const auto next =
        std::lower_bound(by_end.begin(), by_end.end(),
                         std::pair<uint32_t, uint32_t>{e.start, 0});
    if (next == by_end.end() || next->first != e.start) {
      return Fault(
          what, "the hull is not closed at vertex " + std::to_string(e.start));
    }
    k = next->second;
  }
  if (k != start) return Fault(what, "the hull is not one closed ring");
  return Status::OK();
}

}  // namespace

Status MatchOpenEdges(
    std::string_view what, std::vector<OpenEdge> open,
    const std::function<Status(uint32_t vertex, uint32_t* id)>& id_of,
    std::vector<std::array<OpenEdge, 2>>* pairs, std::vector<OpenEdge>* ring) {
  std::sort(open.begin(), open.end(), [](const OpenEdge& x, const OpenEdge& y) {
    return std::make_tuple(Ends(x), x.face, x.edge) <
           std::make_tuple(Ends(y), y.face, y.edge);
  });
  std::vector<OpenEdge> hull;
  pairs->clear();
  for (size_t k = 0; k < open.size();) {
    const OpenEdge& e = open[k];
    const auto name = [&] {
      return "edge " + std::to_string(std::min(e.start, e.end)) + "-" +
             std::to_string(std::max(e.start, e.end));
    };
    if (k + 2 < open.size() && Ends(open[k + 2]) == Ends(e)) {
      return Fault(what, name() + " borders more than two triangles");
    }
    if (k + 1 == open.size() || Ends(open[k + 1]) != Ends(e)) {
      hull.push_back(e);
      ++k;
      continue;
    }
    const OpenEdge& g = open[k + 1];
    if (e.start != g.end) {
      return Fault(what, "the two triangles of " + name() + " overlap");
    }
    pairs->push_back({e, g});
    k += 2;
  }
  return LinkRing(what, hull, id_of, ring);
}

Status CheckEulerFormula(std::string_view what, size_t vertices,
                         size_t triangles, size_t hull_edges) {
  if (2 * vertices == triangles + hull_edges + 2) return Status::OK();
  return Fault(what, std::to_string(vertices) + " vertices, " +
                         std::to_string(triangles) + " triangles and " +
                         std::to_string(hull_edges) +
                         " hull edges break Euler's formula");
}

}  // namespace locator
