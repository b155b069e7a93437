#include "core/reports/session_report.h"

#include <cmath>
#include <sstream>
#include <tuple>

#include "core/common/csv_cell.h"
#include "core/common/number_format.h"
#include "core/hand/hand_track.h"
#include "core/processing/measures.h"
#include "core/results/summary_reading.h"
#include "core/results/trial_outputs.h"

namespace lmc {

MeanSd mean_sd(const std::vector<double>& v) {
  double s = 0, s2 = 0;
  int n = 0;
  for (double x : v) {
    if (!std::isfinite(x)) continue;
    s += x;
    s2 += x * x;
    ++n;
  }
  MeanSd r{kNaN, kNaN, n};
  if (n > 0) r.mean = s / n;
  if (n > 1) r.sd = std::sqrt(std::max(0.0, (s2 - s * s / n) / (n - 1)));
  return r;
}

namespace {

double json_number_or_nan(const nlohmann::json& j) {
  return j.is_number() ? j.get<double>() : kNaN;
}
double at(const nlohmann::json& j, const char* key, size_t k) {
  return summary_element(j, key, k);
}

std::string three_decimals(double v) {
  return format_fixed(v, 3);
}
// A missing mean or SD (no value, or a single value has no SD) is written "n/a", never "nan" or 0.
std::string mean_pm_sd(const MeanSd& m, int d = 2) {
  const auto part = [d](double v) { return std::isfinite(v) ? format_fixed(v, d) : std::string("n/a"); };
  return part(m.mean) + " ± " + part(m.sd);
}

using Group = std::tuple<std::string, std::string, std::string>;  // layout, pose, motion

constexpr const char* kFingers[] = {"thumb", "index", "middle", "ring", "pinky"};

// Every trial's values, per (layout, pose, motion) group and pooled over all trials.
struct GroupValues {
  std::vector<double> finger_lmc[kNumFingers], finger_vicon[kNumFingers], finger_diff[kNumFingers];
  std::vector<double> rom_lmc[kNumAngles], rom_vicon[kNumAngles], rom_diff[kNumAngles], angle_diff[kNumAngles];
  std::map<std::string, std::vector<double>> vis;  // device → per-finger rates
  int trials = 0, with_vicon = 0;
};
struct ReportValues {
  std::map<Group, GroupValues> groups;
  std::vector<double> all_finger_diff, all_rom_diff, all_angle_diff;
  std::map<std::string, std::vector<double>> vis_by_layout;
};

std::string trials_csv_header() {
  std::ostringstream trials;
  trials << "subject,trial,layout,pose,motion,repetition,method,frames,has_vicon";
  for (const char* f : kFingers) trials << ",lmc_" << f << "_mm";
  for (const char* f : kFingers) trials << ",vicon_" << f << "_mm";
  for (int a = 0; a < kNumAngles; ++a) trials << ",lmc_rom_" << angle_name(a) << "_deg";
  for (int a = 0; a < kNumAngles; ++a) trials << ",vicon_rom_" << angle_name(a) << "_deg";
  trials << ",lag_frames,lag_correlation\n";
  return trials.str();
}

// One trial's summary into its group's values and the pooled differences.
void collect_trial_values(const nlohmann::json& s, const Group& g, GroupValues& acc, ReportValues& all) {
  const bool vic = summary_has_vicon(s);
  const auto& lmc = s.value("lmc", nlohmann::json::object());
  const auto vicon = vic ? s["vicon"] : nlohmann::json::object();
  for (size_t k = 0; k < kNumFingers; ++k) {
    acc.finger_lmc[k].push_back(at(lmc, "finger_mean_mm", k));
    if (vic) {
      acc.finger_vicon[k].push_back(at(vicon, "finger_mean_mm", k));
      const double d = at(lmc, "finger_mean_mm", k) - at(vicon, "finger_mean_mm", k);
      acc.finger_diff[k].push_back(d);
      all.all_finger_diff.push_back(d);
    }
  }
  for (size_t k = 0; k < kNumAngles; ++k) {
    acc.rom_lmc[k].push_back(at(lmc, "angle_rom_deg", k));
    if (vic) {
      acc.rom_vicon[k].push_back(at(vicon, "angle_rom_deg", k));
      const double d = at(lmc, "angle_rom_deg", k) - at(vicon, "angle_rom_deg", k);
      acc.rom_diff[k].push_back(d);
      all.all_rom_diff.push_back(d);
      if (s.contains("comparison")) {
        const double d_angle = at(s["comparison"], "angle_diff_mean_deg", k);
        acc.angle_diff[k].push_back(d_angle);
        all.all_angle_diff.push_back(d_angle);
      }
    }
  }
  for (const auto& d : summary_visibility(s)) {
    for (const double r : d.rates) {
      acc.vis[d.device].push_back(r);
      all.vis_by_layout[std::get<0>(g)].push_back(r);
    }
  }
}

// The trial's row of trials.csv.
void write_trial_row(std::ostringstream& trials, const std::string& subject, const nlohmann::json& s, const Group& g) {
  const auto& tag = s.value("tag", nlohmann::json::object());
  const bool vic = summary_has_vicon(s);
  const auto& lmc = s.value("lmc", nlohmann::json::object());
  const auto vicon = vic ? s["vicon"] : nlohmann::json::object();
  trials << csv_cell(subject) << ',' << csv_cell(s.value("trial", "")) << ',' << std::get<0>(g) << ',' << std::get<1>(g)
         << ',' << std::get<2>(g) << ',' << tag.value("repetition", 0) << ',' << s.value("method", "") << ','
         << s.value("frames", 0) << ',' << (vic ? 1 : 0);
  for (size_t k = 0; k < kNumFingers; ++k) trials << ',' << three_decimals(at(lmc, "finger_mean_mm", k));
  for (size_t k = 0; k < kNumFingers; ++k) trials << ',' << three_decimals(vic ? at(vicon, "finger_mean_mm", k) : kNaN);
  for (size_t k = 0; k < kNumAngles; ++k) trials << ',' << three_decimals(at(lmc, "angle_rom_deg", k));
  for (size_t k = 0; k < kNumAngles; ++k) trials << ',' << three_decimals(vic ? at(vicon, "angle_rom_deg", k) : kNaN);
  const auto lag =
      s.contains("comparison") ? s["comparison"].value("lag", nlohmann::json::object()) : nlohmann::json::object();
  trials << ',' << (lag.value("clear", false) ? std::to_string(lag.value("frames", 0)) : std::string("nan")) << ','
         << three_decimals(lag.contains("correlation") ? json_number_or_nan(lag["correlation"]) : kNaN) << '\n';
}

// The Markdown's opening: counts and the differences pooled over every trial.
void write_report_overview(std::ostringstream& md, const SessionReport& rep, const ReportValues& all) {
  md << "# Processing report\n\n" << rep.trials << " trial(s), " << rep.trials_with_vicon << " with Vicon.\n\n";
  md << "Differences are LMC − Vicon (the paper quotes Vicon − LMC for finger length).\n\n";
  md << "* Finger length difference, all fingers and trials: " << mean_pm_sd(mean_sd(all.all_finger_diff))
     << " mm (n = " << mean_sd(all.all_finger_diff).n << ")\n";
  md << "* Joint angle difference (per frame, averaged per trial), all joints and trials: "
     << mean_pm_sd(mean_sd(all.all_angle_diff)) << "° (n = " << mean_sd(all.all_angle_diff).n << ")\n";
  md << "* Range-of-motion difference, all joints and trials: " << mean_pm_sd(mean_sd(all.all_rom_diff))
     << "° (n = " << mean_sd(all.all_rom_diff).n << ")\n";
  for (const auto& [layout, v] : all.vis_by_layout)
    md << "* Visibility rate, layout " << layout << ": " << mean_pm_sd(mean_sd(v)) << "\n";
}

// finger_length.csv and its Markdown table, group by group.
std::string write_finger_length_tables(std::ostringstream& md, const ReportValues& all) {
  std::ostringstream fl;
  fl << "layout,pose,motion,finger,trials,lmc_mean_mm,lmc_sd_mm,vicon_mean_mm,vicon_sd_mm,diff_mean_mm,diff_sd_mm\n";
  md << "\n## Finger length (mm): LMC, Vicon, LMC − Vicon (mean ± SD over trials)\n\n";
  md << "| layout | pose | motion | n | finger | LMC | Vicon | LMC − Vicon |\n|---|---|---|---:|---|---:|---:|---:|\n";
  for (const auto& [g, acc] : all.groups) {
    const auto& [layout, pose, motion] = g;
    for (size_t k = 0; k < kNumFingers; ++k) {
      const MeanSd l = mean_sd(acc.finger_lmc[k]), v = mean_sd(acc.finger_vicon[k]), d = mean_sd(acc.finger_diff[k]);
      fl << layout << ',' << pose << ',' << motion << ',' << kFingers[k] << ',' << acc.trials << ','
         << three_decimals(l.mean) << ',' << three_decimals(l.sd) << ',' << three_decimals(v.mean) << ','
         << three_decimals(v.sd) << ',' << three_decimals(d.mean) << ',' << three_decimals(d.sd) << '\n';
      md << "| " << layout << " | " << pose << " | " << motion << " | " << acc.trials << " | " << kFingers[k] << " | "
         << mean_pm_sd(l) << " | " << mean_pm_sd(v) << " | " << mean_pm_sd(d) << " |\n";
    }
  }
  return fl.str();
}

// joint_angles.csv and its Markdown table, group by group.
std::string write_joint_angle_tables(std::ostringstream& md, const ReportValues& all) {
  std::ostringstream ja;
  ja << "layout,pose,motion,joint,trials,lmc_rom_mean_deg,lmc_rom_sd_deg,vicon_rom_mean_deg,vicon_rom_sd_deg,rom_diff_"
        "mean_deg,"
        "rom_diff_sd_deg,frame_angle_diff_mean_deg,frame_angle_diff_sd_deg\n";
  md << "\n## Joint angles (°): range of motion LMC, Vicon, LMC − Vicon, and the angle difference LMC − Vicon per "
        "frame "
        "averaged per trial (mean ± SD over trials)\n\n";
  md << "| layout | pose | motion | joint | ROM LMC | ROM Vicon | ROM LMC − Vicon | angle LMC − Vicon |\n"
        "|---|---|---|---|---:|---:|---:|---:|\n";
  for (const auto& [g, acc] : all.groups) {
    const auto& [layout, pose, motion] = g;
    for (size_t k = 0; k < kNumAngles; ++k) {
      const MeanSd l = mean_sd(acc.rom_lmc[k]), v = mean_sd(acc.rom_vicon[k]), d = mean_sd(acc.rom_diff[k]);
      const MeanSd fa = mean_sd(acc.angle_diff[k]);
      ja << layout << ',' << pose << ',' << motion << ',' << angle_name(static_cast<int>(k)) << ',' << acc.trials << ','
         << three_decimals(l.mean) << ',' << three_decimals(l.sd) << ',' << three_decimals(v.mean) << ','
         << three_decimals(v.sd) << ',' << three_decimals(d.mean) << ',' << three_decimals(d.sd) << ','
         << three_decimals(fa.mean) << ',' << three_decimals(fa.sd) << '\n';
      md << "| " << layout << " | " << pose << " | " << motion << " | " << angle_name(static_cast<int>(k)) << " | "
         << mean_pm_sd(l) << " | " << mean_pm_sd(v) << " | " << mean_pm_sd(d) << " | " << mean_pm_sd(fa) << " |\n";
    }
  }
  return ja.str();
}

// visibility.csv and its Markdown table, group by group and device by device.
std::string write_visibility_tables(std::ostringstream& md, const ReportValues& all) {
  std::ostringstream vis;
  vis << "layout,pose,motion,device,values,rate_mean,rate_sd\n";
  md << "\n## Visibility rate per device (mean ± SD over fingers and trials; −1 = never saw the hand)\n\n";
  md << "| layout | pose | motion | device | rate |\n|---|---|---|---|---:|\n";
  for (const auto& [g, acc] : all.groups) {
    const auto& [layout, pose, motion] = g;
    for (const auto& [dev, v] : acc.vis) {
      const MeanSd m = mean_sd(v);
      vis << layout << ',' << pose << ',' << motion << ',' << dev << ',' << m.n << ',' << three_decimals(m.mean) << ','
          << three_decimals(m.sd) << '\n';
      md << "| " << layout << " | " << pose << " | " << motion << " | " << dev << " | " << mean_pm_sd(m) << " |\n";
    }
  }
  return vis.str();
}

}  // namespace

SessionReport build_session_report(const std::vector<ReportInput>& inputs) {
  SessionReport rep;
  ReportValues all;
  std::ostringstream trials;
  trials << trials_csv_header();
  for (const auto& in : inputs) {
    const auto& s = in.summary;
    const auto& tag = s.value("tag", nlohmann::json::object());
    const Group g{tag.value("layout", "unknown"), tag.value("pose", "unknown"), tag.value("motion", "unknown")};
    GroupValues& acc = all.groups[g];
    ++acc.trials;
    ++rep.trials;
    if (summary_has_vicon(s)) {
      ++acc.with_vicon;
      ++rep.trials_with_vicon;
    }
    collect_trial_values(s, g, acc, all);
    write_trial_row(trials, in.subject, s, g);
  }
  rep.trials_csv = trials.str();

  // The tables are written in the Markdown's order: overview, finger length, joint angles, visibility.
  std::ostringstream md;
  write_report_overview(md, rep, all);
  rep.finger_length_csv = write_finger_length_tables(md, all);
  rep.joint_angle_csv = write_joint_angle_tables(md, all);
  rep.visibility_csv = write_visibility_tables(md, all);
  rep.markdown = md.str();
  return rep;
}

}  // namespace lmc
