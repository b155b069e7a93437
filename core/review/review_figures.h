#pragma once
// The Review tab's and `lmc figures`' pictures as core figures (core/figures/figure.h), so the
// screen, the SVG, the CSV behind it and its sidecar are all drawn from one description (issue
// #12): a trial's angles and finger lengths against Vicon on one time axis, a Bland–Altman plot per
// measure and group, and the study's visibility-rate map.
#include <string>

#include "core/figures/figure.h"
#include "core/review/agreement_table.h"
#include "core/review/trial_series.h"
#include "core/review/visibility_map.h"

namespace lmc {

// Six joint-angle panels and five finger-length panels, fused LMC against Vicon (and each
// controller after realignment when `each_controller`).
FigureGrid trial_figure(const TrialSeries& series, bool each_controller = false);

// Points (one series per subject, so repeated trials of one subject share a colour), the bias and
// both 95 % limits as dashed lines labelled with their values; the method is a note.
Figure bland_altman_figure(const AgreementGroup& group, const MeasureAgreement& measure);

// The visibility-rate map as the paper reads it: per layout, the mean rate of each controller for
// each motion (x: the motions in order, named in the notes), −1 … 1.
Figure visibility_map_figure(const VisibilityMap& map);

// "initial-horizontal-index_mcp-rom" style names: safe file stems (letters, digits, '-', '_').
std::string figure_stem(const std::string& text);

}  // namespace lmc
