#include "core/results/processing_cache.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/common/paths.h"
#include "core/io/atomic_write.h"
#include "core/processing/process_options_json.h"

#ifndef LMC_VERSION
#define LMC_VERSION "unknown"
#endif

namespace fs = std::filesystem;

namespace lmc {
namespace {

constexpr const char* kCacheFormat = "lmc-processing-cache";
constexpr int kCacheFormatVersion = 1;

// Path, size and modification time: what `make` trusts. Hashing the contents would cost as much as
// reading a recording, which is most of what the cache saves.
nlohmann::json file_identity(const fs::path& p) {
  std::error_code ec;
  const fs::path abs = fs::absolute(p, ec).lexically_normal();
  nlohmann::json j = {{"path", (ec ? p : abs).string()}};
  const auto size = fs::file_size(p, ec);
  j["size"] = ec ? nlohmann::json(nullptr) : nlohmann::json(static_cast<std::uint64_t>(size));
  const auto mtime = fs::last_write_time(p, ec);
  j["mtime"] =
      ec ? nlohmann::json(nullptr) : nlohmann::json(static_cast<std::int64_t>(mtime.time_since_epoch().count()));
  return j;
}

nlohmann::json optional_file(const std::optional<fs::path>& p) {
  return p ? file_identity(*p) : nlohmann::json(nullptr);
}

// FNV-1a, 64 bit: stable across runs and machines (std::hash is not), enough to name a file; the
// stored key decides whether an entry really matches.
std::string fnv1a_hex(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

nlohmann::json outcome_json(const ProcessedTrial& o) {
  return {{"trial", o.trial},        {"ok", o.ok},           {"error", o.error},
          {"warnings", o.warnings},  {"summary", o.summary}, {"layout_used", o.layout_used},
          {"has_vicon", o.has_vicon}};
}

ProcessedTrial outcome_from_json(const nlohmann::json& j) {
  ProcessedTrial o;
  o.trial = j.at("trial").get<std::string>();
  o.ok = j.at("ok").get<bool>();
  o.error = j.at("error").get<std::string>();
  o.warnings = j.at("warnings").get<std::vector<std::string>>();
  o.summary = j.at("summary");
  o.layout_used = j.at("layout_used").get<std::string>();
  o.has_vicon = j.at("has_vicon").get<bool>();
  return o;
}

}  // namespace

nlohmann::json processing_cache_key(const TrialSources& job, const BatchOptions& options) {
  nlohmann::json k;
  k["software_version"] = LMC_VERSION;
  k["trial"] = job.trial;
  k["lmc"] = file_identity(job.lmc);
  k["vicon"] = optional_file(job.vicon);
  k["sidecar"] = optional_file(job.sidecar);
  k["session_layout"] = job.layout_json ? *job.layout_json : nlohmann::json(nullptr);
  // A layout named by path can change under the same name: its identity goes in, not its name.
  if (options.layout) {
    std::error_code ec;
    k["layout"] =
        fs::is_regular_file(*options.layout, ec) ? file_identity(*options.layout) : nlohmann::json(*options.layout);
  } else {
    k["layout"] = nullptr;
  }
  k["mapping"] = optional_file(options.mapping);
  k["process"] = process_options_json(options.process);
  return k;
}

ProcessingCache ProcessingCache::in_user_cache() {
  const fs::path base = user_cache_dir();
  return ProcessingCache(base.empty() ? fs::path() : base / "processed");
}

fs::path ProcessingCache::entry_path(const nlohmann::json& key) const {
  return dir_ / (fnv1a_hex(key.dump()) + ".json");
}

std::optional<ProcessedTrial> ProcessingCache::find(const nlohmann::json& key) const {
  if (dir_.empty()) return std::nullopt;
  std::ifstream in(entry_path(key), std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  // A damaged or foreign entry is a miss: the trial is processed again and the entry rewritten.
  const nlohmann::json entry = nlohmann::json::parse(text.str(), nullptr, false);
  if (!entry.is_object() || entry.value("format", "") != kCacheFormat ||
      entry.value("format_version", 0) != kCacheFormatVersion) {
    return std::nullopt;
  }
  if (!entry.contains("key") || entry["key"] != key || !entry.contains("outcome")) return std::nullopt;
  try {
    return outcome_from_json(entry["outcome"]);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

std::optional<std::string> ProcessingCache::store(const nlohmann::json& key, const ProcessedTrial& outcome) const {
  if (dir_.empty()) return std::nullopt;
  try {
    fs::create_directories(dir_);
    const nlohmann::json entry = {{"format", kCacheFormat},
                                  {"format_version", kCacheFormatVersion},
                                  {"key", key},
                                  {"outcome", outcome_json(outcome)}};
    write_file_atomically(entry_path(key), entry.dump() + "\n");
  } catch (const std::exception& e) {
    return std::string("the processing cache could not keep ") + outcome.trial + ": " + e.what();
  }
  return std::nullopt;
}

CachedBatch process_session_cached(const std::vector<TrialSources>& jobs, const BatchOptions& options,
                                   const ProcessingCache& cache) {
  CachedBatch batch;
  batch.outcomes.resize(jobs.size());
  batch.from_cache.assign(jobs.size(), false);
  // Method-comparison errors are not part of an entry: such a batch is always processed afresh.
  const bool use_cache = !options.compare_methods && !cache.dir().empty();
  std::vector<nlohmann::json> keys(jobs.size());
  std::vector<size_t> todo;
  for (size_t k = 0; k < jobs.size(); ++k) {
    if (use_cache) {
      keys[k] = processing_cache_key(jobs[k], options);
      if (auto hit = cache.find(keys[k])) {
        batch.outcomes[k] = std::move(*hit);
        batch.from_cache[k] = true;
        continue;
      }
    }
    todo.push_back(k);
  }
  const int cached = static_cast<int>(jobs.size() - todo.size());
  const int total = static_cast<int>(jobs.size());
  if (options.on_progress) options.on_progress(cached, total);
  std::vector<TrialSources> fresh_jobs;
  for (size_t k : todo) fresh_jobs.push_back(jobs[k]);
  BatchOptions fresh_options = options;
  if (options.on_progress) {
    fresh_options.on_progress = [&options, cached, total](int done, int) { options.on_progress(cached + done, total); };
  }
  std::vector<ProcessedTrial> fresh = process_batch(fresh_jobs, fresh_options);
  for (size_t i = 0; i < todo.size(); ++i) {
    const size_t k = todo[i];
    if (use_cache && !fresh[i].cancelled) {
      if (auto problem = cache.store(keys[k], fresh[i])) batch.cache_warnings.push_back(*problem);
    }
    batch.outcomes[k] = std::move(fresh[i]);
  }
  return batch;
}

}  // namespace lmc
