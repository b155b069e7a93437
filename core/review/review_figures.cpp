#include "core/review/review_figures.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "core/common/number_format.h"
#include "core/hand/hand_frame.h"

namespace lmc {
namespace {

// Fused LMC and Vicon keep the same colours in every panel; controllers follow in palette order.
constexpr std::size_t kFusedSlot = 0, kViconSlot = 7, kFirstDeviceSlot = 1;

Series time_series(const std::string& name, const std::vector<double>& t, const std::vector<double>& y,
                   std::size_t slot) {
  Series s;
  s.name = name;
  s.colour = series_colour(slot);
  s.x = t;
  s.y = y;
  s.shade_gaps = true;
  return s;
}

std::string value_text(double v, const std::string& unit) {
  if (!std::isfinite(v)) return "n/a";
  return format_readable(v, 1, true) + " " + unit;
}

}  // namespace

FigureGrid trial_figure(const TrialSeries& s, bool each_controller) {
  FigureGrid grid;
  grid.title = s.trial + (s.has_vicon ? ": fused LMC against Vicon" : ": fused LMC (no Vicon file)");
  grid.x = {"time", "s", std::nullopt};
  const auto panel = [&](const std::string& label, const std::string& unit, auto pick) {
    Figure f;
    f.y = {label, unit, std::nullopt};
    f.series.push_back(time_series("fused LMC", s.time_s, pick(s.fused), kFusedSlot));
    if (s.has_vicon) f.series.push_back(time_series("Vicon", s.time_s, pick(s.vicon), kViconSlot));
    if (each_controller) {
      for (std::size_t d = 0; d < s.devices.size(); ++d) {
        f.series.push_back(time_series("LMC" + std::to_string(s.devices[d].device_id), s.time_s,
                                       pick(s.devices[d].measures), kFirstDeviceSlot + d));
      }
    }
    grid.panels.push_back(std::move(f));
  };
  for (int a = 0; a < kNumAngles; ++a) {
    panel(std::string(angle_name(a)), "deg",
          [a](const MeasureSeries& m) -> const std::vector<double>& { return m.angle_deg[a]; });
  }
  for (int k = 0; k < kNumFingers; ++k) {
    panel(std::string(digit_name(k)) + " length", "mm",
          [k](const MeasureSeries& m) -> const std::vector<double>& { return m.finger_mm[k]; });
  }
  grid.notes.push_back("Missing values are gaps (shaded), never 0.");
  return grid;
}

Figure bland_altman_figure(const AgreementGroup& group, const MeasureAgreement& m) {
  Figure f;
  const std::string where = group.layout == "all" ? std::string("all trials") : group.layout + " layout, " + group.pose;
  f.title = m.measure.part + " " + m.measure.quantity + ": LMC against Vicon (" + where + ")";
  f.x = {"mean of LMC and Vicon", m.measure.unit, std::nullopt};
  f.y = {"LMC - Vicon", m.measure.unit, std::nullopt};
  std::map<std::string, std::size_t> by_subject;
  for (const auto& p : m.points) {
    auto [it, added] = by_subject.emplace(p.subject, f.series.size());
    if (added) {
      Series s;
      s.name = p.subject;
      s.style = SeriesStyle::points;
      f.series.push_back(std::move(s));
    }
    f.series[it->second].x.push_back(p.mean);
    f.series[it->second].y.push_back(p.difference);
  }
  const auto& b = m.bland_altman;
  if (std::isfinite(b.bias)) {
    f.references.push_back({b.bias, "bias " + value_text(b.bias, m.measure.unit), Dash::dashed, {60, 60, 60}});
  }
  if (std::isfinite(b.loa_low)) {
    f.references.push_back(
        {b.loa_low, "lower " + value_text(b.loa_low, m.measure.unit), Dash::dotted, {120, 120, 120}});
    f.references.push_back(
        {b.loa_high, "upper " + value_text(b.loa_high, m.measure.unit), Dash::dotted, {120, 120, 120}});
  }
  f.notes.push_back(std::to_string(m.n_trials) + " trial(s) of " + std::to_string(m.n_subjects) + " subject(s); " +
                    (b.method.empty() ? std::string("Bland-Altman") : b.method));
  if (!b.reason.empty()) f.notes.push_back("No limits: " + b.reason);
  return f;
}

Figure visibility_map_figure(const VisibilityMap& map) {
  Figure f;
  f.title = "Visibility rate per controller and motion (the study's map)";
  f.y = {"visibility rate (-1 = never saw the hand)", "", AxisRange{-1.05, 1.05}};
  std::vector<std::string> motions;
  std::set<std::string> seen;
  for (const auto& c : map.cells) {
    if (seen.insert(c.motion).second) motions.push_back(c.motion);
  }
  std::map<std::string, std::size_t> motion_index;
  std::string names;
  for (std::size_t i = 0; i < motions.size(); ++i) {
    motion_index[motions[i]] = i + 1;
    names += (i > 0 ? ", " : "") + std::to_string(i + 1) + " " + motions[i];
  }
  f.x = {"motion", "", AxisRange{0.5, static_cast<double>(motions.size()) + 0.5}};
  std::map<std::string, std::size_t> series_of;
  for (const auto& c : map.cells) {
    const std::string name = c.device + " " + c.layout;
    auto [it, added] = series_of.emplace(name, f.series.size());
    if (added) {
      Series s;
      s.name = name;
      s.style = SeriesStyle::line_and_points;
      f.series.push_back(std::move(s));
    }
    f.series[it->second].x.push_back(static_cast<double>(motion_index[c.motion]));
    f.series[it->second].y.push_back(c.rate_mean);
  }
  f.notes.push_back("motions: " + names);
  return f;
}

std::string figure_stem(const std::string& text) {
  std::string out;
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '-' || c == '_') {
      out += static_cast<char>(std::tolower(u));
    } else if (!out.empty() && out.back() != '-') {
      out += '-';
    }
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  if (out.empty()) out = "figure";
  return out.substr(0, 64);
}

}  // namespace lmc
