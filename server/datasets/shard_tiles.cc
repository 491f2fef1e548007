#include "server/datasets/shard_tiles.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <system_error>
#include <utility>

#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator {
namespace {

bool ParseIndex(std::string_view text, uint64_t* value) {
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), *value);
  return error == std::errc() && end == text.data() + text.size() &&
         !text.empty();
}

// The tile ranges [first, end) `selector` names among `tiles` (see
// ShardTiles::Select), or what is wrong with it.
StatusOr<std::vector<std::pair<uint64_t, uint64_t>>> ParseSelector(
    std::string_view selector, uint64_t tiles) {
  const auto bad = [&](std::string_view why) {
    return Status::InvalidArgument("--tiles " + QuotedInput(selector) + ": " +
                                   std::string(why));
  };
  if (selector.size() > 4096) return bad("longer than 4096 bytes");
  std::vector<std::pair<uint64_t, uint64_t>> ranges;
  if (const size_t slash = selector.find('/');
      slash != std::string_view::npos) {
    uint64_t part = 0, parts = 0;
    if (!ParseIndex(selector.substr(0, slash), &part) ||
        !ParseIndex(selector.substr(slash + 1), &parts) || parts == 0 ||
        part >= parts || parts > std::numeric_limits<uint32_t>::max()) {
      return bad("expected K/N with 0 <= K < N");
    }
    const uint64_t first = part * tiles / parts;
    const uint64_t end = (part + 1) * tiles / parts;
    if (first == end) {
      return bad("part " + std::to_string(part) + " of " +
                 std::to_string(parts) + " gets no tile (the tile set has " +
                 std::to_string(tiles) + ")");
    }
    ranges.emplace_back(first, end);
    return ranges;
  }
  size_t at = 0;
  while (at <= selector.size()) {
    const size_t comma = std::min(selector.find(',', at), selector.size());
    const std::string_view item = selector.substr(at, comma - at);
    const size_t dash = item.find('-');
    uint64_t first = 0, last = 0;
    const bool ok = dash == std::string_view::npos
                        ? ParseIndex(item, &first) && ParseIndex(item, &last)
                        : ParseIndex(item.substr(0, dash), &first) &&
                              ParseIndex(item.substr(dash + 1), &last);
    if (!ok || last < first) {
      return bad("expected K/N or tiles and ranges like 0-9,12");
    }
    if (last >= tiles) {
      return bad("tile " + std::to_string(last) +
                 " does not exist (the tile set has " + std::to_string(tiles) +
                 ")");
    }
    ranges.emplace_back(first, last + 1);
    at = comma + 1;
  }
  return ranges;
}

}  // namespace

ShardTiles::ShardTiles(TileRouter router, std::vector<uint32_t> served,
                       std::string selector, uint64_t fingerprint)
    : router_(std::move(router)),
      served_(std::move(served)),
      is_served_(router_.num_tiles(), false),
      selector_(std::move(selector)),
      fingerprint_(fingerprint) {
  for (const uint32_t tile : served_) is_served_[tile] = true;
}

StatusOr<std::shared_ptr<const ShardTiles>> ShardTiles::Select(
    TileRouter router, std::string_view selector, uint64_t fingerprint) {
  std::vector<std::pair<uint64_t, uint64_t>> ranges = {{0, router.num_tiles()}};
  if (!selector.empty()) {
    ASSIGN_OR_RETURN(ranges, ParseSelector(selector, router.num_tiles()));
  }
  std::vector<bool> selected(router.num_tiles(), false);
  for (const auto& [first, end] : ranges) {
    std::fill(selected.begin() + first, selected.begin() + end, true);
  }
  std::vector<uint32_t> served;
  for (size_t t = 0; t < selected.size(); ++t) {
    if (selected[t]) served.push_back(static_cast<uint32_t>(t));
  }
  return std::shared_ptr<const ShardTiles>(
      new ShardTiles(std::move(router), std::move(served),
                     std::string(selector), fingerprint));
}

Status ShardTiles::CheckSelector(std::string_view selector) {
  // Syntax only: as if the set had as many tiles as can be named.
  if (selector.empty()) return Status::OK();
  return ParseSelector(selector, uint64_t{1} << 32).status();
}

Status ShardTiles::CheckServed(std::span<const Point2> points,
                               size_t first_index) const {
  if (serves_all()) return Status::OK();
  for (size_t i = 0; i < points.size(); ++i) {
    const size_t tile = router_.TileOf(points[i]);
    if (!is_served_[tile]) {
      return Status::FailedPrecondition(
          "point " + std::to_string(first_index + i) + " " +
          PointText(points[i]) + " lies in tile " + std::to_string(tile) +
          ", which this server does not serve (--tiles " +
          QuotedInput(selector_) + "); route by GetTopology");
    }
  }
  return Status::OK();
}

}  // namespace locator
