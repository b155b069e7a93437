#include "core/processing/trial_tag.h"

#include <cctype>
#include <filesystem>

namespace lmc {

std::string without_stage_suffix(std::string stem) {
  for (const std::string suffix : {".raw", ".resampled", ".raytraced"}) {
    if (stem.size() > suffix.size() && stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0) {
      stem.erase(stem.size() - suffix.size());
      break;
    }
  }
  return stem;
}

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

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

// Hand-written rather than std::regex: libstdc++'s regex trips -Wmaybe-uninitialized under the
// sanitizer build, and the scheme is simple.
TrialTag parse_trial_tag(const std::string& file_or_name) {
  TrialTag tag;
  tag.trial = trial_name_of(file_or_name);
  const auto us = tag.trial.find('_');
  if (us == std::string::npos) return tag;
  const std::string layout = lower(tag.trial.substr(0, us));
  if (layout == "naiv") {
    tag.layout = "initial";
  } else if (layout == "opti") {
    tag.layout = "optimized";
  } else {
    return tag;
  }
  const std::string rest = tag.trial.substr(us + 1);
  if (rest.size() < 4) return tag;
  const std::string digits = rest.substr(rest.size() - 3);
  const std::string motion = lower(rest.substr(0, rest.size() - 3));
  for (char c : digits) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return tag;
  }
  if (digits[0] != '1' && digits[0] != '2') return tag;
  if (motion != "static" && motion != "index" && motion != "thumb" && motion != "wrist" && motion != "trial")
    return tag;
  tag.motion = motion == "trial" ? "dynamic" : motion;
  tag.pose = digits[0] == '1' ? "horizontal" : "vertical";
  tag.repetition = std::stoi(digits.substr(1));
  tag.parsed = true;
  return tag;
}

}  // namespace lmc
