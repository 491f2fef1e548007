#include "server/bench/suites/grid_benchmark.h"

#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <span>
#include <sstream>
#include <thread>
#include <vector>

#include "common/gis/gdal_support.h"
#include "common/gis/raster_writer.h"
#include "common/status_macros.h"
#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "server/bench/datasets/surface_terrain.h"
#include "server/bench/stopwatch.h"

namespace locator::bench {
namespace {

constexpr double kNodata = -9999;

// Writes the CSV and the VRT; *z_range is the range of the heights.
Status WriteInputs(const GridBenchOptions& options, const std::string& csv,
                   const std::string& vrt, double* z_range) {
  std::ofstream out(csv);
  out << "x,y,z\n" << std::setprecision(17);
  double low = INFINITY, high = -INFINITY;
  for (const Point2& p : TerrainPoints(options.points, 42)) {
    const double z = TerrainHeight(p);
    low = std::min(low, z);
    high = std::max(high, z);
    out << p.x << ',' << p.y << ',' << z << '\n';
  }
  *z_range = high - low;
  std::ofstream(vrt)
      << "<OGRVRTDataSource>\n  <OGRVRTLayer name=\"points\">\n"
      << "    <SrcDataSource>" << csv << "</SrcDataSource>\n"
      << "    <SrcLayer>points</SrcLayer>\n"
      << "    <GeometryType>wkbPoint25D</GeometryType>\n"
      << "    <GeometryField encoding=\"PointFromColumns\" x=\"x\" y=\"y\" "
         "z=\"z\"/>\n  </OGRVRTLayer>\n</OGRVRTDataSource>\n";
  if (!out || !std::filesystem::exists(vrt)) {
    return Status::IOError("cannot write the inputs in " + options.work_dir);
  }
  return Status::OK();
}

RasterSpec SpecFor(const GridBenchOptions& options) {
  return RasterSpec{.box = TerrainBox(),
                    .width = options.size,
                    .height = options.size,
                    .nodata = kNodata};
}

// Renders every row of `spec` on `threads` threads into `cells`.
Status RenderAll(const Engine& engine, const RasterSpec& spec, unsigned threads,
                 std::vector<double>* cells) {
  cells->assign(spec.cells(), 0);
  std::vector<Status> results(threads);
  std::vector<std::thread> workers;
  // Interleaved blocks of 16 rows balance the threads over the hull's ends.
  constexpr uint32_t kBlock = 16;
  for (unsigned t = 0; t < threads; ++t) {
    workers.emplace_back([&, t] {
      for (uint32_t first = t * kBlock; first < spec.height;
           first += threads * kBlock) {
        const uint32_t rows = std::min(kBlock, spec.height - first);
        results[t] = engine.RenderRows(
            spec, first, rows, cells->data() + size_t{first} * spec.width);
        if (!results[t].ok()) return;
      }
    });
  }
  for (std::thread& w : workers) w.join();
  for (const Status& s : results) {
    if (!s.ok()) return s;
  }
  return Status::OK();
}

Status WriteGeoTiff(const RasterSpec& spec, const std::vector<double>& cells,
                    const std::string& path) {
  std::unique_ptr<gis::RasterWriter> writer;
  const gis::RasterShape shape{.width = spec.width,
                               .height = spec.height,
                               .box = spec.box,
                               .cell_width = spec.cell_width(),
                               .cell_height = spec.cell_height(),
                               .nodata = spec.nodata,
                               .crs_wkt = ""};
  RETURN_IF_ERROR(
      gis::RasterWriter::Open(path, shape, {.driver = "GTiff"}, &writer));
  RETURN_IF_ERROR(writer->WriteRows(0, spec.height, cells));
  return writer->Close();
}

// Locator end to end: CSV -> engine -> raster -> GeoTIFF.
Status LocatorEndToEnd(const GridBenchOptions& options, const std::string& csv,
                       const std::string& tif, std::unique_ptr<Engine>* engine,
                       std::vector<double>* cells) {
  ASSIGN_OR_RETURN(Dataset dataset, LoadDataset(csv));
  // A one-shot job needs no learned start table: Jump&Walk starts each
  // block's first walk, scanline coherence every other.
  EngineOptions engine_options;
  engine_options.strategy = "jump-and-walk";
  ASSIGN_OR_RETURN(*engine, Engine::Create(std::move(dataset), engine_options));
  const RasterSpec spec = SpecFor(options);
  RETURN_IF_ERROR(RenderAll(**engine, spec, options.threads, cells));
  return WriteGeoTiff(spec, *cells, tif);
}

Status RunGdalGrid(const GridBenchOptions& options, const std::string& vrt,
                   const std::string& tif) {
  const BoundingBox box = TerrainBox();
  std::ostringstream command;
  command << std::setprecision(17)
          << "gdal_grid -q -a linear:radius=0:nodata=" << kNodata
          << " -l points -txe " << box.min_x << ' ' << box.max_x << " -tye "
          << box.max_y << ' ' << box.min_y << " -outsize " << options.size
          << ' ' << options.size
          << " -ot Float64 -of GTiff -co TILED=YES --config GDAL_NUM_THREADS "
          << options.threads << " '" << vrt << "' '" << tif << "'";
  std::filesystem::remove(tif);
  if (std::system(command.str().c_str()) != 0) {
    return Status::Internal("failed: " + command.str());
  }
  return Status::OK();
}

struct Comparison {
  double max_abs_difference = 0;
  uint64_t both = 0, only_locator = 0, only_gdal = 0;
};

// Compares `cells` with the raster gdal_grid wrote, cell by cell, mapping
// its rows by its own geotransform (north-up or south-up).
Status Compare(const RasterSpec& spec, const std::vector<double>& cells,
               const std::string& gdal_tif, Comparison* out) {
  gis::RegisterGdalDrivers();
  std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(gdal_tif.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (ds == nullptr) return Status::IOError("cannot open " + gdal_tif);
  double gt[6];
  ds->GetGeoTransform(gt);
  std::vector<double> row(spec.width);
  GDALRasterBand* band = ds->GetRasterBand(1);
  for (uint32_t r = 0; r < spec.height; ++r) {
    if (band->RasterIO(GF_Read, 0, static_cast<int>(r),
                       static_cast<int>(spec.width), 1, row.data(),
                       static_cast<int>(spec.width), 1, GDT_Float64, 0,
                       0) != CE_None) {
      return Status::IOError("cannot read " + gdal_tif);
    }
    const double y = gt[3] + (r + 0.5) * gt[5];
    const auto ours = static_cast<uint32_t>(
        std::floor((spec.box.max_y - y) / spec.cell_height()));
    for (uint32_t c = 0; c < spec.width; ++c) {
      const double mine = cells[size_t{ours} * spec.width + c];
      const bool have_mine = mine != kNodata, have_gdal = row[c] != kNodata;
      if (have_mine && have_gdal) {
        ++out->both;
        out->max_abs_difference =
            std::max(out->max_abs_difference, std::abs(mine - row[c]));
      } else if (have_mine) {
        ++out->only_locator;
      } else if (have_gdal) {
        ++out->only_gdal;
      }
    }
  }
  return Status::OK();
}

}  // namespace

Status RunGridBenchmark(const GridBenchOptions& options, std::ostream& out) {
  std::filesystem::create_directories(options.work_dir);
  const std::string dir = options.work_dir + "/";
  const std::string csv = dir + "points.csv", vrt = dir + "points.vrt";
  const std::string ours = dir + "locator.tif", theirs = dir + "gdal_grid.tif";
  double z_range = 0;
  RETURN_IF_ERROR(WriteInputs(options, csv, vrt, &z_range));
  out << "grid benchmark: " << options.points << " points, " << options.size
      << " x " << options.size << " cells, " << options.threads
      << " threads, inputs in " << options.work_dir << "\n"
      << std::fixed << std::setprecision(3);
  std::unique_ptr<Engine> engine;
  std::vector<double> cells;
  std::vector<double> locator_s, gdal_s;
  for (int i = 0; i < options.repeats; ++i) {
    Stopwatch watch;
    engine.reset();
    RETURN_IF_ERROR(LocatorEndToEnd(options, csv, ours, &engine, &cells));
    locator_s.push_back(watch.Seconds());
    watch.Restart();
    RETURN_IF_ERROR(RunGdalGrid(options, vrt, theirs));
    gdal_s.push_back(watch.Seconds());
    out << "run " << i + 1 << ": locator end to end " << locator_s.back()
        << " s (build " << engine->dataset_info().build_seconds
        << " s), gdal_grid -a linear " << gdal_s.back() << " s, ratio "
        << gdal_s.back() / locator_s.back() << "\n";
  }
  const RasterSpec spec = SpecFor(options);
  std::vector<double> again;
  const Stopwatch render_watch;
  RETURN_IF_ERROR(RenderAll(*engine, spec, options.threads, &again));
  const double render_s = render_watch.Seconds();
  out << "locator render only (engine built): " << render_s << " s, "
      << spec.cells() / render_s / 1e6 << " M cells/s\n";
  Comparison c;
  RETURN_IF_ERROR(Compare(spec, cells, theirs, &c));
  out << std::scientific << std::setprecision(3) << "rasters: " << c.both
      << " cells valued in both; max |difference| " << c.max_abs_difference
      << " (" << c.max_abs_difference / z_range << " of the z range " << z_range
      << "); " << c.only_locator << " valued by locator only, " << c.only_gdal
      << " by gdal_grid only\n";
  return Status::OK();
}

}  // namespace locator::bench
