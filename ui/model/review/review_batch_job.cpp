#include "ui/model/review/review_batch_job.h"

#include <algorithm>

#include "core/results/processing_cache.h"
#include "core/session/session_trials.h"

namespace lmc::ui {

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

ReviewBatch run_review_batch(const ReviewBatchInput& input, std::stop_token stop,
                             const std::function<void(int done, int total)>& progress) {
  ReviewBatch batch;
  std::vector<lmc::TrialSources> jobs;
  std::vector<std::filesystem::path> folder_of;
  for (const auto& folder : input.folders) {
    try {
      auto found = session::trial_sources_for_input(folder, std::nullopt, &batch.notes);
      for (auto& j : found) {
        jobs.push_back(std::move(j));
        folder_of.push_back(folder);
      }
    } catch (const std::exception& e) {
      // One unreadable folder must not hide the others.
      batch.notes.push_back(e.what());
    }
  }
  // One processing run per correction in use (folders without one share the first), each with
  // its own options; the cache keys on the options, so corrected and plain results never mix.
  std::vector<const LengthCorrection*> group_key;  // nullptr: no correction
  std::vector<int> group_of(jobs.size(), 0);
  if (input.options.process.method != FusionMethod::kDefault && !input.corrections.empty()) {
    batch.notes.push_back(
        "length corrections are not applied with the reference fusion: it stays the study's algorithm");
  }
  group_key.push_back(nullptr);
  for (size_t k = 0; k < jobs.size(); ++k) {
    const LengthCorrection* c = folder_correction(input.options, input.corrections, folder_of[k]);
    if (c == nullptr) continue;
    const auto g = std::find(group_key.begin(), group_key.end(), c);
    group_of[k] = static_cast<int>(g - group_key.begin());
    if (g == group_key.end()) group_key.push_back(c);
  }
  const ProcessingCache cache(input.cache_dir);
  std::vector<ProcessedTrial> outcomes(jobs.size());
  std::vector<bool> from_cache(jobs.size(), false);
  const int total = static_cast<int>(jobs.size());
  int done_before = 0;
  for (size_t g = 0; g < group_key.size(); ++g) {
    std::vector<lmc::TrialSources> group_jobs;
    std::vector<size_t> index;
    for (size_t k = 0; k < jobs.size(); ++k) {
      if (group_of[k] != static_cast<int>(g)) continue;
      group_jobs.push_back(jobs[k]);
      index.push_back(k);
    }
    if (group_jobs.empty()) continue;
    BatchOptions options = folder_options(input.options, input.corrections, folder_of[index.front()]);
    options.stop = stop;
    if (progress)
      options.on_progress = [&progress, done_before, total](int done, int) { progress(done_before + done, total); };
    CachedBatch done = process_session_cached(group_jobs, options, cache);
    for (auto& w : done.cache_warnings) batch.cache_warnings.push_back(std::move(w));
    for (size_t i = 0; i < index.size(); ++i) {
      outcomes[index[i]] = std::move(done.outcomes[i]);
      from_cache[index[i]] = done.from_cache[i];
    }
    done_before += static_cast<int>(group_jobs.size());
  }
  for (size_t k = 0; k < jobs.size(); ++k) {
    ReviewTrial t;
    t.folder = folder_of[k];
    t.job = jobs[k];
    t.outcome = std::move(outcomes[k]);
    t.from_cache = from_cache[k];
    const std::string subject = folder_of[k].filename().empty() ? folder_of[k].parent_path().filename().string()
                                                                : folder_of[k].filename().string();
    t.row = trial_row(subject, t.job.trial, t.outcome.ok ? t.outcome.summary : nlohmann::json(), t.outcome.error,
                      t.outcome.cancelled);
    (t.from_cache ? batch.from_cache : batch.processed_now) += t.outcome.cancelled ? 0 : 1;
    batch.trials.push_back(std::move(t));
  }
  return batch;
}

void ReviewBatchJob::start(ReviewBatchInput input) {
  job_.start([in = std::move(input)](std::stop_token stop, JobChannel<ReviewBatchReport>& channel) {
    channel.set_stage("processing");
    return run_review_batch(in, stop, [&channel](int done, int total) { channel.set_progress(done, total); });
  });
}

}  // namespace lmc::ui
