#pragma once
// The one real trial with Vicon that the study shared (reference-data/validation:
// Interp_LMC_Naiv_Static101.txt with Naiv_Static101.trc, recorded on paper-initial), loaded the
// way processing takes it. A test checks the files first with LMC_REQUIRE_REFERENCE_FILE, so a
// clone without the study's data folder skips it and says why.
#include <filesystem>

#include "core/hand/hand_track.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/vicon_mapping.h"
#include "core/processing/batch.h"  // load_vicon_markers: TRC or C3D by extension
#include "tests/support/reference_data.h"

namespace lmc::test {

struct SharedRealTrialFiles {
  std::filesystem::path lmc, trc;
};

inline SharedRealTrialFiles shared_real_trial_files() {
  const auto dir = reference_file("validation");
  return {dir / "Interp_LMC_Naiv_Static101.txt", dir / "Naiv_Static101.trc"};
}

struct SharedRealTrial {
  LmcRecording recording;
  HandTrack vicon;  // the TRC through the project's Vicon → LMC marker mapping
  Layout layout;    // paper-initial
};

inline SharedRealTrial load_shared_real_trial() {
  const SharedRealTrialFiles files = shared_real_trial_files();
  return {read_lmc_recording(files.lmc),
          apply_vicon_mapping(load_vicon_mapping(asset_file("mappings/vicon-26-to-lmc.json")),
                              load_vicon_markers(files.trc)),
          load_layout(asset_file("layouts/paper-initial.json"))};
}

}  // namespace lmc::test
