#include <map>
#include <mutex>
#include <stdexcept>

#include "carve/carver.h"
#include "common/error.h"

namespace sonarcarve {
namespace {

struct Entry {
  std::string name;
  CarverFactory factory;
};

// A function-local registry: engines register from static initialisers of other files, in
// an order no one controls.
struct Registry {
  std::mutex mutex;
  std::map<CarverEngine, Entry> entries;
};

Registry& registry() {
  static Registry instance;
  return instance;
}

}  // namespace

bool registerCarverEngine(CarverEngine key, std::string name, CarverFactory factory) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const auto& [k, entry] : r.entries) {
    if (k == key || entry.name == name) {
      throw std::logic_error("carving engine registered twice: " + name);
    }
  }
  r.entries.emplace(key, Entry{std::move(name), std::move(factory)});
  return true;
}

std::unique_ptr<Carver> makeCarver(CarverEngine key, const CarverSetup& setup) {
  CarverFactory factory;
  {
    Registry& r = registry();
    const std::lock_guard lock(r.mutex);
    const auto it = r.entries.find(key);
    if (it == r.entries.end()) {
      throw Error("parameters", "engine",
                  "no carving engine number " + std::to_string(static_cast<int>(key)));
    }
    factory = it->second.factory;
  }
  return factory(setup);
}

void Carver::fuse(const VoxelMap&) {
  throw Error("parameters", "engine",
              "this engine cannot start from a saved map; use the fast engine");
}

VoxelValues collectVoxels(const std::function<void(const Carver::VoxelVisitor&)>& each) {
  VoxelValues collected;
  each([&](const Eigen::Vector3i& voxel, float value) {
    collected.voxels.push_back(voxel);
    collected.values.push_back(value);
  });
  return collected;
}

VoxelValues surfaceCandidates(const Carver& carver) {
  return collectVoxels(
      [&](const Carver::VoxelVisitor& visit) { carver.forEachSurfaceCandidate(visit); });
}

std::vector<CarverEngine> carverEngines() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::vector<CarverEngine> keys;
  for (const auto& entry : r.entries) {
    keys.push_back(entry.first);
  }
  return keys;
}

std::string carverEngineName(CarverEngine key) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  const auto it = r.entries.find(key);
  return it == r.entries.end() ? "engine " + std::to_string(static_cast<int>(key))
                               : it->second.name;
}

std::optional<CarverEngine> carverEngineFromName(std::string_view name) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const auto& [key, entry] : r.entries) {
    if (entry.name == name) {
      return key;
    }
  }
  return std::nullopt;
}

}  // namespace sonarcarve
