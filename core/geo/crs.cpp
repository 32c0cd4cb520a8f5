#include "geo/crs.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "geo/internal/proj_handles.h"

namespace sonarcarve {
namespace {

const char* kExpected = "expected a projected CRS in metres, e.g. EPSG:32631 (WGS 84 / UTM 31N)";

// Both axes of a projected CRS's coordinate system in metres.
bool axesInMetres(PJ_CONTEXT* context, const PJ* crs) {
  const proj::Object cs(proj_crs_get_coordinate_system(context, crs));
  if (!cs) {
    return false;
  }
  const int axes = proj_cs_get_axis_count(context, cs.get());
  for (int i = 0; i < axes; ++i) {
    double to_metres = 0.0;
    if (!proj_cs_get_axis_info(context, cs.get(), i, nullptr, nullptr, nullptr, &to_metres, nullptr,
                               nullptr, nullptr) ||
        to_metres != 1.0) {
      return false;
    }
  }
  return axes == 2;
}

}  // namespace

std::optional<std::string> gridCrsProblem(const std::string& definition) {
  if (definition.empty()) {
    return std::string("empty: ") + kExpected;
  }
  const proj::Context context = proj::quietContext();
  const proj::Object crs(proj_create(context.get(), definition.c_str()));
  if (!crs || !proj_is_crs(crs.get())) {
    return "'" + definition + "' is not a CRS PROJ knows (" + proj::lastError(context.get()) +
           "): " + kExpected;
  }
  if (proj_get_type(crs.get()) != PJ_TYPE_PROJECTED_CRS) {
    return "'" + definition + "' (" + proj_get_name(crs.get()) +
           ") is not a projected CRS: " + kExpected;
  }
  if (!axesInMetres(context.get(), crs.get())) {
    return "'" + definition + "' (" + proj_get_name(crs.get()) +
           ") does not have two axes in metres: " + kExpected;
  }
  return std::nullopt;
}

void requireGridCrs(const std::string& definition, const std::string& file,
                    const std::string& field) {
  if (const auto problem = gridCrsProblem(definition)) {
    throw Error(file, field, *problem);
  }
}

std::string crsName(const std::string& definition) {
  const proj::Context context = proj::quietContext();
  const proj::Object crs(proj_create(context.get(), definition.c_str()));
  const char* name = crs ? proj_get_name(crs.get()) : nullptr;
  return name != nullptr && *name != '\0' ? std::string(name) : definition;
}

std::string crsWkt(const std::string& definition, const std::string& file,
                   const std::string& field) {
  const proj::Context context = proj::quietContext();
  const proj::Object crs(proj_create(context.get(), definition.c_str()));
  if (!crs || !proj_is_crs(crs.get())) {
    throw Error(file, field,
                "'" + definition + "' is not a CRS PROJ knows (" + proj::lastError(context.get()) +
                    "): expected an EPSG code, a PROJ string or WKT");
  }
  const char* options[] = {"MULTILINE=NO", nullptr};
  const char* wkt = proj_as_wkt(context.get(), crs.get(), PJ_WKT1_GDAL, options);
  if (wkt == nullptr) {
    wkt = proj_as_wkt(context.get(), crs.get(), PJ_WKT2_2019, options);
  }
  if (wkt == nullptr) {
    throw Error(file, field,
                "PROJ cannot write '" + definition + "' as WKT (" + proj::lastError(context.get()) +
                    "): expected a CRS with a WKT form");
  }
  return wkt;
}

std::string utmZoneCrs(double latitude_deg, double longitude_deg) {
  const int zone =
      std::clamp(static_cast<int>(std::floor((longitude_deg + 180.0) / 6.0)) + 1, 1, 60);
  const int code = (latitude_deg >= 0.0 ? 32600 : 32700) + zone;
  return "EPSG:" + std::to_string(code);
}

std::string crsComment(const std::string& crs) {
  std::string text = std::string(kCrsCommentKeyword) + " " + crs;
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

}  // namespace sonarcarve
