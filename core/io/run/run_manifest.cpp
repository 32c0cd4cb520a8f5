#include "io/run/run_manifest.h"

#include <algorithm>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/error.h"
#include "common/input_limits.h"
#include "common/sha256.h"
#include "io/files/atomic_file.h"
#include "io/files/input_file.h"
#include "io/files/json_text.h"

namespace sonarcarve {
namespace {

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// A name of a file directly in the folder: no separator, not "." or "..".
bool isPlainFileName(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos &&
         name.find('\0') == std::string::npos;
}

void addNamesFrom(const nlohmann::json& list, std::vector<std::string>& names) {
  if (!list.is_array()) {
    return;
  }
  for (const nlohmann::json& entry : list) {
    const nlohmann::json& name =
        entry.is_object() && entry.contains("name") ? entry["name"] : entry;
    if (name.is_string() && isPlainFileName(name.get<std::string>())) {
      names.push_back(name.get<std::string>());
    }
  }
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The manifest at `path` as JSON; discarded (not an object) when missing or unreadable.
nlohmann::json readManifest(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return nlohmann::json::value_t::discarded;
  }
  try {
    return nlohmann::json::parse(readInputFile(path, "a run manifest", kMaxRecordFileBytes),
                                 nullptr, false);
  } catch (const Error&) {
    return nlohmann::json::value_t::discarded;
  }
}

// The SHA-256 of a file, read in pieces; empty if it cannot be read.
std::string fileSha256(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    return {};
  }
  Sha256 hash;
  std::string piece(1 << 20, '\0');
  while (in.read(piece.data(), static_cast<std::streamsize>(piece.size())) || in.gcount() > 0) {
    hash.update(std::string_view(piece.data(), static_cast<std::size_t>(in.gcount())));
  }
  return in.bad() ? std::string() : hash.hexDigest();
}

}  // namespace

std::optional<std::string> manifestStatus(const std::filesystem::path& folder) {
  const nlohmann::json manifest = readManifest(folder / RunManifest::kFileName);
  if (!manifest.is_object() || !manifest.contains("status") || !manifest["status"].is_string()) {
    return std::nullopt;
  }
  return manifest["status"].get<std::string>();
}

std::vector<std::string> filesListedInManifest(const std::filesystem::path& path) {
  const nlohmann::json manifest = readManifest(path);
  std::vector<std::string> names;
  if (manifest.is_object()) {
    addNamesFrom(manifest.value("files", nlohmann::json()), names);
    addNamesFrom(manifest.value("earlier_files", nlohmann::json()), names);
  }
  return names;
}

RunManifest::RunManifest(std::filesystem::path folder, std::vector<std::string> arguments,
                         const std::vector<std::string>& known_outputs)
    : folder_(std::move(folder)), arguments_(std::move(arguments)), started_utc_(utcNow()) {
  std::vector<std::string> candidates = filesListedInManifest(folder_ / kFileName);
  candidates.insert(candidates.end(), known_outputs.begin(), known_outputs.end());
  for (const std::string& name : candidates) {
    std::error_code ec;
    if (name != kFileName && !contains(earlier_files_, name) &&
        std::filesystem::is_regular_file(folder_ / name, ec)) {
      earlier_files_.push_back(name);
    }
  }
  write("running", "");
}

RunManifestFile describeRunFile(const std::filesystem::path& folder, const std::string& name) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(folder / name, ec);
  return {name, ec ? 0 : bytes, fileSha256(folder / name)};
}

void RunManifest::wrote(const std::string& name) {
  files_.push_back(describeRunFile(folder_, name));
}

void RunManifest::finish(const std::string& status, const std::string& error) {
  std::vector<std::string> kept;
  for (const std::string& name : earlier_files_) {
    const bool rewritten = std::any_of(files_.begin(), files_.end(),
                                       [&](const RunManifestFile& f) { return f.name == name; });
    std::error_code ec;
    if (!rewritten && std::filesystem::remove(folder_ / name, ec)) {
      removed_.push_back(folder_ / name);
    } else if (!rewritten && ec) {
      kept.push_back(name);  // could not be removed: still listed, the next run tries again
    }
  }
  earlier_files_ = kept;
  write(status, error);
}

void RunManifest::write(const std::string& status, const std::string& error) const {
  nlohmann::json files = nlohmann::json::array();
  for (const RunManifestFile& f : files_) {
    files.push_back({{"name", f.name}, {"bytes", f.bytes}, {"sha256", f.sha256}});
  }
  nlohmann::json manifest = {{"format", "sonarcarve run manifest 1"},
                             {"arguments", arguments_},
                             {"version", SONARCARVE_VERSION},
                             {"started_utc", started_utc_},
                             {"status", status},
                             {"files", files}};
  if (status != "running") {
    manifest["finished_utc"] = utcNow();
  }
  if (!error.empty()) {
    manifest["error"] = error;
  }
  if (!earlier_files_.empty()) {
    manifest["earlier_files"] = earlier_files_;
  }
  writeFileAtomically(folder_ / kFileName, jsonText(manifest) + "\n");
}

}  // namespace sonarcarve
