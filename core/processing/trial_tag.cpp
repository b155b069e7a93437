#include "core/processing/trial_tag.h"

#include <filesystem>
#include <regex>

namespace lmc {

std::string trial_name_of(const std::string& file_name) {
  std::string s = std::filesystem::path(file_name).filename().string();
  // Strip extensions we know (possibly two: ".raw.txt").
  for (int k = 0; k < 2; ++k) {
    const auto dot = s.rfind('.');
    if (dot == std::string::npos) break;
    const std::string ext = s.substr(dot);
    if (ext == ".txt" || ext == ".tsv" || ext == ".trc" || ext == ".c3d" || ext == ".raw" || ext == ".resampled" ||
        ext == ".raytraced" || ext == ".lmc" || ext == ".TRC" || ext == ".C3D") {
      s.erase(dot);
    } else {
      break;
    }
  }
  for (const char* prefix : {"Interp_", "LMC_"}) {
    const std::string p(prefix);
    if (s.rfind(p, 0) == 0 && s.size() > p.size()) s.erase(0, p.size());
  }
  return s;
}

TrialTag parse_trial_tag(const std::string& file_or_name) {
  TrialTag tag;
  tag.trial = trial_name_of(file_or_name);
  static const std::regex scheme(R"(^(Naiv|Opti)_(Static|Index|Thumb|Wrist|Trial)([12])([0-9]{2})$)", std::regex::icase);
  std::smatch m;
  if (!std::regex_match(tag.trial, m, scheme)) {
    static const std::regex layout_only(R"(^(Naiv|Opti)_.*)", std::regex::icase);
    if (std::regex_match(tag.trial, m, layout_only)) tag.layout = (m[1].str()[0] == 'N' || m[1].str()[0] == 'n') ? "initial" : "optimized";
    return tag;
  }
  tag.layout = (m[1].str()[0] == 'N' || m[1].str()[0] == 'n') ? "initial" : "optimized";
  std::string motion = m[2].str();
  for (char& c : motion) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  tag.motion = motion == "trial" ? "dynamic" : motion;
  tag.pose = m[3].str() == "1" ? "horizontal" : "vertical";
  tag.repetition = std::stoi(m[4].str());
  tag.parsed = true;
  return tag;
}

}  // namespace lmc
