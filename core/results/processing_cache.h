#pragma once
// The workbench's cache of processed trials: reopening a session is instant and only
// what changed is processed again. An entry holds a trial's outcome (its summary, warnings and
// error), keyed by everything that decides it — the software version, each input file's path,
// size and modification time, the layout and mapping chosen, and every processing parameter
// (process_options_json). The full key is stored in the entry and compared on reading, so a hash
// collision or a stale entry is a miss, never a wrong result. Entries live in the user's cache
// folder (paths.h user_cache_dir), never in the recorded session's folder; a damaged entry is a
// miss and is written again.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/processing/batch.h"

namespace lmc {

// The key of one trial's processing: JSON with every input that decides the outcome.
nlohmann::json processing_cache_key(const TrialSources& job, const BatchOptions& options);

class ProcessingCache {
 public:
  // `dir` is created on the first store; an empty path turns caching off.
  explicit ProcessingCache(std::filesystem::path dir) : dir_(std::move(dir)) {}
  // user_cache_dir()/processed, or off when there is no cache folder.
  static ProcessingCache in_user_cache();

  std::optional<ProcessedTrial> find(const nlohmann::json& key) const;
  // Writes atomically; a failure to write (read-only or full disk) is returned as a message, never
  // thrown: the result is still shown, only not kept.
  std::optional<std::string> store(const nlohmann::json& key, const ProcessedTrial& outcome) const;
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path entry_path(const nlohmann::json& key) const;
  std::filesystem::path dir_;
};

struct CachedBatch {
  std::vector<ProcessedTrial> outcomes;  // in job order
  std::vector<bool> from_cache;          // per outcome
  std::vector<std::string> cache_warnings;
};

// process_batch with the cache in front: cached outcomes are returned as they are, the rest are
// processed (options.on_progress counts all trials, cached ones first) and stored. Cancelled trials
// are never stored. options.on_result is called only for the trials processed now.
CachedBatch process_session_cached(const std::vector<TrialSources>& jobs, const BatchOptions& options,
                                   const ProcessingCache& cache);

}  // namespace lmc
