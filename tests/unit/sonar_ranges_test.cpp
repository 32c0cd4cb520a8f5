// The physical ranges of a sonar's declared geometry (sonar/sonar_ranges.h), as the readers of
// recordings apply them: each quantity named by the recording's own field.
#include <gtest/gtest.h>

#include <limits>

#include "sonar/sonar_ranges.h"

namespace sonarcarve {
namespace {

// An Oculus M750d at 30 m: 512 beams over 130 degrees, 1024 bins of 3 cm, 20 degrees high.
RecordedGeometry usualSonar() {
  return {.near_range_m = {"near", 0.0},
          .range_resolution_m = {"resolution", 0.03},
          .bins = 1024,
          .field_of_view_deg = {"fov", 130.0},
          .vertical_aperture_deg = {"aperture", 20.0}};
}

TEST(SonarRanges, AUsualSonarIsWithinEveryRange) {
  EXPECT_EQ(recordedGeometryProblem(usualSonar()), std::nullopt);
}

TEST(SonarRanges, EachQuantityOutsideItsRangeIsNamedByItsField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const struct {
    RecordedQuantity RecordedGeometry::*quantity;
    double value;
    std::string expected;
  } cases[] = {
      {&RecordedGeometry::range_resolution_m, 1e-300,
       "resolution: expected 1e-04 to 10 m, got 1e-300"},
      {&RecordedGeometry::range_resolution_m, nan, "resolution: expected 1e-04 to 10 m, got nan"},
      {&RecordedGeometry::near_range_m, -1.0, "near: expected 0 to 1000 m, got -1"},
      {&RecordedGeometry::field_of_view_deg, 0.0,
       "fov: expected 0.1 to 360 (excluded) degrees, got 0"},
      {&RecordedGeometry::field_of_view_deg, 400.0,
       "fov: expected 0.1 to 360 (excluded) degrees, got 400"},
      {&RecordedGeometry::vertical_aperture_deg, 1e-300,
       "aperture: expected 0.1 to 180 (excluded) degrees, got 1e-300"},
  };
  for (const auto& c : cases) {
    RecordedGeometry g = usualSonar();
    (g.*c.quantity).value = c.value;
    EXPECT_EQ(recordedGeometryProblem(g), c.expected);
  }
}

TEST(SonarRanges, TheFarthestRangeIsBoundedAndAFieldNotRecordedIsNotChecked) {
  RecordedGeometry g = usualSonar();
  g.near_range_m.value = 900.0;
  g.range_resolution_m.value = 9.0;  // 1024 bins reach 10.1 km
  EXPECT_EQ(recordedGeometryProblem(g),
            "resolution: the farthest range is 10116 m (1024 bins from 900 m): expected at most "
            "10000 m");
  g = usualSonar();
  g.vertical_aperture_deg = {};  // not in the recording: given or assumed by its reader
  EXPECT_EQ(recordedGeometryProblem(g), std::nullopt);
  EXPECT_EQ(outsideRange(1500.0, kSoundSpeed), std::nullopt);
  EXPECT_EQ(outsideRange(0.0, kSoundSpeed), "expected 1000 to 2000 m/s, got 0");
}

}  // namespace
}  // namespace sonarcarve
