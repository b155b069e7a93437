#include "core/review/folder_length_corrections.h"

#include <algorithm>

namespace lmc {
namespace {

// The correction that applies to `folder`'s trials, or nullptr (none chosen, or the reference fusion).
const LengthCorrection* folder_correction(const BatchOptions& options, const FolderLengthCorrections& corrections,
                                          const std::filesystem::path& folder) {
  if (options.process.method != FusionMethod::kDefault) return nullptr;
  const auto it = corrections.find(folder);
  return it != corrections.end() ? &it->second.correction : nullptr;
}

}  // namespace

BatchOptions folder_options(const BatchOptions& options, const FolderLengthCorrections& corrections,
                            const std::filesystem::path& folder) {
  BatchOptions out = options;
  if (const LengthCorrection* c = folder_correction(options, corrections, folder)) out.process.length_correction = *c;
  return out;
}

CachedBatch process_folders_cached(const std::vector<TrialSources>& jobs,
                                   const std::vector<std::filesystem::path>& folder_of, const BatchOptions& options,
                                   const FolderLengthCorrections& corrections, const ProcessingCache& cache,
                                   std::vector<std::string>* notes) {
  if (notes != nullptr && options.process.method != FusionMethod::kDefault && !corrections.empty()) {
    notes->push_back("length corrections are not applied with the reference fusion: it stays the study's algorithm");
  }
  // One processing run per correction in use (folders without one share the first).
  std::vector<const LengthCorrection*> group_key{nullptr};  // nullptr: no correction
  std::vector<int> group_of(jobs.size(), 0);
  for (size_t k = 0; k < jobs.size(); ++k) {
    const LengthCorrection* c = folder_correction(options, corrections, folder_of.at(k));
    if (c == nullptr) continue;
    const auto g = std::find(group_key.begin(), group_key.end(), c);
    group_of[k] = static_cast<int>(g - group_key.begin());
    if (g == group_key.end()) group_key.push_back(c);
  }
  CachedBatch out;
  out.outcomes.resize(jobs.size());
  out.from_cache.assign(jobs.size(), false);
  const int total = static_cast<int>(jobs.size());
  int done_before = 0;
  for (size_t g = 0; g < group_key.size(); ++g) {
    std::vector<TrialSources> group_jobs;
    std::vector<size_t> index;
    for (size_t k = 0; k < jobs.size(); ++k) {
      if (group_of[k] != static_cast<int>(g)) continue;
      group_jobs.push_back(jobs[k]);
      index.push_back(k);
    }
    if (group_jobs.empty()) continue;
    BatchOptions group_options = folder_options(options, corrections, folder_of[index.front()]);
    if (options.on_progress) {
      group_options.on_progress = [&progress = options.on_progress, done_before, total](int done, int) {
        progress(done_before + done, total);
      };
    }
    CachedBatch done = process_session_cached(group_jobs, group_options, cache);
    for (auto& w : done.cache_warnings) out.cache_warnings.push_back(std::move(w));
    for (size_t i = 0; i < index.size(); ++i) {
      out.outcomes[index[i]] = std::move(done.outcomes[i]);
      out.from_cache[index[i]] = done.from_cache[i];
    }
    done_before += static_cast<int>(group_jobs.size());
  }
  return out;
}

void add_length_correction_files(nlohmann::json& parameters, FusionMethod method,
                                 const FolderLengthCorrections& corrections) {
  if (method != FusionMethod::kDefault) return;
  for (const auto& [folder, c] : corrections) parameters["length_correction_files"][folder.string()] = c.file.string();
}

}  // namespace lmc
