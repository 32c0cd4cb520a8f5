#include "carve/map_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "common/available_memory.h"
#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/atomic_file.h"
#include "io/files/input_file.h"

namespace sonarcarve {
namespace {

constexpr char kMagic[8] = {'S', 'C', 'M', 'A', 'P', '\n', '\x1a', '\0'};
constexpr char kEndMarker[8] = {'S', 'C', 'M', 'A', 'P', 'E', 'N', 'D'};
constexpr std::uint32_t kVersion = 1;
constexpr std::uint8_t kFree = 1;
constexpr std::uint8_t kMixed = 2;
constexpr int kVoxels = VoxelMap::kBlockVoxels;
// Bytes a block costs in a VoxelMap's tables (state, slot, stamp), and a Mixed block's values.
constexpr std::uint64_t kBlockTableBytes = 1 + 4 + 4;
constexpr std::uint64_t kBlockValueBytes = kVoxels * sizeof(float);

using Values = std::array<float, kVoxels>;

// A map over exactly the blocks [first, first + dims) of the grid of `voxel_size_m`.
std::unique_ptr<VoxelMap> gridMap(double voxel_size_m, const Eigen::Vector3i& first,
                                  const Eigen::Vector3i& dims) {
  // Voxel centres, so that no rounding moves the box across a block border.
  const Eigen::Vector3d lo =
      ((first * VoxelMap::kBlockSide).cast<double>().array() + 0.5).matrix() * voxel_size_m;
  const Eigen::Vector3d hi =
      (((first + dims) * VoxelMap::kBlockSide).cast<double>().array() - 0.5).matrix() *
      voxel_size_m;
  return std::make_unique<VoxelMap>(voxel_size_m, Eigen::AlignedBox3d(lo, hi));
}

// Whether box-relative block coordinates `rel` lie inside `map`'s box.
bool insideBox(const VoxelMap& map, const Eigen::Vector3i& rel) {
  return (rel.array() >= 0).all() && (rel.array() < map.blockDims().array()).all();
}

// The first block and one past the last of the union of two maps' boxes.
std::pair<Eigen::Vector3i, Eigen::Vector3i> unionOfBoxes(const VoxelMap& a, const VoxelMap& b) {
  return {a.firstBlock().cwiseMin(b.firstBlock()),
          (a.firstBlock() + a.blockDims()).cwiseMax(b.firstBlock() + b.blockDims())};
}

// The 512 values of the block at global block coordinates `g` (unknown outside the box).
void blockValues(const VoxelMap& map, const Eigen::Vector3i& g, Values& out) {
  const Eigen::Vector3i rel = g - map.firstBlock();
  if (!insideBox(map, rel)) {
    out.fill(VoxelMap::kUnknown);
    return;
  }
  map.copyValues(map.blockIndex(rel), out.data());
}

void stored(VoxelMap& map, std::size_t b, const Values& values) {
  const bool all_unknown =
      std::all_of(values.begin(), values.end(), [](float v) { return v == VoxelMap::kUnknown; });
  if (!all_unknown) {
    map.storeBlock(b, values.data(), 0);  // kept as Free when every voxel is carved
  }
}

void requireOneGrid(const VoxelMap& a, const VoxelMap& b) {
  if (a.voxelSize() != b.voxelSize()) {
    throw Error("merge", "",
                "the maps have voxels of " + std::to_string(a.voxelSize()) + " and " +
                    std::to_string(b.voxelSize()) + " m: expected one grid");
  }
}

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// Reads the file's fields in order, naming the byte of any problem.
class MapReader {
 public:
  MapReader(std::string bytes, std::string file)
      : bytes_(std::move(bytes)), file_(std::move(file)) {}

  template <typename T>
  T get(const char* what) {
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  void getBytes(void* into, std::size_t n, const char* what) {
    need(n, what);
    std::memcpy(into, bytes_.data() + at_, n);
    at_ += n;
  }
  bool startsWith(const char (&text)[8]) const {
    return bytes_.size() - at_ >= 8 && std::memcmp(bytes_.data() + at_, text, 8) == 0;
  }
  void skip(std::size_t n) { at_ += n; }
  std::size_t offset() const { return at_; }
  std::size_t left() const { return bytes_.size() - at_; }
  [[noreturn]] void fail(std::size_t at, const std::string& message) const {
    throw Error(file_, bytePlace(at), message);
  }

 private:
  void need(std::size_t n, const char* what) const {
    if (bytes_.size() - at_ < n) {
      fail(at_,
           std::string("the file ends; expected ") + what + " (cut short: write the map again)");
    }
  }
  std::string bytes_;
  std::string file_;
  std::size_t at_ = 0;
};

}  // namespace

void saveMap(const VoxelMap& map, const std::filesystem::path& path) {
  std::string out(kMagic, sizeof(kMagic));
  Values block_values;
  put(out, kVersion);
  put(out, map.voxelSize());
  for (int a = 0; a < 3; ++a) {
    put(out, static_cast<std::int32_t>(map.firstBlock()[a]));
  }
  for (int a = 0; a < 3; ++a) {
    put(out, static_cast<std::int32_t>(map.blockDims()[a]));
  }
  const std::size_t kept = map.blockCount() - map.blockCount(VoxelMap::BlockState::Unknown);
  put(out, static_cast<std::uint64_t>(kept));
  // Blocks in the order of the box's rows, by their place in it (the table's pages are not
  // part of the format).
  for (std::size_t n = 0; n < map.boxBlockCount(); ++n) {
    const std::size_t b = map.blockAtRowOrder(n);
    const VoxelMap::BlockState state = map.state(b);
    if (state == VoxelMap::BlockState::Unknown) {
      continue;
    }
    put(out, static_cast<std::uint64_t>(n));
    if (state == VoxelMap::BlockState::Free) {
      put(out, kFree);
    } else {  // Mixed, or Partial written as its values
      put(out, kMixed);
      map.copyValues(b, block_values.data());
      out.append(reinterpret_cast<const char*>(block_values.data()), kBlockValueBytes);
    }
  }
  out.append(kEndMarker, sizeof(kEndMarker));
  writeFileAtomically(path, out);
}

std::unique_ptr<VoxelMap> loadMap(const std::filesystem::path& path) {
  MapReader r(readInputFile(path, "a SonarCarve map file (.scmap)", kMaxMapFileBytes),
              path.string());
  if (r.left() == 0) {
    r.fail(0, "the file is empty; expected a SonarCarve map file (.scmap)");
  }
  if (!r.startsWith(kMagic)) {
    r.fail(0, "not a SonarCarve map file: expected it to start with SCMAP");
  }
  r.skip(sizeof(kMagic));
  const std::size_t version_at = r.offset();
  const auto version = r.get<std::uint32_t>("the format version");
  if (version != kVersion) {
    r.fail(version_at, "format version " + std::to_string(version) + ": expected " +
                           std::to_string(kVersion) + " (a newer SonarCarve wrote it?)");
  }
  const std::size_t size_at = r.offset();
  const auto voxel = r.get<double>("the voxel size");
  if (!(std::isfinite(voxel) && voxel > 1e-4 && voxel < 1e3)) {
    r.fail(size_at, "voxel size " + std::to_string(voxel) + " m: expected 0.0001 to 1000 m");
  }
  Eigen::Vector3i first, dims;
  for (int a = 0; a < 3; ++a) {
    first[a] = r.get<std::int32_t>("the first block");
  }
  const std::size_t dims_at = r.offset();
  for (int a = 0; a < 3; ++a) {
    dims[a] = r.get<std::int32_t>("the block dimensions");
  }
  const double total = static_cast<double>(dims.x()) * dims.y() * dims.z();
  if ((dims.array() < 1).any() || total > 2.0e9 ||
      (first.array().abs() > (1 << 12)).any()) {  // OctoMap's +-32768 voxels, in blocks
    r.fail(dims_at, "a grid of " + std::to_string(dims.x()) + " x " + std::to_string(dims.y()) +
                        " x " + std::to_string(dims.z()) +
                        " blocks: expected 1 to 2e9 blocks within +-4096 blocks of the origin");
  }
  const std::size_t count_at = r.offset();
  const auto kept = r.get<std::uint64_t>("the number of blocks");
  const auto blocks = static_cast<std::uint64_t>(total);
  if (kept > blocks) {
    r.fail(count_at,
           std::to_string(kept) + " blocks: expected at most the grid's " + std::to_string(blocks));
  }
  // What the map will hold, against the memory left (the file's own size bounds the values).
  const std::uint64_t need =
      blocks * kBlockTableBytes +
      std::min<std::uint64_t>(kept, r.left() / kBlockValueBytes) * kBlockValueBytes;
  if (const auto memory = availableMemory(); memory && need > memory->bytes) {
    r.fail(dims_at, "the map needs " + std::to_string(need >> 20) + " MB, more than the " +
                        std::to_string(memory->bytes >> 20) + " MB available (" + memory->source +
                        ")");
  }
  auto map = gridMap(voxel, first, dims);
  Values values;
  std::uint64_t previous = 0;
  for (std::uint64_t n = 0; n < kept; ++n) {
    const std::size_t index_at = r.offset();
    const auto row_order = r.get<std::uint64_t>("a block index");
    if (row_order >= blocks || (n > 0 && row_order <= previous)) {
      r.fail(index_at, "block index " + std::to_string(row_order) +
                           ": expected increasing indices below " + std::to_string(blocks));
    }
    previous = row_order;
    const std::size_t b = map->blockAtRowOrder(row_order);
    const std::size_t state_at = r.offset();
    const auto state = r.get<std::uint8_t>("a block state");
    if (state == kFree) {
      map->storeBlock(b, nullptr, 0);
    } else if (state == kMixed) {
      const std::size_t values_at = r.offset();
      r.getBytes(values.data(), kBlockValueBytes, "a block's 512 values");
      for (int i = 0; i < kVoxels; ++i) {
        if (!(values[static_cast<std::size_t>(i)] >= 0.0f)) {  // NaN or negative
          r.fail(values_at + static_cast<std::size_t>(i) * sizeof(float),
                 "voxel value " + std::to_string(values[static_cast<std::size_t>(i)]) +
                     ": expected 0 (carved), a positive intensity or +inf (unknown)");
        }
      }
      map->storeBlock(b, values.data(), 0);
    } else {
      r.fail(state_at, "block state " + std::to_string(state) + ": expected 1 (free) or 2 (mixed)");
    }
  }
  const std::size_t end_at = r.offset();
  if (!r.startsWith(kEndMarker)) {
    r.fail(end_at, r.left() < sizeof(kEndMarker)
                       ? "the file ends; expected its end marker (cut short: write the map again)"
                       : "expected the end marker SCMAPEND");
  }
  r.skip(sizeof(kEndMarker));
  if (r.left() != 0) {
    r.fail(r.offset(), std::to_string(r.left()) + " bytes after the end marker: expected none");
  }
  return map;
}

Eigen::AlignedBox3d voxelCentresBox(const VoxelMap& map) {
  const Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5 * map.voxelSize());
  const Eigen::AlignedBox3d box = map.bounds();
  return {box.min() + half, box.max() - half};
}

void fuseInto(VoxelMap& target, const VoxelMap& source) {
  requireOneGrid(target, source);
  Values mine, theirs;
  for (std::size_t n = 0; n < source.blockCount(); ++n) {
    if (source.state(n) == VoxelMap::BlockState::Unknown) {
      continue;
    }
    const Eigen::Vector3i g = source.blockCoords(n) + source.firstBlock();
    const Eigen::Vector3i rel = g - target.firstBlock();
    if (!insideBox(target, rel)) {
      continue;
    }
    blockValues(target, g, mine);
    blockValues(source, g, theirs);
    for (std::size_t i = 0; i < mine.size(); ++i) {
      mine[i] = std::min(mine[i], theirs[i]);
    }
    stored(target, target.blockIndex(rel), mine);
  }
}

std::unique_ptr<VoxelMap> mergeMaps(const VoxelMap& a, const VoxelMap& b) {
  requireOneGrid(a, b);
  const auto [first, last] = unionOfBoxes(a, b);
  auto merged = gridMap(a.voxelSize(), first, last - first);
  fuseInto(*merged, a);
  fuseInto(*merged, b);
  return merged;
}

bool sameVoxels(const VoxelMap& a, const VoxelMap& b) {
  if (a.voxelSize() != b.voxelSize()) {
    return false;
  }
  const auto [first, last] = unionOfBoxes(a, b);
  Values va, vb;
  for (int z = first.z(); z < last.z(); ++z) {
    for (int y = first.y(); y < last.y(); ++y) {
      for (int x = first.x(); x < last.x(); ++x) {
        blockValues(a, {x, y, z}, va);
        blockValues(b, {x, y, z}, vb);
        if (va != vb) {
          return false;
        }
      }
    }
  }
  return true;
}

}  // namespace sonarcarve
