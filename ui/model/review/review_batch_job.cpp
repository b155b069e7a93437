#include "ui/model/review/review_batch_job.h"

#include <map>

#include "core/results/processing_cache.h"
#include "core/session/session_folder.h"
#include "core/session/session_trials.h"

namespace lmc::ui {

namespace {

// A trial's subject is the person, not the folder: a subject session's id from its manifest (two
// folders of one subject id are one subject), else the folder's name for a folder of loose trials.
std::string subject_of(const TrialSources& job, const std::filesystem::path& folder,
                       std::map<std::filesystem::path, std::string>& ids) {
  const std::filesystem::path dir = job.lmc.parent_path();
  if (const auto it = ids.find(dir); it != ids.end()) return it->second;
  std::string id;
  if (is_session_folder(dir)) {
    try {
      id = read_session_state(dir).subject().subject_id;
    } catch (const std::exception&) {
      id.clear();  // unreadable here: the batch's notes say why; the folder names it meanwhile
    }
  }
  if (id.empty())
    id = folder.filename().empty() ? folder.parent_path().filename().string() : folder.filename().string();
  ids.emplace(dir, id);
  return id;
}

}  // namespace

ReviewBatch run_review_batch(const ReviewBatchInput& input, std::stop_token stop,
                             const std::function<void(int done, int total)>& progress) {
  ReviewBatch batch;
  std::vector<lmc::TrialSources> jobs;
  std::vector<std::filesystem::path> folder_of;
  for (const auto& folder : input.folders) {
    try {
      auto found = trial_sources_for_input(folder, std::nullopt, &batch.notes);
      for (auto& j : found) {
        jobs.push_back(std::move(j));
        folder_of.push_back(folder);
      }
    } catch (const std::exception& e) {
      // One unreadable folder must not hide the others.
      batch.notes.push_back(e.what());
    }
  }
  BatchOptions options = input.options;
  options.stop = stop;
  if (progress) options.on_progress = progress;
  CachedBatch done = process_folders_cached(jobs, folder_of, options, input.corrections,
                                            ProcessingCache(input.cache_dir), &batch.notes);
  batch.cache_warnings = std::move(done.cache_warnings);
  std::map<std::filesystem::path, std::string> subject_ids;  // by session folder: each read once
  for (size_t k = 0; k < jobs.size(); ++k) {
    ReviewTrial t;
    t.folder = folder_of[k];
    t.job = jobs[k];
    t.outcome = std::move(done.outcomes[k]);
    t.from_cache = done.from_cache[k];
    const std::string subject = subject_of(t.job, folder_of[k], subject_ids);
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
