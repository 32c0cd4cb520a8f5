// rosbag2's SQLite3 storage (.db3): tables topics(id, name, type, serialization_format, ...)
// and messages(id, topic_id, timestamp, data); newer bags add schema, metadata and
// message_definitions tables (the definitions are kept: they say whether a type starts with a
// header) and a type_description_hash column, which is not needed. Payloads compressed one by one
// (rosbag2's compression_mode: message, zstd) are decompressed. The file is opened read-only and
// immutable (no journal is written beside a bag that may sit on read-only media); payloads are read
// by row id on demand.
#include <sqlite3.h>

#include <map>
#include <mutex>

#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/decompress.h"
#include "io/files/input_file.h"
#include "io/rosbag/ros_bag.h"

namespace sonarcarve {
namespace {

// A hostile or corrupt database must not make a query run for ever: SQLite calls this every
// 1000 virtual-machine steps and stops the query after a budget (far above any real bag's
// index: about 20 steps a row).
constexpr int kProgressStepsPerCall = 1000;
constexpr long kMaxProgressCalls = 200000000L / kProgressStepsPerCall;

class SqliteBag final : public RosBag {
 public:
  explicit SqliteBag(std::filesystem::path path) : path_(std::move(path)), source_(path_.string()) {
    requireRegularFile(path_, "a rosbag2 SQLite3 bag (.db3)");
    const std::string uri = "file:" + encodedPath() + "?mode=ro&immutable=1";
    if (sqlite3_open_v2(uri.c_str(), &db_, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr) !=
        SQLITE_OK) {
      const std::string why = db_ != nullptr ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      db_ = nullptr;
      throw Error(source_, "", "cannot open as SQLite3: " + why);
    }
    sqlite3_progress_handler(db_, kProgressStepsPerCall, &SqliteBag::onProgress, this);
    try {
      index();
    } catch (...) {
      sqlite3_close(db_);
      db_ = nullptr;
      throw;
    }
  }
  ~SqliteBag() override {
    sqlite3_finalize(payload_query_);
    sqlite3_close(db_);
  }
  SqliteBag(const SqliteBag&) = delete;
  SqliteBag& operator=(const SqliteBag&) = delete;

  const std::filesystem::path& path() const override { return path_; }
  std::string storage() const override { return "SQLite3"; }
  const std::vector<BagTopic>& topics() const override { return topics_; }
  const std::vector<BagMessage>& messages() const override { return messages_; }
  const std::vector<std::string>& problems() const override { return problems_; }

  std::vector<std::uint8_t> payload(const BagMessage& message) const override {
    const std::lock_guard lock(mutex_);
    progress_calls_ = 0;
    sqlite3_reset(payload_query_);
    sqlite3_bind_int64(payload_query_, 1, static_cast<sqlite3_int64>(message.locator));
    if (sqlite3_step(payload_query_) != SQLITE_ROW) {
      throw Error(source_, message.place, "cannot read the data: " + errorText());
    }
    const auto* data = static_cast<const std::uint8_t*>(sqlite3_column_blob(payload_query_, 0));
    const int size = sqlite3_column_bytes(payload_query_, 0);
    std::vector<std::uint8_t> out(data, data + (data != nullptr && size > 0 ? size : 0));
    sqlite3_reset(payload_query_);
    // rosbag2's message compression (compression_mode: message) stores each payload as a zstd
    // frame; CDR starts with 00 00 or 00 01, never with the zstd magic.
    return isZstdFrame(out) ? decompressZstdFrame(out, kMaxBagChunkBytes, source_, message.place)
                            : out;
  }

 private:
  static int onProgress(void* self) {
    auto* bag = static_cast<SqliteBag*>(self);
    return ++bag->progress_calls_ > kMaxProgressCalls ? 1 : 0;
  }

  // The path as a URI path: '%', '?' and '#' escaped.
  std::string encodedPath() const {
    std::string out;
    for (const char c : std::filesystem::absolute(path_).string()) {
      if (c == '%' || c == '?' || c == '#') {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%%%02X", static_cast<unsigned char>(c));
        out += hex;
      } else {
        out += c;
      }
    }
    return out;
  }

  std::string errorText() const { return sqlite3_errmsg(db_); }

  sqlite3_stmt* prepare(const char* sql, const std::string& expected) const {
    sqlite3_stmt* statement = nullptr;
    if (sqlite3_prepare_v2(db_, sql, -1, &statement, nullptr) != SQLITE_OK) {
      const std::string why = errorText();
      sqlite3_finalize(statement);
      throw Error(source_, "", "SQLite: " + why + " (expected " + expected + ")");
    }
    return statement;
  }

  static std::string text(sqlite3_stmt* statement, int column) {
    const auto* t = sqlite3_column_text(statement, column);
    return t != nullptr ? reinterpret_cast<const char*>(t) : "";
  }

  void index() {
    const std::string tables =
        "a rosbag2 bag: tables topics(id, name, type, "
        "serialization_format) and messages(id, topic_id, timestamp, data)";
    std::map<std::int64_t, std::size_t> topic_of_id;
    sqlite3_stmt* q = prepare("SELECT id, name, type, serialization_format FROM topics", tables);
    int rc = 0;
    while ((rc = sqlite3_step(q)) == SQLITE_ROW) {
      BagTopic topic{text(q, 1), text(q, 2), text(q, 3), 0, ""};
      topic_of_id[sqlite3_column_int64(q, 0)] = topics_.size();
      topics_.push_back(std::move(topic));
    }
    sqlite3_finalize(q);
    if (rc != SQLITE_DONE) {
      throw Error(source_, "table topics", "SQLite: " + errorText() + " (expected " + tables + ")");
    }
    readMessageDefinitions();
    q = prepare("SELECT id, topic_id, timestamp FROM messages ORDER BY timestamp, id", tables);
    std::size_t orphans = 0;
    while ((rc = sqlite3_step(q)) == SQLITE_ROW) {
      const std::int64_t id = sqlite3_column_int64(q, 0);
      const auto topic = topic_of_id.find(sqlite3_column_int64(q, 1));
      if (topic == topic_of_id.end()) {
        ++orphans;
        continue;
      }
      BagMessage m;
      m.topic = topic->second;
      m.receive_ns = sqlite3_column_int64(q, 2);
      m.locator = static_cast<std::uint64_t>(id);
      m.place = "message id " + std::to_string(id);
      ++topics_[m.topic].messages;
      messages_.push_back(std::move(m));
    }
    sqlite3_finalize(q);
    if (rc != SQLITE_DONE) {
      throw Error(source_, "table messages",
                  "SQLite: " + errorText() + " after " + std::to_string(messages_.size()) +
                      " rows (expected " + tables + ")");
    }
    if (orphans > 0) {
      problems_.push_back(source_ + ": " + std::to_string(orphans) +
                          " messages of a topic_id not in the topics table; skipped");
    }
    if (topics_.empty()) {
      throw Error(source_, "table topics", "no topic: expected the topics of a bag");
    }
    payload_query_ = prepare("SELECT data FROM messages WHERE id = ?", tables);
  }

  // Bags from ROS 2 Iron on keep each type's definition in a message_definitions table;
  // older bags have none (then definitions stay empty).
  void readMessageDefinitions() {
    sqlite3_stmt* q = prepare(
        "SELECT name FROM sqlite_master WHERE type = 'table' AND name = 'message_definitions'",
        "the SQLite schema table");
    const bool present = sqlite3_step(q) == SQLITE_ROW;
    sqlite3_finalize(q);
    if (!present) {
      return;
    }
    q = prepare("SELECT topic_type, encoding, encoded_message_definition FROM message_definitions",
                "message_definitions(topic_type, encoding, encoded_message_definition)");
    while (sqlite3_step(q) == SQLITE_ROW) {
      if (text(q, 1) != "ros2msg") {
        continue;
      }
      for (BagTopic& topic : topics_) {
        if (topic.type == text(q, 0)) {
          topic.definition = text(q, 2);
        }
      }
    }
    sqlite3_finalize(q);
  }

  std::filesystem::path path_;
  std::string source_;
  sqlite3* db_ = nullptr;
  sqlite3_stmt* payload_query_ = nullptr;
  mutable std::mutex mutex_;
  mutable long progress_calls_ = 0;
  std::vector<BagTopic> topics_;
  std::vector<BagMessage> messages_;
  std::vector<std::string> problems_;
};

}  // namespace

std::unique_ptr<RosBag> openSqliteBag(const std::filesystem::path& path) {
  return std::make_unique<SqliteBag>(path);
}

}  // namespace sonarcarve
