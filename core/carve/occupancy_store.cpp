#include "carve/occupancy_store.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>

#include "common/error.h"
#include "io/files/temporary_file.h"

namespace sonarcarve {
namespace {

constexpr const char* kSource = "temporary file of map.bt blocks";
constexpr std::size_t kRecordBytes = sizeof(OccupancyBlock::leaves);

}  // namespace

void OccupancyStore::add(const std::vector<OccupancyBlock>& blocks) {
  if (blocks.empty()) {
    return;
  }
  if (problem_.empty()) {
    try {
      writeToFile(blocks);
      return;
    } catch (const Error& e) {
      problem_ = e.what();
    }
  }
  for (const OccupancyBlock& b : blocks) {
    keys_.push_back({b.morton, kInMemory | kept_.size()});
    kept_.push_back(b);
  }
}

void OccupancyStore::writeToFile(const std::vector<OccupancyBlock>& blocks) {
  if (!file_) {
    file_.reset(openTemporaryFile(kSource), [](std::FILE* x) { std::fclose(x); });
  }
  if (fseeko(file_.get(), 0, SEEK_END) != 0) {
    throw Error(kSource, "", std::string("could not seek to its end: ") + std::strerror(errno));
  }
  // The file's end, not this store's count: a copy may have added blocks to the same file.
  const auto first = static_cast<std::uint64_t>(ftello(file_.get())) / kRecordBytes;
  for (std::size_t n = 0; n < blocks.size(); ++n) {
    if (std::fwrite(blocks[n].leaves.data(), 1, kRecordBytes, file_.get()) != kRecordBytes ||
        (n + 1 == blocks.size() && std::fflush(file_.get()) != 0)) {
      throw Error(kSource, "block " + std::to_string(first + n),
                  std::string("could not be written (disk full?): ") + std::strerror(errno));
    }
  }
  for (std::size_t n = 0; n < blocks.size(); ++n) {
    keys_.push_back({blocks[n].morton, first + n});
  }
}

SortedOccupancy OccupancyStore::sorted() const {
  std::vector<Key> keys = keys_;
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return a.morton < b.morton || (a.morton == b.morton && a.record < b.record);
  });
  SortedOccupancy out;
  out.mortons.reserve(keys.size());
  std::vector<std::uint64_t> records;
  records.reserve(keys.size());
  for (const Key& k : keys) {
    out.mortons.push_back(k.morton);
    records.push_back(k.record);
  }
  auto kept = std::make_shared<const std::vector<OccupancyBlock>>(kept_);
  out.read = [file = file_, kept, records = std::move(records)](std::size_t n,
                                                                OccupancyBlock& block) {
    if ((records[n] & kInMemory) != 0) {
      block.leaves = (*kept)[records[n] & ~kInMemory].leaves;
      return;
    }
    const std::uint64_t offset = records[n] * kRecordBytes;
    if (fseeko(file.get(), static_cast<off_t>(offset), SEEK_SET) != 0 ||
        std::fread(block.leaves.data(), 1, kRecordBytes, file.get()) != kRecordBytes) {
      throw Error(kSource, "block " + std::to_string(records[n]),
                  "could not be read back at byte " + std::to_string(offset));
    }
  };
  return out;
}

}  // namespace sonarcarve
