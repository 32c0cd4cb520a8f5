// Demo scenes built in code, in the world NED frame (metres), each with its inspection target:
//   riser           a vertical pipeline of 10.5 m, 0.4 m diameter, three buoyancy modules
//                   near the top and two tie-back cables running down to the seabed at 20 m
//   jacket-node     a 0.8 m leg with a node can and four 0.44 m braces at several angles
//   seabed-objects  two boxes, a lying cylinder and a sphere on a seabed sloping 3 degrees
//   manifold        a subsea template on a flat seabed: mud mat, manifold body with a valve
//                   deck, header pipe, valve stems with hand wheels, flowline spools and a
//                   jumper (large faces that look up, beside pipes)
//   seabed-field    a seabed of any extent with objects, generated from a seed (sim/
//                   seabed_field.h): as a scene, its tiles within 20 m of the origin; a
//                   simulation surveys the field itself (SimulationRequest::field)
#pragma once

#include <string>
#include <vector>

#include "geometry/scene.h"
#include "sim/scene_seabed.h"

namespace sonarcarve {

std::vector<std::string> demoSceneNames();
bool isDemoScene(const std::string& name);
/// Throws Error for an unknown name. `relief` (default: none) replaces the flat seabed of the
/// riser, the jacket node (which then stands on one at 20 m), seabed-objects and the manifold
/// with one with relief (sim/scene_seabed.h); the seabed field keeps its own.
Scene makeDemoScene(const std::string& name, const SeabedReliefSpec& relief = {});
/// The trajectory a scene is usually inspected with: lawnmower over seabed-objects, the
/// manifold and the seabed field, vertical otherwise (a loaded mesh included).
std::string usualTrajectory(const std::string& scene);

}  // namespace sonarcarve
