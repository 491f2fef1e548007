// What a raster dataset spec that comes in a request (a Reload's) may make
// GDAL do: read the file the spec names, and nothing else. The operator's
// own specs (--dataset) are not checked here; they may use all of GDAL.
//
//   - The source is read by one of a few drivers (GTiff, AAIGrid, EHdr,
//     SRTMHGT, USGSDEM and Surfer's GSAG, GSBG and GS7BG): formats whose
//     reader opens the named file and its own side-cars (.aux.xml, .ovr,
//     .msk, .prj, a world file, an .hdr), but no other file its content
//     could name (a VRT's sources, an ERDAS .img's spill files) and no
//     network. The driver is driver= when given, else the one of these GDAL
//     identifies the file as.
//   - a_srs= passes the request CRS policy (CheckRequestCrs): no file
//     outside PROJ's data directories.
//   - band= only picks a band of the file.
//
// Thread-safety: free functions; may run on any thread.

#ifndef LOCATOR_COMMON_GIS_UNTRUSTED_RASTER_SPEC_H_
#define LOCATOR_COMMON_GIS_UNTRUSTED_RASTER_SPEC_H_

#include <string>

#include "common/gis/raster_dataset_spec.h"
#include "locator/status.h"

namespace locator::gis {

// OK when a request may use every option of `spec`; else InvalidArgument
// naming the first option it may not use and why.
Status CheckUntrustedRasterOptions(const RasterDatasetSpec& spec);

// The driver that is to read `path` (the spec's source, resolved) for a
// request's `spec`: spec.driver when it is one of the drivers above, else
// the one GDAL identifies `path` as. InvalidArgument naming the drivers when
// there is none.
Status UntrustedRasterDriver(const RasterDatasetSpec& spec,
                             const std::string& path, std::string* driver);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_UNTRUSTED_RASTER_SPEC_H_
