#include "sim/demo_scenes.h"

#include <cmath>
#include <numbers>

#include "common/error.h"
#include "sim/scene_seabed.h"
#include "sim/scene_shapes.h"
#include "sim/seabed_field.h"

namespace sonarcarve {
namespace {

Scene riser(const SeabedReliefSpec& relief) {
  Scene scene;
  scene.name = "riser";
  const SceneSeabed seabed(20.0, 0.0, relief, {0, 0}, 1.0);
  scene.append(seabed.mesh(30.0, 1, 0.35f));
  scene.append(tubeShape({0, 0, 9.5}, {0, 0, 20.0}, 0.2, 48, 0.8f));
  for (double top : {10.4, 11.5, 12.6}) {
    scene.append(tubeShape({0, 0, top}, {0, 0, top + 0.8}, 0.45, 64, 0.9f));
  }
  // Tie-back cables from the riser at 14.5 m down to the seabed, towards the south-east and
  // south-west, so the inspecting vehicle (south of the riser) sees them at both sides.
  for (double east : {5.2, -5.2}) {
    scene.append(tubeShape({0, 0, 14.5}, {-3.0, east, seabed.downAt(-3.0, east)}, 0.05, 16, 0.6f));
  }
  scene.target = {Eigen::Vector3d(0, 0, 15.0), 9.5, 20.0, 20.0};
  return scene;
}

// With a relief, the leg stands on a seabed at 20 m (without, it has none).
Scene jacketNode(const SeabedReliefSpec& relief) {
  Scene scene;
  scene.name = "jacket-node";
  if (relief.relief_m > 0.0) {
    scene.append(SceneSeabed(20.0, 0.0, relief, {0, 0}, 1.0).mesh(30.0, 1, 0.35f));
  }
  scene.append(tubeShape({0, 0, 10.0}, {0, 0, 20.0}, 0.4, 48, 0.8f));
  scene.append(tubeShape({0, 0, 14.2}, {0, 0, 15.8}, 0.55, 48, 0.85f));
  const Eigen::Vector3d node(0, 0, 15.0);
  scene.append(tubeShape(node, {0, 5.0, 15.0}, 0.22, 32, 0.8f));     // horizontal, east
  scene.append(tubeShape(node, {0, -4.0, 11.5}, 0.22, 32, 0.8f));    // up to the west
  scene.append(tubeShape(node, {0, 3.5, 19.0}, 0.22, 32, 0.8f));     // down to the east
  scene.append(tubeShape(node, {3.0, -3.0, 16.5}, 0.22, 32, 0.8f));  // away, north-west
  scene.target = {Eigen::Vector3d(0, 0, 15.0), 10.0, 20.0, relief.relief_m > 0.0 ? 20.0 : 0.0};
  return scene;
}

// Each object rests on the seabed at its centre (with a relief, partly sunk where it rises).
Scene seabedObjects(const SeabedReliefSpec& relief) {
  Scene scene;
  scene.name = "seabed-objects";
  const SceneSeabed seabed(20.0, 3.0, relief);
  scene.append(seabed.mesh(24.0, 48, 0.3f));
  scene.append(boxShape({-2.0, -1.5, seabed.downAt(-2.0, -1.5) - 0.3}, {1.2, 0.8, 0.6}, 0.0, 0.9f));
  scene.append(boxShape({1.5, 2.0, seabed.downAt(1.5, 2.0) - 0.4}, {0.8, 0.8, 0.8}, 30.0, 0.9f));
  const double pipe = seabed.downAt(2.0, -2.0) - 0.3;
  scene.append(tubeShape({2.0, -3.0, pipe}, {2.0, -1.0, pipe}, 0.3, 32, 0.8f));
  scene.append(sphereShape({-1.5, 2.5, seabed.downAt(-1.5, 2.5) - 0.5}, 0.5, 0.85f));
  scene.target = {Eigen::Vector3d(0, 0, 20.0), 19.0, 20.0, 20.0};
  return scene;
}

// A subsea production template: a manifold on a mud mat, on a flat seabed at 20 m. Large faces
// that look up (the mat, the manifold's roof, the valve decks) beside pipes: a header along the
// roof, valve stems and hand wheels, flowline spools along the seabed and a jumper arching over
// it to the east.
// With a relief, the seabed is levelled under the mud mat; the spools and the jumper end on it.
Scene manifold(const SeabedReliefSpec& relief) {
  Scene scene;
  scene.name = "manifold";
  const double floor = 20.0;
  const SceneSeabed seabed(floor, 0.0, relief, {0, 0}, 2.5);
  scene.append(seabed.mesh(24.0, 48, 0.3f));
  scene.append(boxShape({0, 0, floor - 0.05}, {3.6, 2.8, 0.1}, 0.0, 0.6f));     // mud mat
  scene.append(boxShape({0, 0, floor - 0.6}, {2.4, 1.6, 1.0}, 0.0, 0.9f));      // manifold body
  scene.append(boxShape({0.9, 0, floor - 1.15}, {0.6, 1.2, 0.1}, 0.0, 0.85f));  // valve deck
  scene.append(
      tubeShape({-1.4, 0, floor - 1.25}, {1.4, 0, floor - 1.25}, 0.15, 32, 0.8f));  // header
  for (const double east : {-0.5, 0.5}) {
    const double top = floor - 1.75;
    scene.append(tubeShape({0.9, east, floor - 1.2}, {0.9, east, top}, 0.06, 16, 0.8f));  // stem
    scene.append(tubeShape({0.9, east, top}, {0.9, east, top - 0.05}, 0.22, 32, 0.85f));  // wheel
  }
  for (const double east : {-1.0, 1.0}) {  // flowline spools leaving north and south
    for (const double north : {-1.0, 1.0}) {
      scene.append(
          tubeShape({north * 1.2, east * 0.5, floor - 0.25},
                    {north * 4.5, east * 0.5, seabed.downAt(north * 4.5, east * 0.5) - 0.25}, 0.15,
                    32, 0.75f));
    }
  }
  // A jumper from the body's east face, up and over, down to the seabed 3 m away.
  const Eigen::Vector3d a(0, 0.8, floor - 0.5), b(0, 1.8, floor - 1.8), c(0, 3.0, floor - 1.8),
      d(0, 3.8, seabed.downAt(0, 3.8) - 0.25);
  for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, d}}) {
    scene.append(tubeShape(from, to, 0.12, 24, 0.8f));
  }
  scene.target = {Eigen::Vector3d(0, 0, floor - 1.0), floor - 2.0, floor, floor};
  return scene;
}

}  // namespace

std::vector<std::string> demoSceneNames() {
  return {"riser", "jacket-node", "seabed-objects", "manifold", "seabed-field"};
}

bool isDemoScene(const std::string& name) {
  for (const auto& n : demoSceneNames()) {
    if (n == name) {
      return true;
    }
  }
  return false;
}

std::string usualTrajectory(const std::string& scene) {
  return scene == "seabed-objects" || scene == "manifold" || scene == "seabed-field" ? "lawnmower"
                                                                                     : "vertical";
}

Scene makeDemoScene(const std::string& name, const SeabedReliefSpec& relief) {
  if (name == "riser") {
    return riser(relief);
  }
  if (name == "jacket-node") {
    return jacketNode(relief);
  }
  if (name == "seabed-objects") {
    return seabedObjects(relief);
  }
  if (name == "manifold") {
    return manifold(relief);
  }
  if (name == "seabed-field") {
    return SeabedField(SeabedFieldSpec{})
        .area(Eigen::AlignedBox2d(Eigen::Vector2d(-20.0, -20.0), Eigen::Vector2d(19.9, 19.9)));
  }
  throw Error("scene", name,
              "unknown demo scene: expected riser, jacket-node, seabed-objects, manifold or "
              "seabed-field");
}

}  // namespace sonarcarve
