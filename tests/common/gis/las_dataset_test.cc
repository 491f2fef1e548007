// The LAS reader on files the independent test writer (las_writer.h) makes:
// every point format of LAS 1.2 and 1.4, scale and offset, the class and
// return filters, withheld points, the CRS from a WKT record (VLR or EVLR)
// and from GeoTIFF keys, .laz refused with how to decompress, and the
// bad-file table: truncated headers, counts beyond the file, wrong offsets,
// short records, unknown formats and bad (E)VLR lengths, each a precise
// error that names the file.

#include "common/gis/las/las_dataset.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "common/gis/crs_info.h"
#include "common/gis/las/las_dataset_spec.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/common/gis/las_writer.h"
#include "tests/core/scratch_dir.h"

namespace locator::gis::las {
namespace {

using ::testing::HasSubstr;
using testing::LasFileOptions;
using testing::LasPoint;
using testing::Patch;
using ::testing::StartsWith;

// Five points around (500000, 5500000): ground (2) with one withheld,
// vegetation (5) as a first of two returns, water (9).
std::vector<LasPoint> Tile() {
  return {
      {500000.25, 5500000.50, 101.25, 2, 1, 1, false},
      {500010.00, 5500000.00, 102.50, 2, 1, 1, false},
      {500000.00, 5500010.75, 103.00, 5, 1, 2, false},
      {500010.50, 5500010.00, 99.75, 9, 2, 2, false},
      {500005.00, 5500005.00, 150.00, 2, 1, 1, true},
  };
}

LasFileOptions Options(uint8_t minor, uint8_t format) {
  LasFileOptions o;
  o.minor_version = minor;
  o.point_format = format;
  o.offset = {500000, 5500000, 0};
  return o;
}

class LasDatasetTest : public ::testing::Test {
 protected:
  std::string Write(const std::string& name, const std::string& bytes) const {
    const std::string path = dir_.path() + "/" + name;
    testing::WriteFile(path, bytes);
    return path;
  }
  static Status LoadBytes(const std::string& bytes, Dataset* out,
                          const LasFilter& filter = LasFilter(),
                          size_t max_points = DatasetLimits().max_points) {
    DatasetLimits limits;
    limits.max_points = max_points;
    LasPointCounts counts;
    return LoadLasBytes(bytes, "tile.las", filter, limits, out, &counts);
  }

  test::ScratchDir dir_;
};

TEST_F(LasDatasetTest, EveryPointFormatKeepsScaledPointsAndDropsWithheld) {
  const std::vector<LasPoint> tile = Tile();
  for (uint8_t minor : {0, 1, 2, 3, 4}) {
    for (uint8_t format = 0; format <= 10; ++format) {
      if (format >= 6 && minor < 4) continue;
      if (format >= 4 && format <= 5 && minor < 3) continue;
      SCOPED_TRACE("LAS 1." + std::to_string(minor) + " format " +
                   std::to_string(format));
      Dataset ds;
      const Status status =
          LoadBytes(testing::LasBytes(tile, Options(minor, format)), &ds);
      ASSERT_TRUE(status.ok()) << status.ToString();
      ASSERT_EQ(ds.points.size(), 4u);
      ASSERT_EQ(ds.values.size(), 4u);
      for (size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(ds.points[i].x, tile[i].x, 1e-9);
        EXPECT_NEAR(ds.points[i].y, tile[i].y, 1e-9);
        EXPECT_NEAR(ds.values[i], tile[i].z, 1e-9);
      }
      EXPECT_TRUE(ds.crs.empty());
    }
  }
}

TEST_F(LasDatasetTest, ClassAndReturnFiltersKeepWhatTheyName) {
  for (uint8_t format : {1, 6}) {
    const std::string bytes =
        testing::LasBytes(Tile(), Options(format == 6 ? 4 : 2, format));
    const auto kept = [&](const std::string& spec) {
      const StatusOr<LasDatasetSpec> parsed =
          ParseLasDatasetSpec("t.las?" + spec);
      EXPECT_TRUE(parsed.ok()) << spec;
      Dataset ds;
      EXPECT_TRUE(
          LoadBytes(bytes, &ds, parsed.ok() ? parsed->filter : LasFilter())
              .ok())
          << spec;
      std::vector<double> z = ds.values;
      return z;
    };
    EXPECT_THAT(kept("classes=2"), ::testing::ElementsAre(101.25, 102.5));
    EXPECT_THAT(kept("classes=2,9"),
                ::testing::ElementsAre(101.25, 102.5, 99.75));
    EXPECT_THAT(kept("returns=first"),
                ::testing::ElementsAre(101.25, 102.5, 103));
    EXPECT_THAT(kept("returns=last"),
                ::testing::ElementsAre(101.25, 102.5, 99.75));
    EXPECT_THAT(kept("classes=5,9&returns=last"),
                ::testing::ElementsAre(99.75));
  }
}

TEST_F(LasDatasetTest, ExtraBytesPerRecordAreSkipped) {
  LasFileOptions o = Options(4, 6);
  o.record_length = 30 + 7;
  Dataset ds;
  ASSERT_TRUE(LoadBytes(testing::LasBytes(Tile(), o), &ds).ok());
  ASSERT_EQ(ds.values.size(), 4u);
  EXPECT_EQ(ds.values[3], 99.75);
}

TEST_F(LasDatasetTest, TheCrsComesFromTheWktRecordOrTheGeoTiffKeys) {
  const auto epsg = [](const Dataset& ds) {
    const StatusOr<CrsInfo> info = DescribeCrs(ds.crs);
    EXPECT_TRUE(info.ok()) << ds.crs;
    return info.ok() ? info->epsg_code : 0;
  };
  LasFileOptions wkt = Options(4, 6);
  wkt.wkt = testing::EpsgWkt2(32633);
  Dataset ds;
  ASSERT_TRUE(LoadBytes(testing::LasBytes(Tile(), wkt), &ds).ok());
  EXPECT_EQ(epsg(ds), 32633);
  wkt.wkt_in_evlr = true;
  ASSERT_TRUE(LoadBytes(testing::LasBytes(Tile(), wkt), &ds).ok());
  EXPECT_EQ(epsg(ds), 32633);

  LasFileOptions keys = Options(2, 1);
  keys.geo_keys = testing::ProjectedGeoKeys(32632);
  ASSERT_TRUE(LoadBytes(testing::LasBytes(Tile(), keys), &ds).ok());
  EXPECT_EQ(epsg(ds), 32632);
  // Geographic: GTModelType 2, GeographicTypeGeoKey (2048) 4326.
  keys.geo_keys = {1, 1, 0, 2, 1024, 0, 1, 2, 2048, 0, 1, 4326};
  ASSERT_TRUE(LoadBytes(testing::LasBytes(Tile(), keys), &ds).ok());
  EXPECT_EQ(epsg(ds), 4326);
  // A user-defined transverse Mercator on WGS 84, its parameters from the
  // doubles record: GTModelType (1024) projected, GeographicType (2048)
  // 4326, ProjectedCSType (3072) user-defined, ProjCoordTrans (3075) 1
  // (transverse Mercator), ProjLinearUnits (3076) metre, natural origin
  // longitude (3080), false easting (3082), scale (3092).
  keys.geo_keys = {1, 1,    0,     8,    1024, 0,    1,     1,     2048,
                   0, 1,    4326,  3072, 0,    1,    32767, 3075,  0,
                   1, 1,    3076,  0,    1,    9001, 3080,  34736, 1,
                   0, 3082, 34736, 1,    1,    3092, 34736, 1,     2};
  keys.geo_doubles = {15.0, 500000.0, 0.9996};
  ASSERT_TRUE(LoadBytes(testing::LasBytes(Tile(), keys), &ds).ok());
  EXPECT_THAT(ds.crs, HasSubstr("Transverse Mercator"));
  EXPECT_THAT(ds.crs, HasSubstr("WGS 84"));
}

TEST_F(LasDatasetTest, LoadsAFileBySpecWithItsSource) {
  LasFileOptions o = Options(2, 1);
  o.geo_keys = testing::ProjectedGeoKeys(32633);
  const std::string path = Write("tile.las", testing::LasBytes(Tile(), o));
  Dataset ds;
  LasPointCounts counts;
  const std::string spec = path + "?classes=2";
  ASSERT_TRUE(LoadLasDataset(spec, &ds, DatasetLimits(), &counts).ok());
  EXPECT_EQ(ds.source, spec);
  EXPECT_EQ(ds.points.size(), 2u);
  EXPECT_EQ(counts.records, 5u);
  EXPECT_EQ(counts.kept, 2u);
  EXPECT_EQ(counts.withheld, 1u);
  EXPECT_EQ(counts.per_class[2], 3u);
  ASSERT_TRUE(LoadLasDataset("las:" + path, &ds).ok());
  EXPECT_EQ(ds.points.size(), 4u);
}

TEST_F(LasDatasetTest, AlazFileIsRefusedWithHowToDecompressIt) {
  const std::string laz = Write("tile.laz", "anything");
  Dataset ds;
  Status status = LoadLasDataset(laz, &ds);
  EXPECT_EQ(status.code(), Status::Code::kFailedPrecondition);
  EXPECT_THAT(status.message(),
              HasSubstr(laz + ": a compressed LAS file (LAZ)"));
  EXPECT_THAT(status.message(), HasSubstr("laszip -i " + laz + " -o out.las"));
  EXPECT_THAT(status.message(), HasSubstr("pdal translate " + laz));
  // Compressed records in a file named .las: LASzip sets bit 7 of the
  // point format.
  std::string bytes = testing::LasBytes(Tile(), Options(2, 1));
  Patch<uint8_t>(&bytes, testing::kLasPointFormatAt, 0x81);
  status = LoadBytes(bytes, &ds);
  EXPECT_EQ(status.code(), Status::Code::kFailedPrecondition);
  EXPECT_THAT(status.message(), HasSubstr("tile.las: a compressed LAS file"));
}

struct BadFile {
  const char* name;
  uint8_t minor;
  uint8_t format;
  std::function<void(std::string*)> mutate;
  std::string message;
  LasFilter filter = LasFilter();
};

TEST_F(LasDatasetTest, BadFileTable) {
  using namespace testing;  // NOLINT: the patch offsets
  const std::vector<BadFile> rows = {
      {"truncated header", 2, 1, [](std::string* b) { b->resize(100); },
       "tile.las: truncated header: the file has 100 bytes, a LAS header at "
       "least 227"},
      {"truncated 1.4 header", 4, 6, [](std::string* b) { b->resize(300); },
       "tile.las: truncated header: the file has 300 bytes, a LAS 1.4 header "
       "375"},
      {"no signature", 2, 1, [](std::string* b) { (*b)[0] = 'X'; },
       "tile.las: not a LAS file (it does not start with \"LASF\")"},
      {"version 1.5", 2, 1, [](std::string* b) { (*b)[25] = 5; },
       "tile.las: LAS version 1.5 is not supported (1.0 to 1.4 are)"},
      {"header size below the version's", 2, 1,
       [](std::string* b) { Patch<uint16_t>(b, kLasHeaderSizeAt, 100); },
       "tile.las: header size 100 is not between the LAS 1.2 header's 227 "
       "bytes"},
      {"point data offset inside the header", 2, 1,
       [](std::string* b) { Patch<uint32_t>(b, kLasPointDataOffsetAt, 200); },
       "tile.las: offset to point data 200 lies inside the header (227 "
       "bytes)"},
      {"point data offset past the end", 2, 1,
       [](std::string* b) {
         Patch<uint32_t>(b, kLasPointDataOffsetAt, 1000000);
       },
       "tile.las: offset to point data 1000000 lies past the end of the file"},
      {"legacy count beyond the file", 2, 1,
       [](std::string* b) { Patch<uint32_t>(b, kLasLegacyCountAt, 1000); },
       "tile.las: 1000 points of 28 bytes from offset 286 need more than the "
       "140 bytes the file holds there"},
      {"64-bit count beyond the file", 4, 6,
       [](std::string* b) {
         Patch<uint64_t>(b, kLasPointCountAt, uint64_t{1} << 62);
       },
       "tile.las: 4611686018427387904 points of 30 bytes from offset 434 need "
       "more than the 150 bytes"},
      {"legacy count disagrees", 4, 1,
       [](std::string* b) { Patch<uint32_t>(b, kLasLegacyCountAt, 4); },
       "tile.las: the legacy point count 4 disagrees with the point count 5"},
      {"record too short for its format", 2, 1,
       [](std::string* b) { Patch<uint16_t>(b, kLasRecordLengthAt, 20); },
       "tile.las: point data record length 20 is too short for format 1, "
       "whose fields take 28 bytes"},
      {"unknown format", 4, 6,
       [](std::string* b) { Patch<uint8_t>(b, kLasPointFormatAt, 11); },
       "tile.las: point data record format 11 is unknown (LAS has formats 0 "
       "to 10)"},
      {"format 6 in LAS 1.2", 2, 1,
       [](std::string* b) {
         Patch<uint8_t>(b, kLasPointFormatAt, 6);
         Patch<uint16_t>(b, kLasRecordLengthAt, 30);
       },
       "tile.las: point data record format 6 needs LAS 1.4, but the file is "
       "LAS 1.2"},
      {"VLR longer than the room before the points", 2, 1,
       [](std::string* b) {
         Patch<uint16_t>(b, LasFirstVlrLengthAt(LasFileOptions()), 60000);
       },
       "tile.las: VLR 0 ('locator test', record 1) of 60000 bytes at offset "
       "281 runs past the point data offset 286"},
      {"more VLRs than fit", 2, 1,
       [](std::string* b) { Patch<uint32_t>(b, kLasVlrCountAt, 1000); },
       "tile.las: 1000 VLRs of at least 54 bytes each do not fit in the 59 "
       "bytes between the header and the point data"},
      {"EVLR inside the points", 4, 6,
       [](std::string* b) {
         Patch<uint64_t>(b, kLasEvlrStartAt, 400);
         Patch<uint32_t>(b, kLasEvlrCountAt, 1);
       },
       "tile.las: the first EVLR's offset 400 is not between the end of the "
       "point data (584) and the end of the file (584)"},
      {"EVLR past the end", 4, 6,
       [](std::string* b) {
         Patch<uint64_t>(b, kLasEvlrStartAt, b->size());
         Patch<uint32_t>(b, kLasEvlrCountAt, 1);
       },
       "tile.las: 1 EVLRs do not fit in the 0 bytes after offset 584"},
      {"zero scale", 2, 1,
       [](std::string* b) { Patch<double>(b, kLasScaleAt, 0.0); },
       "tile.las: X scale factor 0.000000 must be finite and not zero"},
      {"overflowing scale", 2, 1,
       [](std::string* b) { Patch<double>(b, kLasScaleAt + 8, 1e300); },
       "tile.las: Y scale factor and offset let coordinates overflow a "
       "double"},
      {"class beyond a legacy format", 2, 1, [](std::string*) {},
       "tile.las: class 40 cannot occur in point format 1, whose classes are "
       "0-31",
       [] {
         LasFilter f;
         f.classes.reset();
         f.classes.set(40);
         f.highest_class = 40;
         return f;
       }()},
      {"nothing passes the filter", 2, 1, [](std::string*) {},
       "tile.las: none of its 5 points passes the filters (1 withheld; it has "
       "class 2 (3 points), class 5 (1 points), class 9 (1 points))",
       [] {
         LasFilter f;
         f.classes.reset();
         f.classes.set(6);
         return f;
       }()},
  };
  for (const BadFile& row : rows) {
    SCOPED_TRACE(row.name);
    LasFileOptions o = Options(row.minor, row.format);
    o.user_vlr = "12345";
    std::string bytes = LasBytes(Tile(), o);
    row.mutate(&bytes);
    Dataset ds;
    const Status status = LoadBytes(bytes, &ds, row.filter);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument)
        << status.ToString();
    EXPECT_THAT(status.message(), StartsWith(row.message));
  }
  // An EVLR (the WKT record) whose 64-bit length runs past the end.
  LasFileOptions o = Options(4, 6);
  o.wkt = EpsgWkt2(32633);
  o.wkt_in_evlr = true;
  std::string bytes = LasBytes(Tile(), o);
  const size_t evlr_length_at = 375 + 150 + 20;
  Patch<uint64_t>(&bytes, evlr_length_at, uint64_t{1} << 40);
  Dataset ds;
  const Status status = LoadBytes(bytes, &ds);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(),
              StartsWith("tile.las: EVLR 0 ('LASF_Projection', record 2112) "
                         "of 1099511627776 bytes at offset 585 runs past the "
                         "end of the file"));
}

TEST_F(LasDatasetTest, BadCrsRecordsAreNamed) {
  LasFileOptions o = Options(4, 6);
  o.wkt = "NOT A CRS";
  Dataset ds;
  Status status = LoadBytes(LasBytes(Tile(), o), &ds);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(),
              StartsWith("tile.las: OGC WKT record (2112): unknown CRS "
                         "'NOT A CRS'"));

  o = Options(2, 1);
  // ProjectedCSType (3072) said to be 2 doubles at index 5 of none.
  o.geo_keys = {1, 1, 0, 1, 3072, 34736, 2, 5};
  status = LoadBytes(LasBytes(Tile(), o), &ds);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(),
              StartsWith("tile.las: GeoTIFF key directory (record 34735): key "
                         "3072 refers to 2 values at 5 of record 34736, which "
                         "has 0"));
  o.geo_keys = {1, 1, 0, 9, 1024, 0, 1, 1};
  status = LoadBytes(LasBytes(Tile(), o), &ds);
  EXPECT_THAT(status.message(),
              StartsWith("tile.las: GeoTIFF key directory (record 34735): 9 "
                         "keys need 40 values, it has 8"));
}

TEST_F(LasDatasetTest, EmptyFilesAndThePointLimit) {
  Dataset ds;
  Status status = LoadBytes(LasBytes({}, Options(2, 1)), &ds);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(status.message(), "tile.las: no point records");
  status = LoadBytes(LasBytes(Tile(), Options(2, 1)), &ds, LasFilter(), 3);
  EXPECT_EQ(status.code(), Status::Code::kResourceExhausted);
  EXPECT_EQ(status.message(),
            "tile.las: more than 3 points pass the filters (max_points "
            "limit)");
  status = LoadLasDataset(dir_.path() + "/missing.las", &ds);
  EXPECT_EQ(status.code(), Status::Code::kNotFound);
  EXPECT_THAT(status.message(), StartsWith(dir_.path() + "/missing.las: "));
}

// The committed fuzz seeds (tests/fuzz/corpus/las_fuzzer/) are the files
// the writer makes now. With LOCATOR_WRITE_FUZZ_SEEDS=1 in the environment
// this test writes them afresh (after a change of the writer).
TEST(LasFuzzSeedsTest, CommittedFuzzSeedsAreCurrentFiles) {
  LasFileOptions keys = Options(2, 1);
  keys.geo_keys = testing::ProjectedGeoKeys(32633);
  LasFileOptions evlr = Options(4, 6);
  evlr.wkt = "EPSG:4326";
  evlr.wkt_in_evlr = true;
  LasFileOptions extra = Options(4, 10);
  extra.record_length = 70;
  extra.wkt = "EPSG:32633";
  extra.user_vlr = "user data";
  LasFileOptions waves = Options(3, 5);
  waves.geo_keys = {1, 1, 0, 2, 1024, 0, 1, 2, 2048, 0, 1, 4326};
  const std::pair<std::string, std::string> seeds[] = {
      {"las10_format0.las", testing::LasBytes(Tile(), Options(0, 0))},
      {"las12_format1_geokeys.las", testing::LasBytes(Tile(), keys)},
      {"las13_format5_geographic.las", testing::LasBytes(Tile(), waves)},
      {"las14_format6_wkt_evlr.las", testing::LasBytes(Tile(), evlr)},
      {"las14_format10_extra_bytes.las", testing::LasBytes(Tile(), extra)},
  };
  for (const auto& [name, bytes] : seeds) {
    const std::string path = std::string(LOCATOR_LAS_CORPUS) + "/" + name;
    if (std::getenv("LOCATOR_WRITE_FUZZ_SEEDS") != nullptr) {
      testing::WriteFile(path, bytes);
    }
    std::ifstream in(path, std::ios::binary);
    const std::string committed((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
    EXPECT_EQ(committed, bytes) << name;
    Dataset ds;
    LasPointCounts counts;
    EXPECT_TRUE(
        LoadLasBytes(bytes, name, LasFilter(), DatasetLimits(), &ds, &counts)
            .ok())
        << name;
  }
}

TEST(LasDatasetSpecTest, ParsesItsOptionsAndNamesBadOnes) {
  EXPECT_TRUE(IsLasDatasetSpec("tile.las"));
  EXPECT_TRUE(IsLasDatasetSpec("TILE.LAZ?classes=2"));
  EXPECT_TRUE(IsLasDatasetSpec("las:cloud.bin"));
  EXPECT_FALSE(IsLasDatasetSpec("tile.csv"));
  const StatusOr<LasDatasetSpec> parsed =
      ParseLasDatasetSpec("a.las?classes=2,9&returns=last");
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  const LasDatasetSpec& spec = *parsed;
  EXPECT_EQ(spec.path, "a.las");
  EXPECT_TRUE(spec.filter.classes.test(2));
  EXPECT_TRUE(spec.filter.classes.test(9));
  EXPECT_EQ(spec.filter.classes.count(), 2u);
  EXPECT_EQ(spec.filter.returns, LasReturns::kLast);
  const struct {
    const char* spec;
    const char* message;
  } kBad[] = {
      {"a.las?classes=2,x",
       "option 'classes' must be a comma-separated list "
       "of classes 0-255 (e.g. 2,9), got '2,x'"},
      {"a.las?classes=256", "got '256'"},
      {"a.las?classes=", "got ''"},
      {"a.las?returns=second", "option 'returns' must be all, first or last"},
      {"a.las?classes=2&classes=3", "option 'classes' given twice"},
      {"a.las?colour=red",
       "unknown option 'colour' (known: classes, returns, "
       "max_error, max_points)"},
      {"las:?classes=2", "no path before the options"},
  };
  for (const auto& c : kBad) {
    const Status status = ParseLasDatasetSpec(c.spec).status();
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << c.spec;
    EXPECT_THAT(status.message(), HasSubstr(c.message)) << c.spec;
    EXPECT_THAT(status.message(), HasSubstr(c.spec)) << c.spec;
  }
}

}  // namespace
}  // namespace locator::gis::las
