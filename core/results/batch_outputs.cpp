#include "core/results/batch_outputs.h"

#include <utility>

#include "core/io/file_committer.h"
#include "core/results/trial_outputs.h"

namespace lmc {

std::vector<ProcessedTrial> process_and_write_batch(const std::vector<TrialSources>& jobs, BatchOptions options,
                                                    const std::filesystem::path& out) {
  std::filesystem::create_directories(out);
  FileCommitter committer;
  options.on_result = [&](const TrialAnalysis& r, const nlohmann::json& summary) {
    for (auto& file : trial_output_files(r, summary)) {
      committer.submit(out / file.name, std::move(file.contents), r.tag.trial);
    }
  };
  auto outcomes = process_batch(jobs, options);
  for (const auto& failure : committer.finish()) {
    for (auto& o : outcomes) {
      if (o.trial != failure.owner || !o.ok) continue;
      o.ok = false;
      o.error = failure.message;
    }
  }
  return outcomes;
}

}  // namespace lmc
