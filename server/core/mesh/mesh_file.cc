#include "server/core/mesh/mesh_file.h"

#include <sys/stat.h>

#include <bit>
#include <cstring>
#include <ctime>
#include <span>
#include <utility>

#include "common/status_macros.h"
#include "server/core/dataset/file_io.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/mesh/mesh_check.h"

namespace locator {
namespace {

constexpr char kMagic[8] = {'l', 'o', 'c', 'm', 'e', 's', 'h', '\0'};
constexpr uint32_t kByteOrderMark = 0x01020304u;
constexpr size_t kSectionAlignment = 64;

using Segment = std::array<Point2, 2>;
static_assert(sizeof(Segment) == 32 && sizeof(Point2) == 16);
static_assert(std::endian::native == std::endian::little,
              "mesh files are little-endian");

// The header as it is on disk: fixed-width fields, no padding.
struct Header {
  char magic[8];
  uint32_t version;
  uint32_t byte_order;
  uint64_t fingerprint;
  uint64_t file_bytes;
  // Element counts of the sections, in file order.
  uint64_t triangles, points, values, ids, hull;
  uint64_t boundary, breaklines, edge_sample;
  uint64_t in_domain;
  uint64_t input_points;
  uint64_t digest;
  uint64_t constraints;
  uint64_t holes;
  double box[4];  // min_x, min_y, max_x, max_y
  uint64_t payload_checksum;
  uint64_t duplicates_merged;
  uint64_t reserved[8];      // zero
  uint64_t header_checksum;  // of every byte before it
};
static_assert(sizeof(Header) == kMeshFileHeaderBytes);

// Where each section starts, and where the file ends.
struct Layout {
  uint64_t triangles, points, values, ids, hull;
  uint64_t boundary, breaklines, edge_sample;
  uint64_t end;
};

uint64_t AlignUp(uint64_t offset) {
  return (offset + kSectionAlignment - 1) / kSectionAlignment *
         kSectionAlignment;
}

// Precondition: every count is at most ServingMesh::kMaxElements, so that
// no offset overflows.
Layout LayoutOf(const Header& h) {
  Layout l;
  uint64_t at = kMeshFileHeaderBytes;
  const auto place = [&at](uint64_t count, uint64_t element_bytes) {
    const uint64_t start = AlignUp(at);
    at = start + count * element_bytes;
    return start;
  };
  l.triangles = place(h.triangles, sizeof(MeshTriangle));
  l.points = place(h.points, sizeof(Point2));
  l.values = place(h.values, sizeof(double));
  l.ids = place(h.ids, sizeof(uint32_t));
  l.hull = place(h.hull, sizeof(uint32_t));
  l.boundary = place(h.boundary, sizeof(Segment));
  l.breaklines = place(h.breaklines, sizeof(Segment));
  l.edge_sample = place(h.edge_sample, sizeof(Segment));
  l.end = at;
  return l;
}

uint64_t HeaderChecksum(const Header& h) {
  return Xxh3Of(std::string_view(reinterpret_cast<const char*>(&h),
                                 offsetof(Header, header_checksum)));
}

template <class T>
std::string_view BytesOf(std::span<const T> values) {
  return {reinterpret_cast<const char*>(values.data()), values.size_bytes()};
}

template <class T>
std::span<const T> SectionAt(std::string_view file, uint64_t offset,
                             uint64_t count) {
  return {reinterpret_cast<const T*>(file.data() + offset),
          static_cast<size_t>(count)};
}

Status Unusable(const std::string& why) {
  return Status::InvalidArgument("unusable mesh file: " + why);
}

// The counts a header may hold: within the mesh's index range.
bool CountsInRange(const Header& h) {
  for (const uint64_t count : {h.triangles, h.points, h.values, h.ids, h.hull,
                               h.boundary, h.breaklines, h.edge_sample}) {
    if (count > ServingMesh::kMaxElements) return false;
  }
  return true;
}

Status CheckHeader(std::string_view bytes, uint64_t fingerprint, Header* h) {
  if (bytes.size() < sizeof(Header)) {
    return Unusable("truncated: " + std::to_string(bytes.size()) +
                    " bytes, shorter than the " +
                    std::to_string(sizeof(Header)) + "-byte header");
  }
  std::memcpy(h, bytes.data(), sizeof(Header));
  if (std::memcmp(h->magic, kMagic, sizeof(kMagic)) != 0) {
    return Unusable("not a locator mesh file (wrong magic)");
  }
  if (h->byte_order != kByteOrderMark) {
    return Unusable("written with another byte order");
  }
  if (h->version != kMeshFileVersion) {
    return Unusable("format version " + std::to_string(h->version) +
                    ", this build reads version " +
                    std::to_string(kMeshFileVersion));
  }
  if (HeaderChecksum(*h) != h->header_checksum) {
    return Unusable("header checksum mismatch (corrupt header)");
  }
  if (h->fingerprint != fingerprint) {
    return Unusable("made for another dataset (fingerprint " +
                    std::to_string(h->fingerprint) + ", expected " +
                    std::to_string(fingerprint) + ")");
  }
  if (!CountsInRange(*h)) return Unusable("a section count is out of range");
  const uint64_t expected = LayoutOf(*h).end;
  if (h->file_bytes != expected || bytes.size() != expected) {
    return Unusable("truncated or padded: " + std::to_string(bytes.size()) +
                    " bytes, the header describes " + std::to_string(expected));
  }
  return Status::OK();
}

Header HeaderOf(const MeshFileSummary& m) {
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof(kMagic));
  h.version = kMeshFileVersion;
  h.byte_order = kByteOrderMark;
  h.fingerprint = m.fingerprint;
  h.triangles = m.triangles;
  h.points = m.points;
  h.values = m.values;
  h.ids = m.ids;
  h.hull = m.hull;
  h.boundary = m.boundary;
  h.breaklines = m.breaklines;
  h.edge_sample = m.edge_sample;
  h.in_domain = m.in_domain;
  h.input_points = m.input_points;
  h.digest = m.digest;
  h.constraints = m.constraints;
  h.holes = m.holes;
  h.duplicates_merged = m.duplicates_merged;
  h.box[0] = m.box.min_x;
  h.box[1] = m.box.min_y;
  h.box[2] = m.box.max_x;
  h.box[3] = m.box.max_y;
  h.file_bytes = LayoutOf(h).end;
  return h;
}

}  // namespace

MeshFileSections MeshFileSectionsOf(const MeshFileSummary& summary) {
  const Layout l = LayoutOf(HeaderOf(summary));
  return {{l.triangles, l.points, l.values, l.ids, l.hull, l.boundary,
           l.breaklines, l.edge_sample},
          l.end};
}

Status CheckMeshFileCounts(const MeshFileSummary& summary) {
  return CountsInRange(HeaderOf(summary))
             ? Status::OK()
             : Status::InvalidArgument("the mesh is too large for a mesh file");
}

std::string MeshFileHeader(const MeshFileSummary& summary,
                           uint64_t payload_checksum) {
  Header h = HeaderOf(summary);
  h.payload_checksum = payload_checksum;
  h.header_checksum = HeaderChecksum(h);
  return std::string(reinterpret_cast<const char*>(&h), sizeof(h));
}

Status WriteMeshFile(const std::string& path, uint64_t fingerprint,
                     const BuiltMesh& built) {
  const ServingMesh::Arrays& a = built.mesh->arrays();
  const MeshFacts& facts = built.facts;
  MeshFileSummary m;
  m.fingerprint = fingerprint;
  m.triangles = a.triangles.size();
  m.points = a.points.size();
  m.values = a.values.size();
  m.ids = a.ids.size();
  m.hull = a.hull.size();
  m.boundary = facts.outline.boundary.size();
  m.breaklines = facts.outline.breaklines.size();
  m.edge_sample = facts.edge_sample.size();
  m.in_domain = a.in_domain;
  m.input_points = a.input_points;
  m.digest = a.digest;
  m.constraints = facts.constraints;
  m.holes = facts.holes;
  m.duplicates_merged = facts.duplicates_merged;
  m.box = a.box;
  RETURN_IF_ERROR(CheckMeshFileCounts(m));
  const MeshFileSections offsets = MeshFileSectionsOf(m);

  // The sections with the zero padding before each, in file order.
  const std::string_view sections[] = {
      BytesOf(a.triangles),
      BytesOf(a.points),
      BytesOf(a.values),
      BytesOf(a.ids),
      BytesOf(a.hull),
      BytesOf(std::span<const Segment>(facts.outline.boundary)),
      BytesOf(std::span<const Segment>(facts.outline.breaklines)),
      BytesOf(std::span<const Segment>(facts.edge_sample)),
  };
  static constexpr char kZeros[kSectionAlignment] = {};
  std::vector<std::string_view> pieces = {{}};  // the header, set below
  Xxh3Digest payload_digest;
  uint64_t at = kMeshFileHeaderBytes;
  for (size_t k = 0; k < std::size(sections); ++k) {
    const std::string_view padding(kZeros, offsets.start[k] - at);
    pieces.push_back(padding);
    pieces.push_back(sections[k]);
    payload_digest.Add(padding);
    payload_digest.Add(sections[k]);
    at = offsets.start[k] + sections[k].size();
  }
  const std::string header = MeshFileHeader(m, payload_digest.digest());
  pieces[0] = header;
  return WriteFileAtomically(path, pieces);
}

namespace {

// DecodeMeshFile; with `contents` false, of a file checked before (see
// MapMeshFile): the header and layout only, not a byte of the sections.
Status Decode(std::string_view bytes, uint64_t fingerprint, bool contents,
              ServingMesh::Arrays* arrays, MeshFacts* facts) {
  Header h;
  RETURN_IF_ERROR(CheckHeader(bytes, fingerprint, &h));
  const std::string_view payload = bytes.substr(kMeshFileHeaderBytes);
  if (contents && Xxh3Of(payload) != h.payload_checksum) {
    return Unusable("checksum mismatch (corrupt contents)");
  }
  const Layout l = LayoutOf(h);
  ServingMesh::Arrays a;
  a.triangles = SectionAt<MeshTriangle>(bytes, l.triangles, h.triangles);
  a.points = SectionAt<Point2>(bytes, l.points, h.points);
  a.values = SectionAt<double>(bytes, l.values, h.values);
  a.ids = SectionAt<uint32_t>(bytes, l.ids, h.ids);
  a.hull = SectionAt<uint32_t>(bytes, l.hull, h.hull);
  if (h.in_domain > h.triangles) {
    return Unusable("more in-domain triangles than triangles");
  }
  a.in_domain = static_cast<uint32_t>(h.in_domain);
  a.box = BoundingBox{h.box[0], h.box[1], h.box[2], h.box[3]};
  a.input_points = h.input_points;
  a.digest = h.digest;
  MeshFacts f;
  f.constraints = h.constraints;
  f.holes = h.holes;
  f.duplicates_merged = h.duplicates_merged;
  const auto segments = [&bytes](uint64_t offset, uint64_t count) {
    const auto s = SectionAt<Segment>(bytes, offset, count);
    return std::vector<Segment>(s.begin(), s.end());
  };
  f.outline.boundary = segments(l.boundary, h.boundary);
  f.outline.breaklines = segments(l.breaklines, h.breaklines);
  f.edge_sample = segments(l.edge_sample, h.edge_sample);
  if (contents) {
    if (Status s = CheckMeshArrays(a); !s.ok()) return Unusable(s.message());
    for (const auto* list :
         {&f.outline.boundary, &f.outline.breaklines, &f.edge_sample}) {
      for (const Segment& segment : *list) {
        if (!IsFinite(segment[0]) || !IsFinite(segment[1])) {
          return Unusable("a drawing segment has a non-finite coordinate");
        }
      }
    }
  }
  *arrays = a;
  *facts = std::move(f);
  return Status::OK();
}

// The stamp of a checked file: what identifies its bytes on this host.
std::string StampOf(const struct stat& st) {
  const uint64_t fields[] = {static_cast<uint64_t>(st.st_dev),
                             static_cast<uint64_t>(st.st_ino),
                             static_cast<uint64_t>(st.st_size),
                             static_cast<uint64_t>(st.st_mtim.tv_sec),
                             static_cast<uint64_t>(st.st_mtim.tv_nsec)};
  return "locmesh checked " + std::to_string(kMeshFileVersion) + " " +
         std::string(reinterpret_cast<const char*>(fields), sizeof(fields));
}

std::string StampPath(const std::string& path) { return path + ".checked"; }

// Whether the stamp beside `path` describes the file `st` describes.
bool Stamped(const std::string& path, const struct stat& st) {
  std::string stamp;
  return ReadWholeFile(StampPath(path), "stamp", &stamp, 256).ok() &&
         stamp == StampOf(st);
}

// A mapped mesh file backing a mesh's arrays.
class MappedStorage : public ServingMesh::Storage {
 public:
  explicit MappedStorage(MappedFile file) : file(std::move(file)) {}
  MappedFile file;
};

}  // namespace

Status DecodeMeshFile(std::string_view bytes, uint64_t fingerprint,
                      ServingMesh::Arrays* arrays, MeshFacts* facts) {
  return Decode(bytes, fingerprint, /*contents=*/true, arrays, facts);
}

StatusOr<BuiltMesh> MapMeshFile(const std::string& path, uint64_t fingerprint) {
  struct stat before;
  const bool known = ::stat(path.c_str(), &before) == 0;
  const bool checked = known && Stamped(path, before);
  MappedFile file;
  RETURN_IF_ERROR(MappedFile::Open(
      path, "mesh file", &file,
      checked ? MappedFile::Pages::kOnDemand : MappedFile::Pages::kAtOnce));
  ServingMesh::Arrays arrays;
  MeshFacts facts;
  RETURN_IF_ERROR(Decode(file.bytes(), fingerprint, !checked, &arrays, &facts));
  struct stat after;
  if (!checked && known && ::stat(path.c_str(), &after) == 0 &&
      StampOf(after) == StampOf(before) &&
      ::time(nullptr) > after.st_mtim.tv_sec + 1) {
    // Best effort: without a stamp the next map checks the file again.
    (void)WriteFileAtomically(StampPath(path), StampOf(after));
  }
  BuiltMesh built;
  built.mesh = std::make_shared<const ServingMesh>(
      std::make_unique<MappedStorage>(std::move(file)), arrays);
  built.facts = std::move(facts);
  return built;
}

}  // namespace locator
