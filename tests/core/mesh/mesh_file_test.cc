// Mesh files and the mesh cache: a mapped mesh is the built one, byte for
// byte, and answers alike; every kind of unusable file is ignored with its
// reason and rebuilt; the bounds checks catch what a resealed file could
// smuggle in; the tuning state keeps working beside a mapped mesh.

#include "server/core/mesh/mesh_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/dataset/dataset_fingerprint.h"
#include "server/core/dataset/file_io.h"
#include "server/core/mesh/mesh_cache.h"
#include "server/core/mesh/mesh_check.h"
#include "tests/core/scratch_dir.h"
#include "tests/core/test_datasets.h"
#include "tests/fuzz/mesh_file_fixture.h"

namespace locator {
namespace {

using ::testing::HasSubstr;

// The engine Engine::Create makes of `dataset`; null, failing the test, if
// it cannot.
std::unique_ptr<Engine> CreateEngine(const Dataset& dataset,
                                     const EngineOptions& options) {
  StatusOr<std::unique_ptr<Engine>> engine = Engine::Create(dataset, options);
  EXPECT_TRUE(engine.ok()) << engine.status().ToString();
  return engine.ok() ? *std::move(engine) : nullptr;
}

template <class T>
std::string Bytes(std::span<const T> values) {
  return std::string(reinterpret_cast<const char*>(values.data()),
                     values.size_bytes());
}

using Segments = std::vector<std::array<Point2, 2>>;

std::string Bytes(const Segments& segments) {
  return Bytes(std::span<const std::array<Point2, 2>>(segments));
}

void ExpectSameMesh(const BuiltMesh& a, const BuiltMesh& b) {
  const ServingMesh::Arrays& x = a.mesh->arrays();
  const ServingMesh::Arrays& y = b.mesh->arrays();
  EXPECT_EQ(Bytes(x.triangles), Bytes(y.triangles));
  EXPECT_EQ(Bytes(x.points), Bytes(y.points));
  EXPECT_EQ(Bytes(x.values), Bytes(y.values));
  EXPECT_EQ(Bytes(x.ids), Bytes(y.ids));
  EXPECT_EQ(Bytes(x.hull), Bytes(y.hull));
  EXPECT_EQ(x.in_domain, y.in_domain);
  EXPECT_EQ(Bytes(std::span(&x.box, 1)), Bytes(std::span(&y.box, 1)));
  EXPECT_EQ(x.input_points, y.input_points);
  EXPECT_EQ(x.digest, y.digest);
  EXPECT_EQ(a.facts.constraints, b.facts.constraints);
  EXPECT_EQ(a.facts.holes, b.facts.holes);
  EXPECT_EQ(a.facts.duplicates_merged, b.facts.duplicates_merged);
  EXPECT_EQ(Bytes(a.facts.outline.boundary), Bytes(b.facts.outline.boundary));
  EXPECT_EQ(Bytes(a.facts.outline.breaklines),
            Bytes(b.facts.outline.breaklines));
  EXPECT_EQ(Bytes(a.facts.edge_sample), Bytes(b.facts.edge_sample));
}

std::string ReadMeshBytes(const std::string& path) {
  std::string bytes;
  EXPECT_TRUE(ReadWholeFile(path, "test file", &bytes).ok());
  return bytes;
}

void WriteMeshBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

class MeshFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dataset_ = fuzz::MeshFileFixtureDataset();
    fingerprint_ = DatasetFingerprint(dataset_);
    const Status built =
        BuildOrMapMesh(dataset_, dir_.path(), &built_, &first_);
    ASSERT_TRUE(built.ok()) << built.ToString();
  }

  // Decodes `bytes` as the fixture's mesh file.
  Status Decode(const std::string& bytes) {
    ServingMesh::Arrays arrays;
    MeshFacts facts;
    return DecodeMeshFile(bytes, fingerprint_, &arrays, &facts);
  }

  Dataset dataset_;
  uint64_t fingerprint_ = 0;
  test::ScratchDir dir_;
  BuiltMesh built_;
  MeshCacheOutcome first_;
};

TEST_F(MeshFileTest, FirstBuildTriangulatesAndWritesTheFile) {
  EXPECT_FALSE(first_.mapped);
  EXPECT_EQ(first_.load_error, "");
  EXPECT_EQ(first_.save_error, "");
  EXPECT_THAT(dir_.Entries(), ::testing::ElementsAre(::testing::MatchesRegex(
                                  "mesh-[0-9a-f]{16}\\.mesh")));
  EXPECT_THAT(first_.path, HasSubstr(dir_.path()));
  EXPECT_TRUE(CheckMeshArrays(built_.mesh->arrays()).ok());
  EXPECT_GT(built_.facts.constraints, 0u);
  EXPECT_EQ(built_.facts.holes, 1u);
  EXPECT_EQ(built_.facts.duplicates_merged, 1u);
  EXPECT_FALSE(built_.facts.outline.boundary.empty());
  EXPECT_FALSE(built_.facts.outline.breaklines.empty());
}

TEST_F(MeshFileTest, SecondBuildMapsTheSameMesh) {
  BuiltMesh mapped;
  MeshCacheOutcome second;
  ASSERT_TRUE(BuildOrMapMesh(dataset_, dir_.path(), &mapped, &second).ok());
  EXPECT_TRUE(second.mapped);
  EXPECT_EQ(second.path, first_.path);
  EXPECT_EQ(second.load_error, "");
  ExpectSameMesh(built_, mapped);
  // The resealing the fuzzer uses changes nothing in a sound file.
  const std::string bytes = ReadMeshBytes(first_.path);
  std::string resealed = bytes;
  fuzz::ResealMeshFile(&resealed, fingerprint_);
  EXPECT_EQ(resealed, bytes);
}

TEST_F(MeshFileTest, EnginesOnBuiltAndMappedMeshesAnswerAlike) {
  EngineOptions options;
  options.mesh_cache_dir = dir_.path();
  const std::unique_ptr<Engine> built = CreateEngine(dataset_, EngineOptions());
  ASSERT_NE(built, nullptr);
  const std::unique_ptr<Engine> mapped = CreateEngine(dataset_, options);
  ASSERT_NE(mapped, nullptr);
  EXPECT_TRUE(mapped->dataset_info().mesh_cache.mapped);
  DatasetInfo a = built->dataset_info(), b = mapped->dataset_info();
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.all_triangles, b.all_triangles);
  EXPECT_EQ(a.constraints, b.constraints);
  EXPECT_EQ(a.holes, b.holes);
  EXPECT_EQ(a.duplicates_merged, 1u);
  EXPECT_EQ(b.duplicates_merged, 1u);
  EXPECT_EQ(a.triangulation_bytes, b.triangulation_bytes);
  EXPECT_EQ(Bytes(built->EdgeSample()), Bytes(mapped->EdgeSample()));
  // Points everywhere: inside, in the hole, outside the domain and the
  // hull, on every vertex and edge midpoint.
  std::vector<Point2> queries;
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> coordinate(-0.2, 1.2);
  for (int i = 0; i < 2000; ++i) {
    queries.push_back({coordinate(random), coordinate(random)});
  }
  const ServingMesh::Arrays& arrays = built_.mesh->arrays();
  for (const MeshTriangle& t : arrays.triangles) {
    const Point2& p = arrays.points[t.corner[0] & ServingMesh::kIndexMask];
    const Point2& q = arrays.points[t.corner[1] & ServingMesh::kIndexMask];
    queries.push_back(p);
    queries.push_back({(p.x + q.x) / 2, (p.y + q.y) / 2});
  }
  // Both agree with CGAL's locate() (for a point on an edge or vertex any
  // triangle containing it is right, and the walks start differently).
  const std::unique_ptr<Triangulation> t = test::BuildTriangulation(dataset_);
  ASSERT_NE(t, nullptr);
  std::vector<LocateResult> x, y;
  ASSERT_TRUE(built->LocateBatch(queries, &x).ok());
  ASSERT_TRUE(mapped->LocateBatch(queries, &y).ok());
  for (size_t i = 0; i < queries.size(); ++i) {
    const LocateResult reference = t->ReferenceLocate(queries[i]);
    EXPECT_TRUE(t->Agrees(queries[i], x[i], reference)) << i;
    EXPECT_TRUE(t->Agrees(queries[i], y[i], reference)) << i;
    EXPECT_EQ(x[i].value, y[i].value) << i;
  }
}

TEST_F(MeshFileTest, TuningStateIsRestoredOntoAMappedMesh) {
  test::ScratchDir state_dir;
  EngineOptions options;
  options.mesh_cache_dir = dir_.path();
  options.tuning.state_dir = state_dir.path();
  options.tuning.retune_every = 500;
  const std::unique_ptr<Engine> first = CreateEngine(dataset_, options);
  ASSERT_NE(first, nullptr);
  std::mt19937_64 random(5);
  std::normal_distribution<double> near(0.25, 0.02);
  for (int i = 0; i < 3000; ++i) {
    LocateResult result;
    ASSERT_TRUE(first->Locate({near(random), near(random)}, &result).ok());
  }
  first->Retune();
  ASSERT_TRUE(first->SaveTuningState().ok());
  const std::unique_ptr<Engine> second = CreateEngine(dataset_, options);
  ASSERT_NE(second, nullptr);
  EXPECT_TRUE(second->dataset_info().mesh_cache.mapped);
  const PersistenceSummary p = second->Stats().tuning.persistence;
  EXPECT_TRUE(p.restored_from_state) << p.load_error;
}

struct BadFile {
  std::string name;
  std::function<void(std::string* bytes, uint64_t fingerprint)> spoil;
  std::string reason;
};

// Changes the header field at `at` and reseals, so only that field is bad.
void SetU64AndReseal(std::string* bytes, size_t at, uint64_t value,
                     uint64_t fingerprint) {
  fuzz::PutU64(bytes, at, value);
  fuzz::ResealMeshFile(bytes, fingerprint);
}

const BadFile kBadFiles[] = {
    {"empty", [](std::string* b, uint64_t) { b->clear(); }, "is empty"},
    {"shorter_than_header", [](std::string* b, uint64_t) { b->resize(100); },
     "shorter than the 256-byte header"},
    {"cut_in_half", [](std::string* b, uint64_t) { b->resize(b->size() / 2); },
     "truncated or padded"},
    {"padded", [](std::string* b, uint64_t) { b->append(64, '\0'); },
     "truncated or padded"},
    {"other_magic", [](std::string* b, uint64_t) { (*b)[0] = 'X'; },
     "not a locator mesh file"},
    {"other_byte_order",
     [](std::string* b, uint64_t) { std::swap((*b)[12], (*b)[15]); },
     "another byte order"},
    {"other_version",
     [](std::string* b, uint64_t f) {
       (*b)[8] = 4;
       fuzz::ResealMeshFile(b, f);
     },
     "format version 4, this build reads version 3"},
    {"corrupt_header", [](std::string* b, uint64_t) { (*b)[40] ^= 1; },
     "header checksum mismatch"},
    {"corrupt_contents", [](std::string* b, uint64_t) { b->back() ^= 1; },
     "checksum mismatch (corrupt contents)"},
    {"other_dataset",
     [](std::string* b, uint64_t f) { fuzz::ResealMeshFile(b, f + 1); },
     "made for another dataset"},
    {"neighbour_out_of_range",
     [](std::string* b, uint64_t f) {
       fuzz::PutU64(b, kMeshFileHeaderBytes + 12, 0x7ffffff0);
       fuzz::ResealMeshFile(b, f);
     },
     "invalid mesh"},
    {"clockwise_triangle",
     [](std::string* b, uint64_t f) {
       // Swap corners 0 and 1 of triangle 0 (bytes 0-3 and 4-7).
       char* t = b->data() + kMeshFileHeaderBytes;
       for (int i = 0; i < 4; ++i) std::swap(t[i], t[4 + i]);
       fuzz::ResealMeshFile(b, f);
     },
     "invalid mesh: triangle 0 is not counter-clockwise"},
    {"in_domain_over_count",
     [](std::string* b, uint64_t f) {
       SetU64AndReseal(b, 96, uint64_t{1} << 40, f);
     },
     "more in-domain triangles than triangles"},
    {"huge_count",
     [](std::string* b, uint64_t f) {
       SetU64AndReseal(b, 40, uint64_t{1} << 62, f);
     },
     "a section count is out of range"},
};

class BadMeshFileTest : public MeshFileTest,
                        public ::testing::WithParamInterface<BadFile> {};

TEST_P(BadMeshFileTest, IsIgnoredWithItsReasonThenRebuiltAndRewritten) {
  const std::string sound = ReadMeshBytes(first_.path);
  std::string bytes = sound;
  GetParam().spoil(&bytes, fingerprint_);
  WriteMeshBytes(first_.path, bytes);
  BuiltMesh rebuilt;
  MeshCacheOutcome outcome;
  ASSERT_TRUE(BuildOrMapMesh(dataset_, dir_.path(), &rebuilt, &outcome).ok());
  EXPECT_FALSE(outcome.mapped);
  EXPECT_THAT(outcome.load_error, HasSubstr(GetParam().reason));
  EXPECT_EQ(outcome.save_error, "");
  ExpectSameMesh(built_, rebuilt);
  EXPECT_EQ(ReadMeshBytes(first_.path), sound);
}

INSTANTIATE_TEST_SUITE_P(Rows, BadMeshFileTest, ::testing::ValuesIn(kBadFiles),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                           return info.param.name;
                         });

// MapMeshFile checks a file once: the first map reads all of it and stamps
// it, later maps of the same file check the header only; a file written
// since is checked again.
TEST_F(MeshFileTest, ACheckedFileIsStampedAndLaterMapsReadOnlyItsHeader) {
  namespace fs = std::filesystem;
  const std::string stamp = first_.path + ".checked";
  ASSERT_TRUE(MapMeshFile(first_.path, fingerprint_).ok());
  // Written within the last second: a later write could keep its time.
  EXPECT_FALSE(fs::exists(stamp));

  const auto aged = fs::last_write_time(first_.path) - std::chrono::seconds(10);
  fs::last_write_time(first_.path, aged);
  ASSERT_TRUE(MapMeshFile(first_.path, fingerprint_).ok());
  EXPECT_TRUE(fs::exists(stamp));

  // Spoiled in place with its time put back, the file is what the stamp
  // describes: its contents are not read, its header still is.
  std::string bytes = ReadMeshBytes(first_.path);
  bytes.back() ^= 1;
  WriteMeshBytes(first_.path, bytes);
  fs::last_write_time(first_.path, aged);
  EXPECT_TRUE(MapMeshFile(first_.path, fingerprint_).ok());
  EXPECT_THAT(MapMeshFile(first_.path, fingerprint_ + 1).status().message(),
              HasSubstr("made for another dataset"));

  // Written again (a new time): checked whole, and the damage found.
  fs::last_write_time(first_.path, aged + std::chrono::seconds(1));
  EXPECT_THAT(MapMeshFile(first_.path, fingerprint_).status().message(),
              HasSubstr("checksum mismatch (corrupt contents)"));
}

TEST_F(MeshFileTest, ADirectoryInPlaceOfTheFileIsIgnoredAndNotOverwritten) {
  std::filesystem::remove(first_.path);
  std::filesystem::create_directory(first_.path);
  BuiltMesh rebuilt;
  MeshCacheOutcome outcome;
  ASSERT_TRUE(BuildOrMapMesh(dataset_, dir_.path(), &rebuilt, &outcome).ok());
  EXPECT_FALSE(outcome.mapped);
  EXPECT_THAT(outcome.load_error, HasSubstr("not a readable regular file"));
  EXPECT_THAT(outcome.save_error, HasSubstr("cannot rename"));
  ExpectSameMesh(built_, rebuilt);
}

// The committed fuzz seeds are the files the fixture's datasets make now.
// With LOCATOR_WRITE_FUZZ_SEEDS=1 in the environment this test writes them
// afresh (after a change of the format or of the fixture).
TEST(MeshFileSeedsTest, CommittedFuzzSeedsAreCurrentFiles) {
  const std::string corpus = LOCATOR_MESH_FILE_CORPUS;
  const std::pair<std::string, Dataset> seeds[] = {
      {"holed_values.mesh", fuzz::MeshFileFixtureDataset()},
      {"plain.mesh", GenerateUniform(12, 3)},
  };
  for (const auto& [name, dataset] : seeds) {
    test::ScratchDir dir;
    BuiltMesh built;
    MeshCacheOutcome outcome;
    ASSERT_TRUE(BuildOrMapMesh(dataset, dir.path(), &built, &outcome).ok());
    const std::string bytes = ReadMeshBytes(outcome.path);
    if (std::getenv("LOCATOR_WRITE_FUZZ_SEEDS") != nullptr) {
      WriteMeshBytes(corpus + "/" + name, bytes);
    }
    EXPECT_EQ(ReadMeshBytes(corpus + "/" + name), bytes) << name;
  }
}

// format2.mesh is plain.mesh as version 2 wrote it (an FNV-1a dataset
// digest): a cache holding it maps nothing, says why, and is rewritten.
TEST(MeshFileSeedsTest, AFileOfTheFormerFormatIsRebuilt) {
  const Dataset dataset = GenerateUniform(12, 3);
  test::ScratchDir dir;
  const std::string path =
      MeshFilePath(dir.path(), DatasetFingerprint(dataset));
  WriteMeshBytes(path, ReadMeshBytes(std::string(LOCATOR_MESH_FILE_CORPUS) +
                                     "/format2.mesh"));
  BuiltMesh built;
  MeshCacheOutcome outcome;
  ASSERT_TRUE(BuildOrMapMesh(dataset, dir.path(), &built, &outcome).ok());
  EXPECT_FALSE(outcome.mapped);
  EXPECT_THAT(outcome.load_error,
              HasSubstr("format version 2, this build reads version 3"));
  EXPECT_TRUE(outcome.save_error.empty()) << outcome.save_error;
  BuiltMesh mapped;
  MeshCacheOutcome again;
  ASSERT_TRUE(BuildOrMapMesh(dataset, dir.path(), &mapped, &again).ok());
  EXPECT_TRUE(again.mapped) << again.load_error;
  ExpectSameMesh(built, mapped);
}

TEST(GeneratedMeshTest, CanonicalKeysNameTheSamePoints) {
  const auto key = [](const std::string& spec) {
    const StatusOr<GeneratorSpec> g = ParseGeneratorSpec(spec);
    EXPECT_TRUE(g.ok()) << spec;
    return g.ok() ? g->CanonicalKey() : std::string();
  };
  EXPECT_EQ(key("uniform:1000"), key("uniform:1000:1"));
  EXPECT_EQ(key("clusters:1000:4"), key("clusters:1000:4:1"));
  EXPECT_NE(key("uniform:1000:1"), key("uniform:1000:2"));
  EXPECT_NE(key("uniform:1000:1"), key("uniform:1001:1"));
  EXPECT_NE(key("clusters:1000:4:1"), key("clusters:1000:5:1"));
  EXPECT_NE(key("uniform:1000:1"), key("clusters:1000:1:1"));
  EXPECT_THAT(ParseGeneratorSpec("uniform:0").status().message(),
              HasSubstr("N must be a positive integer"));
  EXPECT_THAT(ParseGeneratorSpec("clusters:5:9").status().message(),
              HasSubstr("K must not exceed N"));
}

// A generator spec's mesh is found through its key file, without the
// points; a missing or malformed key sends the caller to generate them.
TEST(GeneratedMeshTest, KeyFileLeadsToTheMeshWithoutThePoints) {
  test::ScratchDir dir;
  const StatusOr<GeneratorSpec> parsed = ParseGeneratorSpec("uniform:500:9");
  ASSERT_TRUE(parsed.ok());
  const GeneratorSpec& spec = *parsed;
  uint64_t fingerprint = 0;
  EXPECT_EQ(FindGeneratedFingerprint(dir.path(), spec, &fingerprint).code(),
            Status::Code::kNotFound);
  EngineOptions options;
  options.mesh_cache_dir = dir.path();
  const std::unique_ptr<Engine> built =
      CreateEngine(GenerateUniform(500, 9), options);
  ASSERT_NE(built, nullptr);
  const MeshCacheOutcome& cache = built->dataset_info().mesh_cache;
  ASSERT_TRUE(
      RecordGeneratedFingerprint(dir.path(), spec, cache.fingerprint).ok());
  ASSERT_TRUE(FindGeneratedFingerprint(dir.path(), spec, &fingerprint).ok());
  EXPECT_EQ(fingerprint, cache.fingerprint);
  DatasetOrigin origin;
  origin.source = "uniform:500:9";
  const StatusOr<std::unique_ptr<Engine>> from_file =
      Engine::CreateFromMeshFile(fingerprint, origin, options);
  ASSERT_TRUE(from_file.ok()) << from_file.status().ToString();
  const Engine* mapped = from_file->get();
  const DatasetInfo& info = mapped->dataset_info();
  EXPECT_TRUE(info.mesh_cache.mapped);
  EXPECT_EQ(info.source, "uniform:500:9");
  EXPECT_EQ(info.input_points, 500u);
  EXPECT_EQ(info.triangles, built->dataset_info().triangles);
  EXPECT_EQ(Bytes(mapped->EdgeSample()), Bytes(built->EdgeSample()));
  // Another fingerprint has no file; a key file that is not one is refused.
  EXPECT_EQ(Engine::CreateFromMeshFile(fingerprint + 1, origin, options)
                .status()
                .code(),
            Status::Code::kNotFound);
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    if (entry.path().extension() == ".key") {
      WriteMeshBytes(entry.path().string(), "not a key\n");
    }
  }
  EXPECT_THAT(
      FindGeneratedFingerprint(dir.path(), spec, &fingerprint).message(),
      HasSubstr("is not 16 hex digits and a newline"));
}

TEST(DatasetFingerprintTest, ChangesWithEveryInputOfTheTriangulation) {
  const Dataset base = fuzz::MeshFileFixtureDataset();
  const uint64_t fingerprint = DatasetFingerprint(base);
  const std::function<void(Dataset*)> changes[] = {
      [](Dataset* d) { d->points[7].x += 1e-12; },
      [](Dataset* d) { d->values[3] = 1; },
      [](Dataset* d) { d->values.clear(); },
      [](Dataset* d) { d->constraints.rings.pop_back(); },
      [](Dataset* d) {
        // The same lines, split differently between the lists.
        d->constraints.segments.push_back(d->constraints.rings.back());
        d->constraints.rings.pop_back();
      },
      [](Dataset* d) { d->constraints.breaklines[0].points[1].y = 0.31; },
      [](Dataset* d) {
        d->constraints.hole_seeds.push_back({0.5, 0.5});
      },
      [](Dataset* d) {
        d->constraints.triangles.push_back({0, 1, 2});
      },
  };
  for (size_t i = 0; i < std::size(changes); ++i) {
    Dataset changed = base;
    changes[i](&changed);
    EXPECT_NE(DatasetFingerprint(changed), fingerprint) << "change " << i;
  }
  Dataset renamed = base;
  renamed.source = "elsewhere.csv";
  renamed.crs = "EPSG:4326";
  EXPECT_EQ(DatasetFingerprint(renamed), fingerprint);
}

}  // namespace
}  // namespace locator
