#pragma once
// A study as a BIDS-motion dataset (BIDS 1.9, the motion datatype): one subject per subject id (two session folders of
// one id are its ses-1 and ses-2), each accepted trial a recording per tracking system (each controller, the fused
// hand, Vicon when present). One implementation for `lmc export bids` and the Review tab's Export…; the layout of the
// dataset and its naming are described in docs/export.md.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/export/trial_points.h"
#include "core/processing/batch.h"

namespace lmc {

struct BidsExportRequest {
  // Subject session folders, or folders holding several of them (a study).
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path out_dir;  // the dataset's root (created when missing)
  // Subject ids replaced by sub-01, sub-02, … with the key (id → label) written to `anonymise_key`,
  // which must lie outside `out_dir`.
  bool anonymise = false;
  std::filesystem::path anonymise_key;
  bool force = false;  // write into an existing non-empty dataset folder, replacing its files
  BatchOptions session;
  // One line per trial written or left out, for a command's progress lines.
  std::function<void(const std::string& line)> on_trial;
  // Before each trial and once at the end: trials done, trials planned.
  std::function<void(int done, int total)> on_progress;
  // Polled before each trial: true stops there; what is written stays complete and valid on its own
  // (the dataset-level files are written first and describe only what is there).
  std::function<bool()> should_stop;
};

struct BidsExportReport {
  std::filesystem::path dataset;
  int subjects = 0;
  int trials = 0;                  // trials written
  int left_out = 0;                // trials (or inputs) not exported
  std::vector<std::string> notes;  // what was left out or is partial, and why
  bool cancelled = false;
};

// Throws lmc::Error when no session could be found at all, or the dataset folder is not empty and
// `force` is not set (nothing written then).
BidsExportReport export_bids(const BidsExportRequest& request);

}  // namespace lmc
