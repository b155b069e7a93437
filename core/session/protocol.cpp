#include "core/session/protocol.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "core/common/error.h"
#include "core/common/paths.h"
#include "core/common/safe_name.h"
#include "core/io/json_checked.h"
#include "core/processing/measures.h"
#include "core/session/protocol_quality_json.h"

namespace fs = std::filesystem;

namespace lmc {
namespace {

constexpr const char* kProtocolFormat = "lmc-protocol";

bool known_angle(const std::string& joint) {
  for (int a = 0; a < kNumAngles; ++a)
    if (angle_name(a) == joint) return true;
  return false;
}

std::string angle_list() {
  std::string s;
  for (int a = 0; a < kNumAngles; ++a) s += (a ? ", " : "") + std::string(angle_name(a));
  return s;
}

// A key that becomes part of every trial name is held to the file-name rule.
std::string checked_key(const JsonReader& r, const char* field, const std::string& what) {
  const JsonReader k = r.at(field);
  const std::string key = k.string();
  if (auto why = safe_name_problem(key, what); !why.empty()) k.fail(why);
  return key;
}

TrialType trial_type_from_json(const JsonReader& r, const QualityThresholds& defaults) {
  r.only_keys({"key", "sim_motion", "duration_s", "operator_cue", "subject_cue", "rom", "quality"});
  TrialType t;
  t.key = checked_key(r, "key", "trial type key");
  if (t.key.find('_') != std::string::npos)
    r.at("key").fail("a trial type key must not contain '_' (it ends the layout part of trial names)");
  t.sim_motion = r.string("sim_motion");
  const JsonReader d = r.at("duration_s");
  t.duration_s = d.number();
  if (!(t.duration_s > 0 && t.duration_s <= 3600)) d.fail("must be more than 0 and at most 3600 s");
  t.operator_cue = r.string("operator_cue");
  t.subject_cue = r.string("subject_cue");
  if (r.has("rom")) {
    const JsonReader rom = r.at("rom");
    for (size_t i = 0; i < rom.array_size(); ++i) {
      const JsonReader e = rom.at(i);
      e.only_keys({"joint", "expected_deg"});
      RomExpectation x;
      x.joint = e.string("joint");
      if (!known_angle(x.joint)) e.at("joint").fail("unknown joint '" + x.joint + "' (one of: " + angle_list() + ")");
      const JsonReader deg = e.at("expected_deg");
      x.expected_deg = deg.number();
      if (!(x.expected_deg > 0 && x.expected_deg <= 180)) deg.fail("must be more than 0 and at most 180 degrees");
      t.rom.push_back(x);
    }
  }
  t.quality = r.has("quality") ? quality_thresholds_from_json(r.at("quality"), defaults) : defaults;
  return t;
}

}  // namespace

Protocol protocol_from_json(const nlohmann::json& j, const std::string& source) {
  const JsonReader r(j, source);
  r.only_keys({"format", "format_version", "name", "description", "repetitions", "layouts", "poses", "quality",
               "trial_types", "calibration"});
  if (r.string("format") != kProtocolFormat) r.at("format").fail(std::string("expected \"") + kProtocolFormat + "\"");
  if (r.at("format_version").integer() != 1) r.at("format_version").fail("this version reads format_version 1");
  Protocol p;
  p.name = checked_key(r, "name", "protocol name");
  p.description = r.string_or("description", "");
  const JsonReader reps = r.at("repetitions");
  p.repetitions = reps.integer();
  if (p.repetitions < 1 || p.repetitions > 99) reps.fail("must be 1…99 (two digits of the trial name)");

  std::set<std::string> seen;
  const JsonReader layouts = r.at("layouts");
  if (layouts.array_size() == 0) layouts.fail("a protocol needs at least one layout");
  for (size_t i = 0; i < layouts.array_size(); ++i) {
    const JsonReader e = layouts.at(i);
    e.only_keys({"key", "layout"});
    ProtocolLayout l{checked_key(e, "key", "layout key"), e.string("layout")};
    if (l.key.find('_') != std::string::npos) e.at("key").fail("a layout key must not contain '_'");
    if (!seen.insert("layout:" + l.key).second) e.at("key").fail("layout key '" + l.key + "' appears twice");
    p.layouts.push_back(l);
  }
  const JsonReader poses = r.at("poses");
  if (poses.array_size() == 0) poses.fail("a protocol needs at least one pose");
  for (size_t i = 0; i < poses.array_size(); ++i) {
    const JsonReader e = poses.at(i);
    e.only_keys({"key", "code", "cue"});
    ProtocolPose pose;
    pose.key = e.string("key");
    if (pose.key != "horizontal" && pose.key != "vertical") e.at("key").fail("expected \"horizontal\" or \"vertical\"");
    pose.code = e.at("code").integer();
    if (pose.code < 1 || pose.code > 9) e.at("code").fail("must be one digit 1…9");
    pose.cue = e.string_or("cue", "");
    if (!seen.insert("pose:" + std::to_string(pose.code)).second) e.at("code").fail("pose code appears twice");
    p.poses.push_back(pose);
  }
  const QualityThresholds defaults =
      r.has("quality") ? quality_thresholds_from_json(r.at("quality"), {}) : QualityThresholds{};
  const JsonReader types = r.at("trial_types");
  if (types.array_size() == 0) types.fail("a protocol needs at least one trial type");
  for (size_t i = 0; i < types.array_size(); ++i) {
    TrialType t = trial_type_from_json(types.at(i), defaults);
    if (!seen.insert("type:" + t.key).second)
      types.at(i).at("key").fail("trial type key '" + t.key + "' appears twice");
    p.trial_types.push_back(std::move(t));
  }
  if (r.has("calibration")) {
    const JsonReader c = r.at("calibration");
    c.only_keys({"duration_s", "operator_cue", "subject_cue"});
    CalibrationStep step;
    if (c.has("duration_s")) {
      const JsonReader d = c.at("duration_s");
      step.duration_s = d.number();
      if (!(step.duration_s >= 2 && step.duration_s <= 60)) d.fail("must be 2…60 s (a still hand for a few seconds)");
    }
    step.operator_cue = c.string_or("operator_cue", step.operator_cue);
    step.subject_cue = c.string_or("subject_cue", step.subject_cue);
    p.calibration = step;
  }
  // Every name the plan will produce must be a valid file name; check once, here, so an error
  // names the protocol file rather than surfacing mid-session.
  for (const PlannedTrial& t : plan_trials(p))
    if (auto why = safe_name_problem(t.name, "trial name '" + t.name + "'"); !why.empty()) r.fail(why);
  return p;
}

nlohmann::json protocol_to_json(const Protocol& p) {
  nlohmann::json j = {{"format", kProtocolFormat},
                      {"format_version", 1},
                      {"name", p.name},
                      {"description", p.description},
                      {"repetitions", p.repetitions}};
  j["layouts"] = nlohmann::json::array();
  for (const auto& l : p.layouts) j["layouts"].push_back({{"key", l.key}, {"layout", l.layout}});
  j["poses"] = nlohmann::json::array();
  for (const auto& pose : p.poses) j["poses"].push_back({{"key", pose.key}, {"code", pose.code}, {"cue", pose.cue}});
  j["trial_types"] = nlohmann::json::array();
  for (const auto& t : p.trial_types) {
    nlohmann::json rom = nlohmann::json::array();
    for (const auto& x : t.rom) rom.push_back({{"joint", x.joint}, {"expected_deg", x.expected_deg}});
    j["trial_types"].push_back({{"key", t.key},
                                {"sim_motion", t.sim_motion},
                                {"duration_s", t.duration_s},
                                {"operator_cue", t.operator_cue},
                                {"subject_cue", t.subject_cue},
                                {"rom", rom},
                                {"quality", quality_thresholds_to_json(t.quality)}});
  }
  if (p.calibration) {
    j["calibration"] = {{"duration_s", p.calibration->duration_s},
                        {"operator_cue", p.calibration->operator_cue},
                        {"subject_cue", p.calibration->subject_cue}};
  }
  return j;
}

std::string calibration_trial_name(const std::string& layout_key, int attempt) {
  char digits[8];
  std::snprintf(digits, sizeof digits, "%02d", std::clamp(attempt, 0, 99));
  return "Calib_" + layout_key + digits;
}

fs::path protocol_path(const std::string& name_or_path) {
  const fs::path as_path(name_or_path);
  if (name_or_path.find('/') != std::string::npos || as_path.extension() == ".json") return as_path;
  if (auto why = safe_name_problem(name_or_path, "protocol name"); !why.empty()) throw Error(why);
  const fs::path shipped = assets_dir() / "protocols" / (name_or_path + ".json");
  if (!fs::exists(shipped)) {
    std::string known;
    for (const auto& name : shipped_protocol_names()) known += (known.empty() ? "" : ", ") + name;
    throw Error("no protocol named '" + name_or_path + "' (shipped: " + (known.empty() ? "none found" : known) +
                "; or give a .json path)");
  }
  return shipped;
}

std::vector<std::string> shipped_protocol_names() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(assets_dir() / "protocols", ec))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

Protocol load_protocol(const std::string& name_or_path) {
  const fs::path path = protocol_path(name_or_path);
  return protocol_from_json(read_json_file(path), path.string());
}

namespace {

// splitmix64: a tiny generator with a fixed definition, so a counterbalancing seed gives the
// same order everywhere (std::shuffle's algorithm is left to the library).
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
};

std::vector<int> order(int n, SplitMix64* rng) {
  std::vector<int> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<size_t>(i)] = i;
  if (rng != nullptr)
    for (int i = n - 1; i > 0; --i)
      std::swap(v[static_cast<size_t>(i)], v[rng->next() % static_cast<std::uint64_t>(i + 1)]);
  return v;
}

// Built in place: GCC 12's Release build warned of a false -Wstringop-overflow in the inlined
// concatenation of a "0" literal with std::to_string.
std::string two_digits(int n) {
  std::string s = std::to_string(n);
  if (n >= 0 && n < 10) s.insert(s.begin(), '0');
  return s;
}

}  // namespace

std::vector<PlannedTrial> plan_trials(const Protocol& p, std::optional<std::uint64_t> seed) {
  SplitMix64 rng{seed.value_or(0)};
  SplitMix64* shuffle = seed ? &rng : nullptr;
  std::vector<PlannedTrial> plan;
  for (int li : order(static_cast<int>(p.layouts.size()), shuffle)) {
    const ProtocolLayout& layout = p.layouts[static_cast<size_t>(li)];
    for (int pi : order(static_cast<int>(p.poses.size()), shuffle)) {
      const ProtocolPose& pose = p.poses[static_cast<size_t>(pi)];
      for (int ti : order(static_cast<int>(p.trial_types.size()), shuffle)) {
        const TrialType& type = p.trial_types[static_cast<size_t>(ti)];
        for (int rep = 1; rep <= p.repetitions; ++rep) {
          PlannedTrial t;
          t.index = static_cast<int>(plan.size());
          t.name = layout.key + "_" + type.key + std::to_string(pose.code) + two_digits(rep);
          t.layout_key = layout.key;
          t.pose = pi;
          t.trial_type = ti;
          t.repetition = rep;
          t.sim_motion = pose.key + "/" + type.sim_motion;
          plan.push_back(std::move(t));
        }
      }
    }
  }
  return plan;
}

}  // namespace lmc
