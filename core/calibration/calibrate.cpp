#include "core/calibration/calibrate.h"

#include "core/common/error.h"
#include "core/common/number_format.h"

namespace lmc {
namespace {

// Samples that have a finite Vicon point on their frame: (device point, Vicon point, group).
struct ViconPairs {
  std::vector<Vec3> src, dst;
  std::vector<int> group;
  std::vector<std::uint8_t> axes;  // the device axes of src the fit may use (calibration_samples.h)
  int frames = 0;
};

ViconPairs vicon_pairs(const DeviceSamples& s, const HandTrack& vicon) {
  ViconPairs out;
  int last_frame = -1;
  for (int i = 0; i < s.size(); ++i) {
    const int f = s.frame[static_cast<size_t>(i)];
    if (f >= vicon.frame_count) continue;
    const CalibrationPoint& cp = calibration_points()[static_cast<size_t>(s.point[static_cast<size_t>(i)])];
    const Vec3& v = vicon.at(f, cp.point);
    if (!is_finite(v)) continue;
    out.src.push_back(s.p[static_cast<size_t>(i)]);
    out.dst.push_back(v);
    out.group.push_back(cp.group);
    out.axes.push_back(s.axes[static_cast<size_t>(i)]);
    if (f != last_frame) ++out.frames;
    last_frame = f;
  }
  return out;
}

ResidualSums residual_sums(const ViconPairs& p, const RigidTransform& t) {
  ResidualSums sums;
  for (size_t i = 0; i < p.src.size(); ++i) sums.add(p.group[i], masked_distance(t, p.src[i], p.dst[i], p.axes[i]));
  return sums;
}

void store_residuals(DeviceCalibration& d, const ResidualSums& before, const ResidualSums& after) {
  for (int g = 0; g < kNumPointGroups; ++g) {
    auto& r = d.groups[static_cast<size_t>(g)];
    r.samples = after.counts[static_cast<size_t>(g)];
    r.before_mm = before.rms(g);
    r.after_mm = after.rms(g);
  }
  d.all.samples = after.count_all();
  d.all.before_mm = before.rms_all();
  d.all.after_mm = after.rms_all();
}

// Leave-one-out residuals of device d under `transforms`, by group.
ResidualSums consensus_sums(const std::vector<DeviceSamples>& samples, const SampleTable& table,
                            const std::vector<RigidTransform>& transforms, const std::vector<bool>& included, int d) {
  std::vector<Vec3> src, dst;
  std::vector<int> index;
  std::vector<std::uint8_t> axes;
  leave_one_out_pairs(samples, table, transforms, included, d, src, dst, index, &axes);
  ResidualSums sums;
  const DeviceSamples& own = samples[static_cast<size_t>(d)];
  for (size_t i = 0; i < src.size(); ++i) {
    const int group = calibration_points()[static_cast<size_t>(own.point[static_cast<size_t>(index[i])])].group;
    sums.add(group, masked_distance(transforms[static_cast<size_t>(d)], src[i], dst[i], axes[i]));
  }
  return sums;
}

// Mean size of the `included` controllers' corrections (calibration_diagnostics.h's distance).
double mean_correction_mm(const std::vector<RigidTransform>& fitted, const std::vector<RigidTransform>& nominal,
                          const std::vector<bool>& included) {
  double sum = 0;
  int n = 0;
  for (size_t d = 0; d < fitted.size(); ++d) {
    if (!included[d]) continue;
    sum += transform_distance_mm(fitted[d], nominal[d]);
    ++n;
  }
  return n == 0 ? 0.0 : sum / n;
}

int frames_with_samples(const DeviceSamples& s) {
  int n = 0;
  for (int i = 0; i < s.size(); ++i)
    if (i == 0 || s.frame[static_cast<size_t>(i)] != s.frame[static_cast<size_t>(i - 1)]) ++n;
  return n;
}

}  // namespace

namespace {

// Every controller of the layout at its nominal placement, before anything is fitted.
CalibrationResult nominal_result(const CalibrationInput& input, const Layout& layout, const CalibrationOptions& options,
                                 std::vector<RigidTransform>& nominal) {
  const int n = layout.device_count();
  for (const auto& d : input.device_frame.devices) {
    if (d.device_id < 1 || d.device_id > n) {
      throw Error("the recording has device id " + std::to_string(d.device_id) + " but layout '" + layout.name +
                  "' has " + std::to_string(n) + " device(s)");
    }
  }
  CalibrationResult result;
  result.with_vicon = options.use_vicon && input.vicon.has_value();
  nominal.assign(static_cast<size_t>(n), RigidTransform{});
  result.devices.resize(static_cast<size_t>(n));
  for (int d = 0; d < n; ++d) {
    auto& dc = result.devices[static_cast<size_t>(d)];
    dc.slot = layout.devices[static_cast<size_t>(d)].slot;
    dc.device_id = d + 1;
    nominal[static_cast<size_t>(d)] = device_transform(layout.devices[static_cast<size_t>(d)]);
    dc.nominal = dc.fitted_transform = nominal[static_cast<size_t>(d)];
  }
  return result;
}

// Each controller's still-hand samples, with a note for those clamped at an axis cut.
std::vector<DeviceSamples> controller_samples(const CalibrationInput& input, const CalibrationOptions& options,
                                              CalibrationResult& result) {
  std::vector<DeviceSamples> samples(result.devices.size());
  for (size_t k = 0; k < input.device_frame.devices.size(); ++k) {
    const auto& dev = input.device_frame.devices[k];
    auto& s = samples[static_cast<size_t>(dev.device_id - 1)];
    s = gather_samples(dev.track, input.labels.at(k), options.samples);
    auto& dc = result.devices[static_cast<size_t>(dev.device_id - 1)];
    dc.beyond_cut = s.beyond_cut;
    dc.dropped_beyond_cut = s.dropped_beyond_cut;
    if (s.beyond_cut > 0) {
      result.notes.push_back(
          dc.slot + ": " + std::to_string(s.beyond_cut) + " of " + std::to_string(s.size() + s.dropped_beyond_cut) +
          " samples had a coordinate clamped at its ±" + format_fixed(options.samples.axis_cut_mm, 0) +
          " mm axis cut: only their other coordinates were used");
    }
  }
  return samples;
}

// With Vicon: each controller fitted to the Vicon points on its own; the controllers taking part.
std::vector<bool> fit_to_vicon(const CalibrationInput& input, const std::vector<DeviceSamples>& samples,
                               const std::vector<RigidTransform>& nominal, const CalibrationOptions& options,
                               CalibrationResult& result) {
  const int n = static_cast<int>(result.devices.size());
  std::vector<bool> included(static_cast<size_t>(n), false);
  std::vector<ViconPairs> pairs(static_cast<size_t>(n));
  std::vector<RigidTransform> fitted = nominal;
  for (int d = 0; d < n; ++d) {
    auto& dc = result.devices[static_cast<size_t>(d)];
    pairs[static_cast<size_t>(d)] = vicon_pairs(samples[static_cast<size_t>(d)], *input.vicon);
    const ViconPairs& p = pairs[static_cast<size_t>(d)];
    dc.frames = p.frames;
    if (static_cast<int>(p.src.size()) < options.min_samples) {
      dc.warnings.push_back(dc.slot + ": only " + std::to_string(p.src.size()) +
                            " usable samples with Vicon points (needs " + std::to_string(options.min_samples) +
                            "): left as it was");
      continue;
    }
    dc.fitted = true;
    included[static_cast<size_t>(d)] = true;
    fitted[static_cast<size_t>(d)] = robust_rigid_fit(p.src, p.dst, dc.nominal, options.fit, nullptr, p.axes);
  }
  // The part of the corrections all controllers share: the Vicon frame against the layout's.
  const RigidTransform common = mean_correction(fitted, nominal, included);
  const double common_mm = common.t.norm(), common_deg = rotation_angle_deg(common.r);
  RigidTransform to_layout;  // maps Vicon points into the frame the results are given in
  if (options.anchor_vicon_to_layout) {
    to_layout = common.inverse();
    fitted = anchor_to_nominal(fitted, nominal, included);
    result.notes.push_back("kept the layout's world frame; Vicon's frame differed from it by " +
                           format_fixed(common_mm, 1) + " mm and " + format_fixed(common_deg, 2) + "° on average");
  } else if ((common_mm > options.common_shift_warning_mm || common_deg > options.common_turn_warning_deg) &&
             mean_correction_mm(anchor_to_nominal(fitted, nominal, included), nominal, included) <
                 options.common_share_warning * mean_correction_mm(fitted, nominal, included)) {
    result.warnings.push_back(
        "every controller moved by " + format_fixed(common_mm, 1) + " mm and turned " + format_fixed(common_deg, 1) +
        "° on average: the Vicon frame is probably not the layout's world frame. To keep the layout's frame and "
        "take only the controllers' relative placement from Vicon, anchor to the layout (lmc calibrate "
        "--anchor-to-layout)");
  }
  for (int d = 0; d < n; ++d) {
    if (!included[static_cast<size_t>(d)]) continue;
    auto& dc = result.devices[static_cast<size_t>(d)];
    ViconPairs& p = pairs[static_cast<size_t>(d)];
    for (auto& v : p.dst) v = to_layout.apply(v);
    dc.fitted_transform = fitted[static_cast<size_t>(d)];
    store_residuals(dc, residual_sums(p, dc.nominal), residual_sums(p, dc.fitted_transform));
  }
  return included;
}

std::vector<RigidTransform> fitted_transforms(const CalibrationResult& result) {
  std::vector<RigidTransform> fitted(result.devices.size());
  for (size_t d = 0; d < result.devices.size(); ++d) fitted[d] = result.devices[d].fitted_transform;
  return fitted;
}

// Without Vicon: the controllers fitted to each other (the consensus); the controllers taking part.
std::vector<bool> fit_to_each_other(const std::vector<DeviceSamples>& samples, const SampleTable& table,
                                    const std::vector<RigidTransform>& nominal, const CalibrationOptions& options,
                                    CalibrationResult& result) {
  const int n = static_cast<int>(result.devices.size());
  std::vector<bool> included(static_cast<size_t>(n), false);
  // A controller takes part when enough of its samples are shared with another controller
  // that has enough samples of its own.
  std::vector<bool> candidate(static_cast<size_t>(n));
  for (int d = 0; d < n; ++d)
    candidate[static_cast<size_t>(d)] = samples[static_cast<size_t>(d)].size() >= options.min_samples;
  std::vector<Vec3> src, dst;
  std::vector<int> index;
  for (int d = 0; d < n; ++d) {
    auto& dc = result.devices[static_cast<size_t>(d)];
    dc.frames = frames_with_samples(samples[static_cast<size_t>(d)]);
    leave_one_out_pairs(samples, table, nominal, candidate, d, src, dst, index);
    if (!candidate[static_cast<size_t>(d)] || static_cast<int>(src.size()) < options.min_samples) {
      dc.warnings.push_back(dc.slot + ": only " + std::to_string(src.size()) +
                            " usable samples seen together with another controller (needs " +
                            std::to_string(options.min_samples) + "): left as it was");
      continue;
    }
    included[static_cast<size_t>(d)] = true;
  }
  int taking_part = 0;
  for (const bool b : included) taking_part += b ? 1 : 0;
  if (taking_part < 2) {
    result.warnings.push_back("calibration without Vicon needs at least two controllers that see the hand together; " +
                              std::to_string(taking_part) + " did: nothing was changed");
    std::fill(included.begin(), included.end(), false);
    return included;
  }
  ConsensusOptions copt = options.consensus;
  copt.fit = options.fit;
  const ConsensusFit fit = fit_consensus(samples, table, nominal, included, copt);
  result.sweeps = fit.sweeps;
  if (!fit.converged)
    result.warnings.push_back("the consensus fit did not settle within " + std::to_string(fit.sweeps) +
                              " sweeps: its result is approximate");
  for (int d = 0; d < n; ++d) {
    if (!included[static_cast<size_t>(d)]) continue;
    auto& dc = result.devices[static_cast<size_t>(d)];
    dc.fitted = true;
    dc.fitted_transform = fit.transforms[static_cast<size_t>(d)];
  }
  const std::vector<RigidTransform> fitted = fitted_transforms(result);
  for (int d = 0; d < n; ++d) {
    if (!included[static_cast<size_t>(d)]) continue;
    store_residuals(result.devices[static_cast<size_t>(d)], consensus_sums(samples, table, nominal, included, d),
                    consensus_sums(samples, table, fitted, included, d));
  }
  return included;
}

// Disagreement between controllers, in both modes, over the controllers that were fitted.
void store_disagreement(const std::vector<DeviceSamples>& samples, const SampleTable& table,
                        const std::vector<RigidTransform>& nominal, const std::vector<bool>& included,
                        CalibrationResult& result) {
  const std::vector<RigidTransform> fitted = fitted_transforms(result);
  ResidualSums before, after;
  for (int d = 0; d < static_cast<int>(result.devices.size()); ++d) {
    if (!included[static_cast<size_t>(d)]) continue;
    const ResidualSums b = consensus_sums(samples, table, nominal, included, d);
    const ResidualSums a = consensus_sums(samples, table, fitted, included, d);
    for (int g = 0; g < kNumPointGroups; ++g) {
      before.squares[static_cast<size_t>(g)] += b.squares[static_cast<size_t>(g)];
      before.counts[static_cast<size_t>(g)] += b.counts[static_cast<size_t>(g)];
      after.squares[static_cast<size_t>(g)] += a.squares[static_cast<size_t>(g)];
      after.counts[static_cast<size_t>(g)] += a.counts[static_cast<size_t>(g)];
    }
  }
  result.covisible_samples = after.count_all();
  result.disagreement_before_mm = before.rms_all();
  result.disagreement_after_mm = after.rms_all();
}

}  // namespace

CalibrationResult calibrate(const CalibrationInput& input, const Layout& layout, const CalibrationOptions& options) {
  std::vector<RigidTransform> nominal;
  CalibrationResult result = nominal_result(input, layout, options, nominal);
  const std::vector<DeviceSamples> samples = controller_samples(input, options, result);
  const SampleTable table(samples, input.device_frame.frame_count);
  const std::vector<bool> included = result.with_vicon ? fit_to_vicon(input, samples, nominal, options, result)
                                                       : fit_to_each_other(samples, table, nominal, options, result);
  for (auto& dc : result.devices) {
    dc.moved_mm = (dc.fitted_transform.t - dc.nominal.t).norm();
    dc.turned_deg = rotation_angle_deg(dc.nominal.r.transpose() * dc.fitted_transform.r);
  }
  store_disagreement(samples, table, nominal, included, result);
  add_warnings(result, options.warnings);
  return result;
}

}  // namespace lmc
