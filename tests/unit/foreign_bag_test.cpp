// Bags written by writers that are not ours, reproduced by hand in their distinctive
// structures (docs/formats.md, "Bags from other writers"): MCAP files as the official
// conformance data lays them out (records padded with bytes a newer reader must skip,
// attachments and metadata in the data section, message indexes after a chunk, a schemaless
// channel, a summary section that repeats schemas and channels, statistics, chunk indexes and
// summary offsets; and a file of metadata only), and rosbag2 SQLite3 files of the Foxy era
// (no offered_qos_profiles) and of Jazzy (type_description_hash, message_definitions, schema
// and metadata tables). Each must open and list its topics and counts.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include "io/rosbag/mcap_format.h"
#include "io/rosbag/ros_bag.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

// Little-endian MCAP records, built field by field.
class Record {
 public:
  Record& u8(std::uint8_t v) { return raw(&v, 1); }
  Record& u16(std::uint16_t v) { return raw(&v, 2); }
  Record& u32(std::uint32_t v) { return raw(&v, 4); }
  Record& u64(std::uint64_t v) { return raw(&v, 8); }
  Record& str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    return raw(s.data(), s.size());
  }
  Record& bytes32(const std::vector<std::uint8_t>& b) {
    u32(static_cast<std::uint32_t>(b.size()));
    return raw(b.data(), b.size());
  }
  Record& bytes64(const std::vector<std::uint8_t>& b) {
    u64(b.size());
    return raw(b.data(), b.size());
  }
  Record& map(const std::string& key, const std::string& value) {
    u32(static_cast<std::uint32_t>(8 + key.size() + value.size()));
    return str(key).str(value);
  }
  /// The bytes a newer writer may add after the fields this reader knows (conformance "pad").
  Record& pad() { return u8(0x01).u8(0xff).u8(0xff); }
  const std::vector<std::uint8_t>& content() const { return bytes_; }

 private:
  Record& raw(const void* p, std::size_t n) {
    const auto* b = static_cast<const std::uint8_t*>(p);
    bytes_.insert(bytes_.end(), b, b + n);
    return *this;
  }
  std::vector<std::uint8_t> bytes_;
};

void put(std::vector<std::uint8_t>& out, std::uint8_t op, const Record& r) {
  Record header;
  header.u8(op).u64(r.content().size());
  out.insert(out.end(), header.content().begin(), header.content().end());
  out.insert(out.end(), r.content().begin(), r.content().end());
}

std::vector<std::uint8_t> conformanceLikeMcap() {
  std::vector<std::uint8_t> file(mcap::kMagic.begin(), mcap::kMagic.end());
  put(file, mcap::kHeader, Record().str("").str("").pad());
  put(file, mcap::kAttachment,
      Record()
          .u64(1)
          .u64(2)
          .str("myFile")
          .str("application/octet-stream")
          .bytes64({1, 2, 3})
          .u32(0)
          .pad());
  put(file, mcap::kMetadata, Record().str("myMetadata").map("foo", "bar").pad());
  // A chunk of a schema, a channel and a message, each padded but the message (its data
  // runs to the end of the record).
  std::vector<std::uint8_t> records;
  put(records, mcap::kSchema, Record().u16(1).str("Example").str("c").bytes32({4, 5, 6}).pad());
  put(records, mcap::kChannel,
      Record().u16(1).u16(1).str("example").str("a").map("foo", "bar").pad());
  put(records, mcap::kMessage, Record().u16(1).u32(10).u64(2).u64(1).u8(1).u8(2).u8(3));
  const std::size_t chunk_at = file.size();
  put(file, mcap::kChunk,
      Record().u64(2).u64(2).u64(records.size()).u32(0).str("").bytes64(records));
  put(file, mcap::kMessageIndex, Record().u16(1).u32(16).u64(2).u64(0).pad());
  // A schemaless channel and its message in the data section.
  put(file, mcap::kChannel, Record().u16(2).u16(0).str("schemaless").str("json").u32(0).pad());
  put(file, mcap::kMessage, Record().u16(2).u32(0).u64(3).u64(3).u8('{').u8('}'));
  put(file, mcap::kDataEnd, Record().u32(0).pad());
  const std::size_t summary_at = file.size();
  put(file, mcap::kSchema, Record().u16(1).str("Example").str("c").bytes32({4, 5, 6}).pad());
  put(file, mcap::kChannel, Record().u16(1).u16(1).str("example").str("a").map("foo", "bar").pad());
  put(file, mcap::kStatistics,
      Record().u64(2).u16(1).u32(2).u32(1).u32(1).u32(1).u64(2).u64(3).u32(0).pad());
  put(file, mcap::kChunkIndex,
      Record()
          .u64(2)
          .u64(2)
          .u64(chunk_at)
          .u64(100)
          .u32(0)
          .u64(0)
          .str("")
          .u64(records.size())
          .u64(records.size())
          .pad());
  put(file, mcap::kAttachmentIndex,
      Record()
          .u64(8)
          .u64(60)
          .u64(1)
          .u64(2)
          .u64(3)
          .str("myFile")
          .str("application/octet-stream")
          .pad());
  put(file, mcap::kMetadataIndex, Record().u64(50).u64(40).str("myMetadata").pad());
  const std::size_t offsets_at = file.size();
  put(file, mcap::kSummaryOffset, Record().u8(mcap::kSchema).u64(summary_at).u64(40).pad());
  put(file, mcap::kFooter, Record().u64(summary_at).u64(offsets_at).u32(0));
  file.insert(file.end(), mcap::kMagic.begin(), mcap::kMagic.end());
  return file;
}

TEST(ForeignBags, AnMcapWithEveryOptionalRecordListsItsChannelsOnce) {
  const test::ScratchDir dir;
  const auto path = dir.path() / "conformance.mcap";
  const std::vector<std::uint8_t> bytes = conformanceLikeMcap();
  test::writeText(path, std::string(bytes.begin(), bytes.end()));
  const auto bag = openMcapBag(path);
  EXPECT_TRUE(bag->problems().empty()) << bag->problems().front();
  ASSERT_EQ(bag->topics().size(), 2U);  // the summary's repeated channel is not a third
  EXPECT_EQ(bag->topics()[0].name, "example");
  EXPECT_EQ(bag->topics()[0].type, "Example");
  EXPECT_EQ(bag->topics()[0].encoding, "a");
  EXPECT_EQ(bag->topics()[0].messages, 1U);
  EXPECT_EQ(bag->topics()[1].name, "schemaless");
  EXPECT_EQ(bag->topics()[1].type, "");
  EXPECT_EQ(bag->topics()[1].messages, 1U);
  ASSERT_EQ(bag->messages().size(), 2U);
  EXPECT_EQ(bag->payload(bag->messages()[0]), (std::vector<std::uint8_t>{1, 2, 3}));
  EXPECT_EQ(bag->messages()[0].receive_ns, 2);
  EXPECT_EQ(bag->payload(bag->messages()[1]), (std::vector<std::uint8_t>{'{', '}'}));
}

TEST(ForeignBags, AnMcapOfMetadataOnlyIsAnEmptyBagNotACorruptOne) {
  const test::ScratchDir dir;
  std::vector<std::uint8_t> file(mcap::kMagic.begin(), mcap::kMagic.end());
  put(file, mcap::kHeader, Record().str("").str("").pad());
  put(file, mcap::kMetadata, Record().str("myMetadata").map("foo", "bar").pad());
  put(file, mcap::kDataEnd, Record().u32(0));
  put(file, mcap::kFooter, Record().u64(0).u64(0).u32(0));
  file.insert(file.end(), mcap::kMagic.begin(), mcap::kMagic.end());
  const auto path = dir.path() / "metadata.mcap";
  test::writeText(path, std::string(file.begin(), file.end()));
  const auto bag = openMcapBag(path);
  EXPECT_TRUE(bag->topics().empty());
  EXPECT_TRUE(bag->problems().empty());
  // Cut before its end, the same file is refused: nothing says it was empty.
  file.resize(file.size() - 40);
  test::writeText(path, std::string(file.begin(), file.end()));
  test::expectError([&] { openMcapBag(path); }, {"metadata.mcap", "no Channel record"});
}

void exec(sqlite3* db, const std::string& sql) {
  char* error = nullptr;
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK) << error;
}

TEST(ForeignBags, Db3SchemasFromFoxyToJazzyOpen) {
  const test::ScratchDir dir;
  const std::string messages =
      "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp "
      "INTEGER NOT NULL, data BLOB NOT NULL);"
      "INSERT INTO messages VALUES(1, 1, 100, x'000100000500000068656c6c6f000000');"
      "INSERT INTO messages VALUES(2, 1, 200, x'000100000500000068656c6c6f000000');";
  const std::vector<std::pair<std::string, std::string>> eras = {
      {"foxy.db3",
       "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
       "serialization_format TEXT NOT NULL);"
       "INSERT INTO topics VALUES(1, '/chatter', 'std_msgs/msg/String', 'cdr');"},
      {"jazzy.db3",
       "CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);"
       "INSERT INTO schema VALUES(4, 'jazzy');"
       "CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL, "
       "metadata TEXT NOT NULL);"
       "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
       "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL, "
       "type_description_hash TEXT NOT NULL);"
       "INSERT INTO topics VALUES(1, '/chatter', 'std_msgs/msg/String', 'cdr', '', "
       "'RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18');"
       "CREATE TABLE message_definitions(id INTEGER PRIMARY KEY, topic_type TEXT NOT NULL, "
       "encoding TEXT NOT NULL, encoded_message_definition TEXT NOT NULL, "
       "type_description_hash TEXT NOT NULL);"
       "INSERT INTO message_definitions VALUES(1, 'std_msgs/msg/String', 'ros2msg', "
       "'string data', '');"}};
  for (const auto& [name, topics] : eras) {
    const auto path = dir.path() / name;
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    exec(db, topics + messages);
    sqlite3_close(db);
    const auto bag = openRosBag(path);
    ASSERT_EQ(bag->topics().size(), 1U) << name;
    EXPECT_EQ(bag->topics()[0].messages, 2U) << name;
    EXPECT_EQ(bag->topics()[0].definition, name == "jazzy.db3" ? "string data" : "") << name;
    EXPECT_EQ(bag->payload(bag->messages()[1]).size(), 16U) << name;
  }
}

}  // namespace
}  // namespace sonarcarve
