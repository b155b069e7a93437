#pragma once
// A batch of trials processed and its outputs written: what `lmc process` runs and what
// `lmc bench --processing` times. Each trial's files are formatted on the thread that processed it
// and written by a FileCommitter (core/io/file_committer.h), so no processing thread waits for the
// disk; a file that cannot be written fails its trial, naming the file.
#include <filesystem>
#include <vector>

#include "core/processing/batch.h"

namespace lmc {

// `options.on_result` is replaced by the writer. The folder is created if needed.
std::vector<ProcessedTrial> process_and_write_batch(const std::vector<TrialSources>& jobs, BatchOptions options,
                                                    const std::filesystem::path& out);

}  // namespace lmc
