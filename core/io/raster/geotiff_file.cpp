#include "io/raster/geotiff_file.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>

#include "common/error.h"
#include "io/files/atomic_file.h"

namespace sonarcarve {
namespace {

struct DatasetCloser {
  void operator()(void* dataset) const noexcept { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

// GDAL's last error in words, or a fallback.
std::string gdalError(const char* what) {
  const char* message = CPLGetLastErrorMsg();
  return std::string(what) + " (" +
         (message != nullptr && *message != '\0' ? message : "no reason given") + ")";
}

// A /vsimem/ name of its own for each encoding, so that threads never share one.
std::string memoryName() {
  static std::atomic<unsigned long> next{0};
  return "/vsimem/sonarcarve-" + std::to_string(next++) + ".tif";
}

void check(bool ok, const std::string& target, const char* what) {
  if (!ok) {
    throw Error(target, "geotiff", gdalError(what) + ": expected GDAL to write the raster");
  }
}

void fill(void* dataset, const HeightRaster& r, const std::string& target) {
  double transform[6] = {r.west_m, r.cell_m, 0.0, r.north_m, 0.0, -r.cell_m};
  check(GDALSetGeoTransform(dataset, transform) == CE_None, target, "the grid's place");
  if (!r.crs_wkt.empty()) {
    check(GDALSetProjection(dataset, r.crs_wkt.c_str()) == CE_None, target, "the CRS");
  }
  check(GDALSetMetadataItem(dataset, "AREA_OR_POINT", "Area", nullptr) == CE_None, target,
        "the cells' meaning");
  GDALRasterBandH band = GDALGetRasterBand(dataset, 1);
  check(GDALSetRasterNoDataValue(band, kGeoTiffNoData) == CE_None, target, "the nodata value");
  GDALSetDescription(band, r.description.c_str());
  check(GDALSetRasterUnitType(band, "m") == CE_None, target, "the unit");
  std::vector<float> values = r.values;
  for (float& v : values) {
    v = std::isnan(v) ? kGeoTiffNoData : v;
  }
  check(GDALRasterIO(band, GF_Write, 0, 0, r.width, r.height, values.data(), r.width, r.height,
                     GDT_Float32, 0, 0) == CE_None,
        target, "the heights");
}

}  // namespace

std::string geotiffBytes(const HeightRaster& raster, const std::string& target) {
  if (raster.width <= 0 || raster.height <= 0) {
    throw Error(target, "geotiff", "no cell holds data: expected points to grid");
  }
  if (raster.values.size() != static_cast<std::size_t>(raster.width) * raster.height ||
      !(raster.cell_m > 0.0)) {
    throw Error(target, "geotiff", "expected width x height values and a positive cell");
  }
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  check(driver != nullptr, target, "GDAL's GTiff driver");
  const std::string name = memoryName();
  const char* options[] = {"COMPRESS=DEFLATE", "PREDICTOR=3", nullptr};
  CPLErrorReset();
  try {
    Dataset dataset(GDALCreate(driver, name.c_str(), raster.width, raster.height, 1, GDT_Float32,
                               const_cast<char**>(options)));
    check(dataset != nullptr, target, "a GeoTIFF in memory");
    fill(dataset.get(), raster, target);
  } catch (...) {  // closed above; its memory file goes too
    VSIUnlink(name.c_str());
    throw;
  }  // closed: GDAL has written every byte
  vsi_l_offset size = 0;
  GByte* data = VSIGetMemFileBuffer(name.c_str(), &size, TRUE);
  check(data != nullptr, target, "the GeoTIFF's bytes");
  std::string bytes(reinterpret_cast<const char*>(data), static_cast<std::size_t>(size));
  CPLFree(data);
  return bytes;
}

void writeGeoTiff(const std::filesystem::path& path, const HeightRaster& raster) {
  writeFileAtomically(path, geotiffBytes(raster, path.string()));
}

}  // namespace sonarcarve
