#include "server/core/tileset/tileset_mesh.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "common/status_macros.h"
#include "locator/engine_info.h"
#include "server/core/dataset/file_io.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/mesh/large_vector.h"
#include "server/core/mesh/mesh_file.h"
#include "server/core/mesh/radix_sort.h"
#include "server/core/tileset/binary_files.h"
#include "server/core/tileset/tileset_vertices.h"
#include "server/core/tiling/open_edges.h"

namespace locator {
namespace {

constexpr uint32_t kOpen = TileTriangles::kOpen;
constexpr size_t kCopyBytes = size_t{8} << 20;

// A triangle in a bin file: its centroid key, its number (its tile's
// offset plus its index there) and itself, corners rotated, neighbours as
// numbers or kOpen.
struct BinnedTriangle {
  uint32_t key;
  uint32_t number;
  MeshTriangle t;
};
static_assert(sizeof(BinnedTriangle) == 32);

uint64_t FaceEdge(uint32_t number, uint32_t edge) {
  return uint64_t{number} << 2 | edge;
}

class MeshAssembler {
 public:
  explicit MeshAssembler(const TileSetMeshInput& in) : in_(in) {}

  Status Run(const std::string& path);

 private:
  std::string BinPath(size_t bin) const {
    return in_.work + "/triangles-" + std::to_string(bin) + ".bin";
  }
  Status BinTriangles();
  Status MatchOpenEdges();
  Status SortBin(size_t bin);
  Status LinkHull();
  Status WriteTriangles();
  // The neighbour field of edge `edge` of triangle `number` in the mesh,
  // for a field that was kOpen in its tile.
  uint32_t ClosedNeighbor(uint32_t number, uint32_t edge) const;
  Status WriteMesh(const std::string& path);

  const TileSetMeshInput& in_;
  VertexFiles vertices_;
  std::vector<uint32_t> first_cells_;  // of the triangle bins
  uint64_t faces_ = 0;
  uint32_t next_position_ = 0;
  // The edges the tiles left open, then the hull's in ring order.
  std::vector<OpenEdge> open_, ring_;
  // (FaceEdge, neighbour number) of edges closed across tiles, and
  // (FaceEdge, position in the hull ring) of hull edges; sorted.
  std::vector<std::pair<uint64_t, uint32_t>> across_, hull_at_;
  // position_[number]: the triangle's index in the mesh.
  LargeVector<uint32_t> position_;
  std::vector<uint32_t> hull_;  // ServingMesh::Edge codes, in ring order
  std::vector<std::array<Point2, 2>> edge_sample_;
};

Status MeshAssembler::BinTriangles() {
  std::vector<uint64_t> weights(in_.binned.grid.num_cells());
  for (size_t c = 0; c < weights.size(); ++c) {
    weights[c] =
        2 * uint64_t{in_.binned.cell_start[c + 1] - in_.binned.cell_start[c]};
  }
  first_cells_ = CutCellRanges(weights, std::max<size_t>(in_.bin_triangles, 1));
  std::vector<std::unique_ptr<AppendFile>> bins(first_cells_.size());
  for (size_t b = 0; b < bins.size(); ++b) {
    bins[b] = std::make_unique<AppendFile>();
    RETURN_IF_ERROR(bins[b]->Create(BinPath(b), size_t{1} << 20));
  }
  const CellGrid& grid = in_.binned.grid;
  for (const TileSetManifest::TileEntry& entry : in_.manifest.tiles) {
    TileVertices tile;
    RETURN_IF_ERROR(tile.Load(in_.dir + "/" + entry.file, vertices_));
    const auto number = static_cast<uint32_t>(faces_);
    const std::span<const MeshTriangle> own = tile.triangles();
    for (uint32_t k = 0; k < own.size(); ++k) {
      const MeshTriangle& m = own[k];
      const std::array<uint32_t, 3> ids = {
          tile.Id(m.corner[0]), tile.Id(m.corner[1]), tile.Id(m.corner[2])};
      const int r = static_cast<int>(std::min_element(ids.begin(), ids.end()) -
                                     ids.begin());
      BinnedTriangle out{0, number + k, {}};
      for (int i = 0; i < 3; ++i) {
        const int from = (i + r) % 3;  // edge i stays opposite corner i
        out.t.corner[i] = m.corner[from];
        out.t.neighbor[i] =
            m.neighbor[from] == kOpen ? kOpen : m.neighbor[from] + number;
      }
      for (uint32_t i = 0; i < 3; ++i) {
        if (out.t.neighbor[i] != kOpen) continue;
        open_.push_back({out.number, i, out.t.corner[Ccw(static_cast<int>(i))],
                         out.t.corner[Cw(static_cast<int>(i))]});
      }
      out.key = ServingMesh::CentroidKey(
          tile.Point(out.t.corner[0]), tile.Point(out.t.corner[1]),
          tile.Point(out.t.corner[2]), grid.box());
      const size_t bin =
          std::upper_bound(first_cells_.begin(), first_cells_.end(),
                           grid.CellOfKey(out.key)) -
          first_cells_.begin() - 1;
      RETURN_IF_ERROR(bins[bin]->AppendBytes(&out, sizeof(out)));
    }
    faces_ += own.size();
  }
  for (const auto& bin : bins) RETURN_IF_ERROR(bin->Close());
  return Status::OK();
}

Status MeshAssembler::MatchOpenEdges() {
  std::vector<std::array<OpenEdge, 2>> pairs;
  RETURN_IF_ERROR(locator::MatchOpenEdges(
      "tile set", std::move(open_),
      [this](uint32_t vertex, uint32_t* id) {
        return vertices_.ReadId(vertex, id);
      },
      &pairs, &ring_));
  for (const auto& [e, g] : pairs) {
    across_.push_back({FaceEdge(e.face, e.edge), g.face});
    across_.push_back({FaceEdge(g.face, g.edge), e.face});
  }
  std::sort(across_.begin(), across_.end());
  return Status::OK();
}

Status MeshAssembler::SortBin(size_t bin) {
  RandomAccessFile file;
  RETURN_IF_ERROR(file.Open(BinPath(bin)));
  LargeVector<BinnedTriangle> records(file.size() / sizeof(BinnedTriangle));
  RETURN_IF_ERROR(file.ReadItems(0, std::span<BinnedTriangle>(records)));
  // In number order already (tiles were binned in order): sorting by key
  // stably keeps it within a key, as the in-memory assembly does.
  LargeVector<uint64_t> items(records.size());
  for (size_t k = 0; k < records.size(); ++k) {
    items[k] = uint64_t{records[k].key} << 32 | k;
  }
  SortByHighHalf(&items);
  Status status;
  const auto corner_ids = [&](uint64_t item) {
    std::array<uint32_t, 3> ids{};
    const MeshTriangle& t = records[static_cast<uint32_t>(item)].t;
    for (int i = 0; i < 3; ++i) {
      const Status read = vertices_.ReadId(t.corner[i], &ids[i]);
      if (!read.ok()) status = read;
    }
    return ids;
  };
  for (size_t k = 0; k < items.size();) {
    size_t end = k + 1;
    while (end < items.size() && (items[end] >> 32) == (items[k] >> 32)) ++end;
    if (end - k > 1) {
      std::sort(items.begin() + k, items.begin() + end,
                [&](uint64_t a, uint64_t b) {
                  return corner_ids(a) < corner_ids(b);
                });
    }
    k = end;
  }
  RETURN_IF_ERROR(status);
  AppendFile sorted;
  RETURN_IF_ERROR(sorted.Create(BinPath(bin), size_t{1} << 20));
  for (const uint64_t item : items) {
    const BinnedTriangle& r = records[static_cast<uint32_t>(item)];
    position_[r.number] = next_position_++;
    RETURN_IF_ERROR(sorted.AppendBytes(&r, sizeof(r)));
  }
  return sorted.Close();
}

Status MeshAssembler::LinkHull() {
  for (size_t n = 0; n < ring_.size(); ++n) {
    const OpenEdge& e = ring_[n];
    hull_at_.push_back({FaceEdge(e.face, e.edge), static_cast<uint32_t>(n)});
    hull_.push_back(
        ServingMesh::Edge(position_[e.face], static_cast<int>(e.edge)));
  }
  std::sort(hull_at_.begin(), hull_at_.end());
  return CheckEulerFormula("tile set", in_.binned.vertices, faces_,
                           ring_.size());
}

uint32_t MeshAssembler::ClosedNeighbor(uint32_t number, uint32_t edge) const {
  const uint64_t key = FaceEdge(number, edge);
  const auto lookup = [key](const auto& sorted) {
    return std::lower_bound(sorted.begin(), sorted.end(),
                            std::pair<uint64_t, uint32_t>{key, 0});
  };
  const auto across = lookup(across_);
  if (across != across_.end() && across->first == key) {
    return position_[across->second];
  }
  return ServingMesh::kHullBit | lookup(hull_at_)->second;
}

Status MeshAssembler::WriteTriangles() {
  AppendFile out;
  RETURN_IF_ERROR(out.Create(in_.work + "/triangles.bin", kCopyBytes));
  // ServingMesh::SampleEdges, as the triangles come in mesh order.
  const uint64_t edges = in_.binned.vertices + faces_ - 1;
  const uint64_t stride = (edges + kEdgeSampleSize - 1) / kEdgeSampleSize;
  uint64_t edge_index = 0;
  uint32_t f = 0;
  for (size_t bin = 0; bin < first_cells_.size(); ++bin) {
    RandomAccessFile file;
    RETURN_IF_ERROR(file.Open(BinPath(bin)));
    LargeVector<BinnedTriangle> records(file.size() / sizeof(BinnedTriangle));
    RETURN_IF_ERROR(file.ReadItems(0, std::span<BinnedTriangle>(records)));
    std::remove(BinPath(bin).c_str());
    for (const BinnedTriangle& r : records) {
      MeshTriangle m = r.t;
      for (uint32_t i = 0; i < 3; ++i) {
        m.neighbor[i] = m.neighbor[i] == kOpen ? ClosedNeighbor(r.number, i)
                                               : position_[m.neighbor[i]];
        if (!ServingMesh::IsHull(m.neighbor[i]) && m.neighbor[i] < f) continue;
        if (edge_index++ % stride != 0) continue;
        std::array<Point2, 2> sample;
        RETURN_IF_ERROR(vertices_.ReadPoint(m.corner[Ccw(static_cast<int>(i))],
                                            &sample[0]));
        RETURN_IF_ERROR(
            vertices_.ReadPoint(m.corner[Cw(static_cast<int>(i))], &sample[1]));
        edge_sample_.push_back(sample);
      }
      RETURN_IF_ERROR(out.AppendBytes(&m, sizeof(m)));
      ++f;
    }
  }
  return out.Close();
}

Status MeshAssembler::WriteMesh(const std::string& path) {
  const BinnedPoints& b = in_.binned;
  MeshFileSummary m;
  m.fingerprint = b.fingerprint;
  m.triangles = faces_;
  m.points = b.vertices;
  m.values = b.has_values ? b.vertices : 0;
  m.ids = b.vertices;
  m.hull = hull_.size();
  m.edge_sample = edge_sample_.size();
  m.in_domain = faces_;
  m.input_points = b.input_points;
  m.duplicates_merged = b.input_points - b.vertices;
  m.box = b.grid.box();
  RETURN_IF_ERROR(CheckMeshFileCounts(m));
  ASSIGN_OR_RETURN(m.digest, VertexDigestOfFiles(in_.work, b));
  const MeshFileSections offsets = MeshFileSectionsOf(m);

  // The sections in file order: a file of the work directory, or bytes.
  struct Section {
    std::string file;
    std::string_view bytes;
  };
  const auto bytes_of = [](const auto& items) {
    return std::string_view(reinterpret_cast<const char*>(items.data()),
                            items.size() * sizeof(items[0]));
  };
  const Section sections[] = {
      {in_.work + "/triangles.bin", {}},
      {BinnedPointsPath(in_.work), {}},
      {b.has_values ? BinnedValuesPath(in_.work) : "", {}},
      {BinnedIdsPath(in_.work), {}},
      {"", bytes_of(hull_)},
      {"", {}},
      {"", {}},
      {"", bytes_of(edge_sample_)},
  };
  // Feeds the payload (every byte after the header) to `emit`.
  std::vector<char> buffer(kCopyBytes);
  const auto payload = [&](const FileAppender& emit) -> Status {
    static constexpr char kZeros[64] = {};
    uint64_t at = kMeshFileHeaderBytes;
    for (size_t k = 0; k < std::size(sections); ++k) {
      RETURN_IF_ERROR(emit(std::string_view(kZeros, offsets.start[k] - at)));
      at = offsets.start[k];
      if (sections[k].file.empty()) {
        RETURN_IF_ERROR(emit(sections[k].bytes));
        at += sections[k].bytes.size();
        continue;
      }
      RandomAccessFile file;
      RETURN_IF_ERROR(file.Open(sections[k].file));
      for (uint64_t done = 0; done < file.size();) {
        const size_t size =
            std::min<uint64_t>(buffer.size(), file.size() - done);
        RETURN_IF_ERROR(file.ReadAt(done, buffer.data(), size));
        RETURN_IF_ERROR(emit(std::string_view(buffer.data(), size)));
        done += size;
      }
      at += file.size();
    }
    return at == offsets.end ? Status::OK()
                             : Status::Internal(
                                   "tile set: the mesh file's "
                                   "sections do not add up");
  };
  Xxh3Digest digest;
  RETURN_IF_ERROR(payload([&](std::string_view bytes) {
    digest.Add(bytes);
    return Status::OK();
  }));
  const std::string header = MeshFileHeader(m, digest.digest());
  return WriteFileAtomically(path, [&](const FileAppender& append) {
    RETURN_IF_ERROR(append(header));
    return payload(append);
  });
}

Status MeshAssembler::Run(const std::string& path) {
  RETURN_IF_ERROR(vertices_.Open(in_.work));
  RETURN_IF_ERROR(BinTriangles());
  RETURN_IF_ERROR(MatchOpenEdges());
  position_.resize(faces_);
  for (size_t bin = 0; bin < first_cells_.size(); ++bin) {
    RETURN_IF_ERROR(SortBin(bin));
  }
  RETURN_IF_ERROR(LinkHull());
  RETURN_IF_ERROR(WriteTriangles());
  LargeVector<uint32_t>().swap(position_);
  const Status written = WriteMesh(path);
  std::remove((in_.work + "/triangles.bin").c_str());
  return written;
}

}  // namespace

Status WriteTileSetMesh(const TileSetMeshInput& in, const std::string& path) {
  return MeshAssembler(in).Run(path);
}

}  // namespace locator
