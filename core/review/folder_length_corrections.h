#pragma once
// Finger-length corrections chosen per folder of trials (one subject's session each): the
// Review tab and `lmc figures` process what they open with this one rule. A folder's correction
// applies to its trials after the default fusion; the reference fusion is never corrected (it stays
// the study's algorithm). Trials are processed through the cache in one run per correction in use,
// and the cache keys on the options, so corrected and plain results never mix.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/processing/batch.h"
#include "core/processing/length_correction.h"
#include "core/results/processing_cache.h"

namespace lmc {

// A subject's finger-length correction chosen for one folder: the file and what it holds.
struct FolderLengthCorrection {
  std::filesystem::path file;
  LengthCorrection correction;
};
using FolderLengthCorrections = std::map<std::filesystem::path, FolderLengthCorrection>;

// The options one folder's trials are processed with: `options` plus that folder's correction
// when there is one and the fusion is the default.
BatchOptions folder_options(const BatchOptions& options, const FolderLengthCorrections& corrections,
                            const std::filesystem::path& folder);

// Processes `jobs` (jobs[k] found in folder_of[k]) through the cache, each trial with its folder's
// options; outcomes come back in job order. options.stop and options.on_progress (counting every
// trial) are honoured. A note says when corrections were given with the reference fusion.
CachedBatch process_folders_cached(const std::vector<TrialSources>& jobs,
                                   const std::vector<std::filesystem::path>& folder_of, const BatchOptions& options,
                                   const FolderLengthCorrections& corrections, const ProcessingCache& cache,
                                   std::vector<std::string>* notes = nullptr);

// Which folders' lengths were corrected, and with which file, under "length_correction_files" of an
// export's parameters (the trials' own summaries carry the factors); nothing with the reference fusion.
void add_length_correction_files(nlohmann::json& parameters, FusionMethod method,
                                 const FolderLengthCorrections& corrections);

}  // namespace lmc
