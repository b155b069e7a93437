#include "core/reports/layout_report_markdown.h"

#include "core/common/number_format.h"
#include "core/hand/reference_poses.h"

namespace lmc {
namespace {

std::string report_percent(double share) {
  return format_fixed(100.0 * share, 1) + " %";
}

// A weight as typed: 0.05, 1, 0.2 (no trailing zeros).
std::string report_weight(double w) {
  std::string s = format_fixed(w, 3);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// The pose set an `lmc optimize` layout names in its description ("… (seed 1) on <set>, M = …").
std::string searched_on(const std::string& description) {
  if (description.rfind("lmc optimize", 0) != 0) return {};
  const size_t on = description.find(") on ");
  const size_t end = description.rfind(", ");
  if (on == std::string::npos || end == std::string::npos || end <= on + 5) return {};
  return description.substr(on + 5, end - on - 5);
}

std::string pose_sets_side_by_side(const LayoutReport& r) {
  std::string md =
      "\n## On each pose set\n\nThe same layout on every pose set given: M (lower is better), the share of frames "
      "with every finger seen by two or more controllers, each finger seen by at least one, and each controller "
      "seeing some finger.\n\n| set | frames | M | every finger 2+ |";
  for (int k = 0; k < kNumDigits; ++k) md += " " + std::string(digit_name(k)) + " |";
  for (const auto& slot : r.slots) md += " " + slot + " |";
  md += "\n|---|---:|---:|---:|";
  for (int k = 0; k < kNumDigits + static_cast<int>(r.slots.size()); ++k) md += "---:|";
  md += "\n";
  for (const auto& s : r.sets) {
    md += "| " + s.label + " | " + std::to_string(s.frames) + " | " + format_fixed(s.metric, 4) + " | " +
          report_percent(s.redundant_share) + " |";
    // Appended piece by piece: GCC 12 at -O2 warns (falsely) of an overflow in `" " + string&&`.
    for (const double v : s.finger_seen) md.append(" ").append(report_percent(v)).append(" |");
    for (const double v : s.controller_seeing) md.append(" ").append(report_percent(v)).append(" |");
    md += "\n";
  }
  md += "\n";
  for (const auto& s : r.sets) md += "* " + s.label + ": " + s.description + "\n";
  return md;
}

// Title, description, pose set and its provenance, and the figures with their captions.
std::string layout_report_opening(const LayoutReport& r,
                                  const std::vector<std::pair<std::string, std::string>>& figures) {
  std::string md = "# Layout report: " + r.layout_name + "\n\n";
  if (!r.layout_description.empty()) md += r.layout_description + "\n\n";
  md += "Pose set: " + r.poses_description + ". Written by `lmc evaluate --report` (core/metric/layout_report.h).\n\n";
  for (const auto& line : r.poses_provenance) md += "* " + line + "\n";
  if (!r.poses_provenance.empty()) md += "\n";
  if (const std::string searched = searched_on(r.layout_description); !searched.empty())
    md += "The search that made this layout used: " + searched + ".\n\n";
  // The caption also under the picture: alt text alone is only read when the picture is missing.
  for (const auto& [caption, file] : figures) md += "![" + caption + "](" + file + ")\n\n*" + caption + "*\n\n";
  return md;
}

// The controllers that add nothing, overall and inside their axis cuts.
std::string layout_report_idle_controllers(const LayoutReport& r) {
  std::string md;
  int idle = 0;
  for (const auto& c : r.controllers) idle += c.counts ? 0 : 1;
  if (idle == 0) {
    md += "* Every controller counts: the layout is measurably worse without any one of them.\n";
  } else {
    for (const auto& c : r.controllers) {
      if (!c.counts)
        md += "* **" + c.slot + " does not count**: the layout is as good without it (it sees some finger in " +
              report_percent(c.seeing_share) + " of frames).\n";
    }
  }
  int idle_inside = 0;
  for (const auto& c : r.controllers) idle_inside += c.counts_inside_cut ? 0 : 1;
  if (idle_inside == 0) {
    md +=
        "* Inside the axis cuts too: without any one controller, M inside the cut rises or fewer frames have every "
        "finger seen by two controllers inside their cuts.\n";
  } else {
    for (const auto& c : r.controllers) {
      if (!c.counts_inside_cut) {
        md += "* **" + c.slot +
              " adds nothing inside its cut**: it sees some finger with every marker inside its cut in " +
              report_percent(c.seeing_inside_cut_share) + " of frames.\n";
      }
    }
  }
  return md;
}

std::string layout_report_verdict(const LayoutReport& r) {
  std::string md = "## Verdict\n\n";
  md += "* M (the study's metric, lower is better): **" + format_fixed(r.terms_all.metric_m, 4) +
        "**; robust R: " + format_fixed(r.terms_all.total, 4) + ".\n";
  md +=
      "* Every finger seen by at least two controllers in " + report_percent(redundant_share(r.coverage.all.c)) +
      " of frames; some finger seen by none in " +
      report_percent(r.coverage.all.frames > 0 ? static_cast<double>(r.coverage.all.c[0]) / r.coverage.all.frames : 0) +
      ".\n";
  md += layout_report_idle_controllers(r);
  for (const auto& pair : r.overlapping_pairs) {
    md += "* **" + pair +
          " overlap** on the table (their 80 x 30 mm footprints, offsets included): this layout cannot be built as "
          "written.\n";
  }
  md += "* Seen markers beyond the axis cut (250 mm on an axis of the controller that sees them): " +
        report_percent(r.terms_all.axis_cut) +
        " of seeing controller-frames. Counting only what lies inside each "
        "controller's cut (a finger with a marker beyond it unseen by that controller), M is " +
        format_fixed(r.terms_all.metric_m_inside_cut, 4) + " instead of " + format_fixed(r.terms_all.metric_m, 4) +
        ".\n\n";
  return md;
}

std::string layout_report_metric_terms(const LayoutReport& r) {
  std::string md =
      "## Metric terms\n\n| term | what it measures | weight | all | palm down | palm left "
      "|\n|---|---|---:|---:|---:|---:|\n";
  auto term_row = [&](const char* name, const char* meaning, const std::string& weight, double RobustTerms::*field) {
    md += std::string("| ") + name + " | " + meaning + " | " + weight + " | " + format_fixed(r.terms_all.*field, 4) +
          " | " + format_fixed(r.terms_horizontal.*field, 4) + " | " + format_fixed(r.terms_vertical.*field, 4) +
          " |\n";
  };
  for (const RobustTermInfo& term : robust_term_infos()) {
    term_row(term.name, term.meaning, report_weight(robust_term_weight(r.weights, term)), term.value);
  }
  term_row("R", "the total: M plus each weight times its term", "", &RobustTerms::total);
  return md;
}

// Each controller's share, overall and counting only what lies inside its axis cut.
std::string layout_report_contributions(const LayoutReport& r) {
  std::string md =
      "\n## What each controller contributes\n\n"
      "| controller | sees some finger | only one seeing some finger | seen frames beyond the axis cut | palm "
      "off-centre | M without it | every finger 2+ without it | counts |\n"
      "|---|---:|---:|---:|---:|---:|---:|---|\n";
  for (const auto& c : r.controllers) {
    md += "| " + c.slot + " | " + report_percent(c.seeing_share) + " | " + report_percent(c.sole_share) + " | " +
          report_percent(c.cut_share) + " | " + format_fixed(c.off_centre, 3) + " | " +
          format_fixed(c.metric_without, 4) + " | " + report_percent(c.redundant_without) + " | " +
          (c.counts ? "yes" : "**no**") + " |\n";
  }
  md +=
      "\nCounting only what each controller can measure (a finger with a marker beyond the controller's axis cut "
      "unseen by it):\n\n"
      "| controller | sees some finger inside its cut | M inside cut without it | every finger 2+ without it | counts "
      "|\n"
      "|---|---:|---:|---:|---|\n";
  for (const auto& c : r.controllers) {
    md += "| " + c.slot + " | " + report_percent(c.seeing_inside_cut_share) + " | " +
          format_fixed(c.metric_inside_cut_without, 4) + " | " + report_percent(c.redundant_inside_cut_without) +
          " | " + (c.counts_inside_cut ? "yes" : "**no**") + " |\n";
  }
  return md;
}

std::string layout_report_pose_coverage(const LayoutReport& r) {
  std::string md =
      "\n## Coverage per reference pose\n\nShare of the pose's frames in which each finger is seen by at least one "
      "controller (and, after the slash, by two or more).\n\n| pose | frames |";
  for (int k = 0; k < kNumDigits; ++k) md += " " + std::string(digit_name(k)) + " |";
  md += "\n|---|---:|";
  for (int k = 0; k < kNumDigits; ++k) md += "---:|";
  md += "\n";
  for (const auto& p : r.poses) {
    md += "| " + std::string(orientation_words(p.orientation)) + ", " + std::string(motion_words(p.motion)) + " | " +
          std::to_string(p.frames) + " |";
    for (size_t k = 0; k < static_cast<size_t>(kNumDigits); ++k) {
      md +=
          " " + format_fixed(100.0 * p.seen_by_one[k], 0) + " / " + format_fixed(100.0 * p.seen_by_two[k], 0) + " % |";
    }
    md += "\n";
  }
  return md;
}

}  // namespace

std::string format_layout_report_markdown(const LayoutReport& r,
                                          const std::vector<std::pair<std::string, std::string>>& figures) {
  std::string md = layout_report_opening(r, figures);
  md += layout_report_verdict(r);
  md += layout_report_metric_terms(r);
  md += layout_report_contributions(r);
  if (r.sets.size() > 1) md += pose_sets_side_by_side(r);
  md += layout_report_pose_coverage(r);
  return md;
}

}  // namespace lmc
