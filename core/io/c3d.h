#pragma once
// C3D motion files (https://www.c3d.org; docs/formats.md): our own reader and writer for the 3-D
// point data, so a lab can use Vicon's native export instead of TRC. Supported: 512-byte blocks,
// header, parameter section with groups and parameters (POINT:USED, LABELS/LABELS2…, RATE, SCALE,
// DATA_START, FRAMES, UNITS; ANALOG:USED/RATE only to skip analog samples), integer (SCALE > 0) and
// floating-point (SCALE < 0) storage, Intel, DEC and MIPS processor formats. A point whose fourth
// word (residual) is negative is missing and read as NaN. Header values are copies; parameters are
// the master when both exist. Malformed files are rejected with an lmc::Error naming the file and
// the byte offset of the problem.
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/io/vicon_mapping.h"

namespace lmc {

enum class C3dProcessor { kIntel = 84, kDec = 85, kMips = 86 };

struct C3dData {
  C3dProcessor processor = C3dProcessor::kIntel;
  bool float_storage = true;
  double point_scale = -1.0;  // as in the file: negative = float storage
  double point_rate_hz = 100.0;
  std::string units = "mm";
  int first_frame = 1;
  int analog_per_frame = 0;  // analog samples (all channels) per point frame; skipped
  std::vector<std::string> labels;
  // POINT:DESCRIPTIONS, one per label when the file has them (written when not empty).
  std::vector<std::string> descriptions;
  // MANUFACTURER:COMPANY, SOFTWARE and VERSION_LABEL: who wrote the file (written when not empty).
  std::string manufacturer_company, manufacturer_software, manufacturer_version;
  // Every parameter the file has, as "GROUP:NAME" in file order (read only).
  std::vector<std::string> parameter_names;
  // positions[frame][point] in the file's units; NaN where the point is missing.
  std::vector<std::vector<Eigen::Vector3d>> positions;
  std::vector<std::string> warnings;

  int frame_count() const { return static_cast<int>(positions.size()); }
  int point_count() const { return static_cast<int>(labels.size()); }
  // Points in millimetres (units "mm", "cm", "m") with their labels, for the Vicon mapping.
  MarkerSeries to_marker_series(const std::string& source) const;
};

C3dData read_c3d(const std::filesystem::path& path);
C3dData parse_c3d(const std::vector<std::uint8_t>& bytes, const std::string& source);

struct C3dWriteOptions {
  C3dProcessor processor = C3dProcessor::kIntel;
  bool float_storage = true;
  double int_scale = 0.1;  // mm per integer step when float_storage is false
};

// Writes POINT (USED, SCALE, RATE, DATA_START, FRAMES, UNITS, LABELS[, LABELS2 …],
// DESCRIPTIONS[, DESCRIPTIONS2 …]), ANALOG (USED 0), TRIAL (ACTUAL_START_FIELD, ACTUAL_END_FIELD,
// CAMERA_RATE) and MANUFACTURER (COMPANY, SOFTWARE, VERSION_LABEL); missing points (any NaN
// coordinate) get residual −1.
std::vector<std::uint8_t> write_c3d_bytes(const C3dData& data, const C3dWriteOptions& options = {});
void save_c3d(const std::filesystem::path& path, const C3dData& data, const C3dWriteOptions& options = {});  // atomic

}  // namespace lmc
