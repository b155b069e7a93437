#pragma once
// TRC marker files (Motion Analysis "Track Row Column", as exported by Vicon; docs/formats.md).
// Tab-separated: PathFileType line, header keys, header values, `Frame# Time <marker> …`,
// `X1 Y1 Z1 …`, then one row per frame. Missing markers are empty cells (also tolerated: NaN,
// nan); they are read as NaN. Frame count comes from the rows; a disagreeing header is a warning.
#include <Eigen/Core>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace lmc {

struct TrcData {
  double data_rate_hz = 100.0;
  double camera_rate_hz = 100.0;
  std::string units = "mm";  // "mm" or "m"; values are kept as written (see to_millimetres)
  int orig_data_start_frame = 1;
  std::vector<std::string> marker_names;
  std::vector<int> frame_numbers;
  std::vector<double> times_s;
  // positions[f][m]; NaN where the marker is missing.
  std::vector<std::vector<Eigen::Vector3d>> positions;
  std::vector<std::string> warnings;

  int frame_count() const { return static_cast<int>(positions.size()); }
  int marker_count() const { return static_cast<int>(marker_names.size()); }
  int marker_index(const std::string& name) const;  // −1 when absent
  // Converts values to mm in place (units "m" → ×1000); throws for unknown units.
  void to_millimetres();
};

TrcData read_trc(const std::filesystem::path& path);
TrcData parse_trc(std::istream& in, const std::string& source_name);
TrcData parse_trc_text(std::string_view content, const std::string& source_name);
void write_trc(std::ostream& out, const TrcData& trc, const std::string& path_field = "");
void save_trc(const std::filesystem::path& path, const TrcData& trc);  // atomic

}  // namespace lmc
