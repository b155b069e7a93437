#include "devices/sim/study_errors.h"

#include <nlohmann/json.hpp>

namespace lmc::devices {
namespace study_errors_detail {

constexpr const char* kDigitNames[5] = {"thumb", "index", "middle", "ring", "pinky"};

}  // namespace study_errors_detail

HandModelError study_errors_hand_model() {
  // Where each number comes from: devices/README.md, "Simulator: study errors".
  HandModelError e;
  e.enabled = true;
  // Median controller / Vicon finger length on the shared trial (Naiv_Static101, paper-initial),
  // 0.867, 0.844, 0.813, 0.793, 0.763, then moved by ≤ 0.017 so that on the simulator's default
  // hand (190 mm) the median controller's bias in mm matches that trial's. Only the bones that make
  // up the measured finger length are scaled: the fingers' metacarpals, the thumb's zero-length
  // Meta→Proxi bone and its Proxi→Inter bone (the anatomical metacarpal) are not measured.
  e.segment_scale = {{{1, 1, 0.876, 0.876},
                      {1, 0.861, 0.861, 0.861},
                      {1, 0.818, 0.818, 0.818},
                      {1, 0.800, 0.800, 0.800},
                      {1, 0.760, 0.760, 0.760}}};
  e.scale_spread = 0.06;
  // Dorsal skin marker above the joint centre: half the finger's thickness at that joint plus the
  // 2 mm radius of the study's 4 mm markers (Meta points are Vicon hand markers, left as they are).
  e.joint_offset_mm = {0, 12, 10, 8, 5};
  e.joint_offset_spread_mm = 0.5;
  return e;
}

HandModelError hand_model_error_from_json(const JsonReader& r, HandModelError e) {
  r.require_object();
  r.only_keys({"enabled", "segment_scale", "scale_spread", "joint_offset_mm", "joint_offset_spread_mm"});
  if (r.has("enabled")) e.enabled = r.at("enabled").boolean();
  if (r.has("segment_scale")) {
    const JsonReader s = r.at("segment_scale");
    s.require_object();
    s.only_keys({"thumb", "index", "middle", "ring", "pinky"});
    for (size_t dg = 0; dg < 5; ++dg) {
      if (!s.has(study_errors_detail::kDigitNames[dg])) continue;
      const JsonReader bones = s.at(study_errors_detail::kDigitNames[dg]);
      if (bones.array_size() != 4) bones.fail("expected 4 scales (Meta→Proxi, Proxi→Inter, Inter→Dist, Dist→End)");
      for (size_t b = 0; b < 4; ++b) {
        const double v = bones.at(b).number();
        if (!(v > 0)) bones.at(b).fail("must be > 0");
        e.segment_scale[dg][b] = v;
      }
    }
  }
  e.scale_spread = r.number_or("scale_spread", e.scale_spread);
  if (!(e.scale_spread >= 0 && e.scale_spread < 0.5)) r.at("scale_spread").fail("must be between 0 and 0.5");
  if (r.has("joint_offset_mm")) {
    const JsonReader o = r.at("joint_offset_mm");
    if (o.array_size() != 5) o.fail("expected 5 offsets in mm (Meta, Proxi, Inter, Dist, End)");
    for (size_t j = 0; j < 5; ++j) e.joint_offset_mm[j] = o.at(j).number();
  }
  e.joint_offset_spread_mm = r.number_or("joint_offset_spread_mm", e.joint_offset_spread_mm);
  if (!(e.joint_offset_spread_mm >= 0)) r.at("joint_offset_spread_mm").fail("must be ≥ 0");
  return e;
}

nlohmann::json hand_model_error_to_json(const HandModelError& e) {
  nlohmann::json j;
  j["enabled"] = e.enabled;
  nlohmann::json scale = nlohmann::json::object();
  for (size_t dg = 0; dg < 5; ++dg) scale[study_errors_detail::kDigitNames[dg]] = e.segment_scale[dg];
  j["segment_scale"] = scale;
  j["scale_spread"] = e.scale_spread;
  j["joint_offset_mm"] = e.joint_offset_mm;
  j["joint_offset_spread_mm"] = e.joint_offset_spread_mm;
  return j;
}

}  // namespace lmc::devices
