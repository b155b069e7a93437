#pragma once
// The fitted length correction on disk (`lmc length-correction fit` writes it, `lmc process
// --length-correction` reads it): small JSON naming the subject, the trial it was fitted on and
// how, and the factors, so a figure made with it can say where its factors came from.
//
//   {"format": "lmc-length-correction", "version": 1, "method": "default", "subject": "S01",
//    "source": "vicon" | "hand_dimensions", "fit_trial": "Naiv_Static101", "fit_lmc_file": "…",
//    "fit_vicon_file": "…" (vicon), "hand_length_mm": …, "hand_breadth_mm": … (hand_dimensions),
//    "fit_frames": 200, "fingers": ["thumb", …], "fused_mm": [5], "target_mm": [5], "factor": [5]}
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/processing/length_correction.h"

namespace lmc {

nlohmann::json length_correction_json(const LengthCorrection& c);
// Throws lmc::Error naming `source` and the JSON path of anything missing, mistyped, unknown or
// out of range (a factor outside kMinLengthFactor…kMaxLengthFactor).
LengthCorrection length_correction_from_json(const nlohmann::json& j, const std::string& source);

LengthCorrection read_length_correction(const std::filesystem::path& path);
// Written atomically (core/io/atomic_write.h): a half-written file is never read back.
void write_length_correction(const std::filesystem::path& path, const LengthCorrection& c);

}  // namespace lmc
