#include "geo/crs_transform.h"

#include <cmath>

#include "common/error.h"
#include "geo/internal/proj_handles.h"

namespace sonarcarve {

struct CrsTransform::Handles {
  proj::Context context = proj::quietContext();  // first: destroyed after the transform
  proj::Object transform;
};

CrsTransform::CrsTransform(const std::string& from_crs, const std::string& to_crs,
                           const std::string& source, const std::string& place)
    : handles_(std::make_unique<Handles>()) {
  PJ_CONTEXT* context = handles_->context.get();
  for (const std::string* crs : {&from_crs, &to_crs}) {
    const proj::Object object(proj_create(context, crs->c_str()));
    if (!object || !proj_is_crs(object.get())) {
      throw Error(source, place,
                  "'" + *crs + "' is not a CRS PROJ knows (" + proj::lastError(context) +
                      "): expected an authority code such as EPSG:32631, a PROJ string or WKT");
    }
  }
  const proj::Object raw(
      proj_create_crs_to_crs(context, from_crs.c_str(), to_crs.c_str(), nullptr));
  if (raw) {
    handles_->transform.reset(proj_normalize_for_visualization(context, raw.get()));
  }
  if (!handles_->transform) {
    throw Error(source, place,
                "PROJ finds no transformation from '" + from_crs + "' to '" + to_crs + "' (" +
                    proj::lastError(context) + "): expected two CRSs of the same body");
  }
}

CrsTransform::~CrsTransform() = default;
CrsTransform::CrsTransform(CrsTransform&&) noexcept = default;
CrsTransform& CrsTransform::operator=(CrsTransform&&) noexcept = default;

std::optional<Eigen::Vector3d> CrsTransform::apply(const Eigen::Vector3d& xyz) const {
  PJ* transform = handles_->transform.get();
  proj_errno_reset(transform);
  const PJ_COORD out =
      proj_trans(transform, PJ_FWD, proj_coord(xyz.x(), xyz.y(), xyz.z(), HUGE_VAL));
  const Eigen::Vector3d result(out.xyz.x, out.xyz.y, out.xyz.z);
  if (proj_errno(transform) != 0 || !result.allFinite()) {
    return std::nullopt;
  }
  return result;
}

std::string CrsTransform::lastError() const {
  const int code = proj_errno(handles_->transform.get());
  if (code == 0) {
    return "a coordinate outside the CRS's domain";
  }
  return proj_context_errno_string(handles_->context.get(), code);
}

}  // namespace sonarcarve
