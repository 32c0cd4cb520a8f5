// Height rasters as GeoTIFF, written by GDAL (Debian's libgdal-dev): one Float32 band of
// heights in metres, north row first, with its CRS (WKT) and the grid's place in it, cells
// without data set to the band's nodata value. GDAL encodes the file in memory (/vsimem/) and
// writeFileAtomically puts it in place: a failure keeps the previous file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sonarcarve {

struct HeightRaster {
  double west_m = 0.0;        ///< x of the grid's west edge (easting, or local east)
  double north_m = 0.0;       ///< y of the grid's north edge (northing, or local north)
  double cell_m = 1.0;        ///< square cells
  int width = 0;              ///< columns, west to east
  int height = 0;             ///< rows, north to south
  std::vector<float> values;  ///< row-major, north row first; NaN: no data
  std::string crs_wkt;        ///< empty: no CRS (local metres)
  std::string description;    ///< the band's description (what the heights are)
};

/// The nodata value written in place of NaN (GDAL's and most GIS tools' usual choice).
inline constexpr float kGeoTiffNoData = -9999.0f;

/// The GeoTIFF's bytes (DEFLATE-compressed, AREA_OR_POINT=Area). Throws Error(`target`, ...)
/// on an empty raster, a value count that is not width x height, or a failure of GDAL's.
std::string geotiffBytes(const HeightRaster& raster, const std::string& target);

/// geotiffBytes written through writeFileAtomically.
void writeGeoTiff(const std::filesystem::path& path, const HeightRaster& raster);

}  // namespace sonarcarve
