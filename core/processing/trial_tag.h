#pragma once
// What a trial's name says about it. The study names trials `<Layout>_<Motion><P><RR>`
// (e.g. `Naiv_Static101`, core/processing/README.md; the LMC file adds `LMC_` / `Interp_LMC_`):
//   Layout  Naiv → "initial", Opti → "optimized"
//   Motion  Static → "static", Index → "index", Thumb → "thumb", Wrist → "wrist" (flexion);
//           the authors' sample files also use "Trial" for a dynamic trial → "dynamic"
//   P       pose: 1 → "horizontal" (palm down), 2 → "vertical" (palm facing left)
//   RR      repetition 01…99
// Anything else still processes; its tag is "unknown" for the fields it lacks.
#include <string>

namespace lmc {

struct TrialTag {
  std::string trial;  // the trial name proper, e.g. "Naiv_Static101"
  std::string layout = "unknown";
  std::string pose = "unknown";
  std::string motion = "unknown";
  int repetition = 0;
  bool parsed = false;  // the whole scheme matched
};

// Accepts a file name or stem: "Interp_LMC_Naiv_Static101.txt", "LMC_Naiv_Static101.raw.txt",
// "Naiv_Static101.trc", "Naiv_Static101".
TrialTag parse_trial_tag(const std::string& file_or_name);

// The trial name of an LMC or Vicon file: the stem with `Interp_`, `LMC_` prefixes and
// `.raw`, `.resampled`, `.raytraced`, `.lmc` suffixes removed.
std::string trial_name_of(const std::string& file_name);

// `stem` without one trailing stage suffix (`.raw`, `.resampled`, `.raytraced`), prefixes kept.
std::string without_stage_suffix(std::string stem);

}  // namespace lmc
