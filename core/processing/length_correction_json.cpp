#include "core/processing/length_correction_json.h"

#include <vector>

#include "core/common/error.h"
#include "core/io/atomic_write.h"
#include "core/io/json_checked.h"

namespace lmc {
namespace {

constexpr const char* kLengthCorrectionFormat = "lmc-length-correction";

nlohmann::json finger_array_json(const std::array<double, kNumFingers>& v) {
  return nlohmann::json(std::vector<double>(v.begin(), v.end()));
}

std::array<double, kNumFingers> read_finger_array(const JsonReader& r) {
  if (r.array_size() != kNumFingers) r.fail("expected 5 numbers (thumb, index, middle, ring, pinky)");
  std::array<double, kNumFingers> v{};
  for (size_t f = 0; f < kNumFingers; ++f) v[f] = r.at(f).number();
  return v;
}

}  // namespace

nlohmann::json length_correction_json(const LengthCorrection& c) {
  nlohmann::json j;
  j["format"] = kLengthCorrectionFormat;
  j["version"] = 1;
  j["method"] = "default";
  j["subject"] = c.subject;
  j["source"] = length_source_name(c.source);
  j["fit_trial"] = c.fit_trial;
  j["fit_lmc_file"] = c.fit_lmc_file;
  if (c.source == LengthSource::kVicon) {
    j["fit_vicon_file"] = c.fit_vicon_file;
  } else {
    j["hand_length_mm"] = c.hand_length_mm;
    j["hand_breadth_mm"] = c.hand_breadth_mm;
  }
  j["fit_frames"] = c.fit_frames;
  j["fingers"] = {"thumb", "index", "middle", "ring", "pinky"};
  j["fused_mm"] = finger_array_json(c.fused_mm);
  j["target_mm"] = finger_array_json(c.target_mm);
  j["factor"] = finger_array_json(c.factor);
  return j;
}

LengthCorrection length_correction_from_json(const nlohmann::json& j, const std::string& source) {
  const JsonReader r(j, source);
  r.only_keys({"format", "version", "method", "subject", "source", "fit_trial", "fit_lmc_file", "fit_vicon_file",
               "hand_length_mm", "hand_breadth_mm", "fit_frames", "fingers", "fused_mm", "target_mm", "factor"});
  if (r.string("format") != kLengthCorrectionFormat)
    r.at("format").fail(std::string("expected \"") + kLengthCorrectionFormat + "\"");
  if (r.at("version").integer() != 1) r.at("version").fail("unknown version (this program reads version 1)");
  // The factors were fitted on the default fusion's output; on another method they mean nothing.
  if (r.string("method") != "default")
    r.at("method").fail("a length correction is fitted on and applied to the default fusion only");
  LengthCorrection c;
  c.subject = r.string("subject");
  const std::string kind = r.string("source");
  if (kind == "vicon") {
    c.source = LengthSource::kVicon;
    c.fit_vicon_file = r.string_or("fit_vicon_file", "");
  } else if (kind == "hand_dimensions") {
    c.source = LengthSource::kHandDimensions;
    c.hand_length_mm = r.number("hand_length_mm");
    c.hand_breadth_mm = r.number("hand_breadth_mm");
  } else {
    r.at("source").fail("expected \"vicon\" or \"hand_dimensions\"");
  }
  c.fit_trial = r.string("fit_trial");
  c.fit_lmc_file = r.string_or("fit_lmc_file", "");
  c.fit_frames = r.has("fit_frames") ? r.at("fit_frames").integer() : 0;
  if (r.has("fused_mm")) c.fused_mm = read_finger_array(r.at("fused_mm"));
  if (r.has("target_mm")) c.target_mm = read_finger_array(r.at("target_mm"));
  c.factor = read_finger_array(r.at("factor"));
  check_length_factors(c.factor, source + ": at /factor");
  return c;
}

LengthCorrection read_length_correction(const std::filesystem::path& path) {
  return length_correction_from_json(read_json_file(path), path.string());
}

void write_length_correction(const std::filesystem::path& path, const LengthCorrection& c) {
  write_file_atomically(path, length_correction_json(c).dump(2) + "\n");
}

}  // namespace lmc
