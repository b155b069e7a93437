#pragma once
// Everything the robust placement metric (robust_metric.h) needs to know about one layout on a
// pose set, as integer counts so that sums over chunks of frames are exact: the result does not
// depend on how frames are split between threads.
//
// Per (device, frame) pair in which the device sees at least one finger ("a seeing pair"):
//  * the axis cut (paper, discussion): the controller cuts a coordinate beyond about 250 mm from
//    its centre on any axis, so a seen marker with |x|, |y| or |z| > cut in the device frame is a
//    violation. "Seen markers" are the four markers of every finger the device sees.
//  * off-centre: where the palm centre sits in the viewing pyramid: (tx² + tz²)/2 with
//    tx = |x|/(y·tan(half long angle)) and tz likewise along z, clipped to 1; so 0 on the viewing
//    axis, 0.5 in the middle of a side of the pyramid, 1 at an edge where two sides meet. Ratios instead
//    of angles keep trigonometry out of the search's inner loop.
#include <cstdint>
#include <span>
#include <vector>

#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"
#include "core/visibility/visibility_params.h"

namespace lmc {

inline constexpr double kAxisCutMm = 250.0;  // the paper's discussion: "around a maximum of 250 mm at any axis"

// Off-centre penalties are summed in millionths (exact integer sums).
inline constexpr double kOffCentreScale = 1e6;

struct LayoutTally {
  int devices = 0;
  std::int64_t frames = 0;
  std::vector<std::int64_t> c;  // devices + 1: as Coverage::c (the study's histogram)
  // The same histogram when a finger with a marker beyond a controller's axis cut counts as unseen
  // by that controller: it reports the cut value instead of the marker, so it cannot measure that
  // finger (the fusion down-weights such points too, fusion_smoother.h).
  std::vector<std::int64_t> c_inside_cut;
  std::vector<std::int64_t> device_seeing_frames;  // frames in which device d sees ≥ 1 finger
  std::vector<std::int64_t> device_sole_frames;    // frames in which device d alone sees some finger
  std::vector<std::int64_t> device_cut_frames;     // seeing frames of device d with a seen marker beyond the cut
  std::vector<std::int64_t> device_off_centre;     // Σ off-centre penalty of device d's seeing frames (millionths)

  explicit LayoutTally(int device_count = 0);
  void add(const LayoutTally& other);  // same device count
  std::int64_t seeing_pairs() const;
  std::int64_t cut_pairs() const;
  std::int64_t off_centre_sum() const;
};

// The per-frame part of the tally: `bits` holds the visible fingers of each device in `frame`,
// `views` the devices. Adds this frame to `tally`.
void tally_frame(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                 const VisibilityLimits& limits, double axis_cut_mm, LayoutTally& tally);

// The same with the axis cut already decided per device: cut_bits[d] as device_visibility_with_cut
// gives it (visibility_kernel.h), which computes the markers' device-frame coordinates anyway.
// Adds exactly what the overload above adds when cut_bits came from the same axis_cut_mm.
void tally_frame(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                 const FingerBits* cut_bits, const VisibilityLimits& limits, LayoutTally& tally);
void tally_frame(const PreparedFrame& frame, std::span<const DeviceView> views, const FingerBits* bits,
                 const FingerBits* cut_bits, std::span<const VisibilityLimits> limits, LayoutTally& tally);

// A run of frames at once, as the search counts them: bits[d·stride + j] and cut_bits[d·stride + j]
// are device d's bits in frames[j] (the kernel's per-device columns of a chunk). Adds exactly what
// tally_frame adds frame by frame (it is how tally_frame counts), with the per-frame counting done
// for many frames in byte-wide vector operations (the tally runs for every layout a search scores).
void tally_frames(std::span<const PreparedFrame> frames, std::span<const DeviceView> views, const FingerBits* bits,
                  const FingerBits* cut_bits, size_t stride, const VisibilityLimits& limits, LayoutTally& tally);
// The same for a mixed rig: device d's off-centre penalty through its own pyramid, limits[d].
void tally_frames(std::span<const PreparedFrame> frames, std::span<const DeviceView> views, const FingerBits* bits,
                  const FingerBits* cut_bits, size_t stride, std::span<const VisibilityLimits> limits,
                  LayoutTally& tally);

// Seen-marker axis cut and off-centre penalty of one seeing pair (exposed for tests).
bool seen_marker_beyond_cut(const PreparedFrame& frame, const DeviceView& view, FingerBits bits, double axis_cut_mm);
double off_centre_penalty(const PreparedFrame& frame, const DeviceView& view, const VisibilityLimits& limits);

// A whole layout on prepared frames (parallel over frames with oneTBB; exact for any thread count).
// With `frame_subset`, only those frames (e.g. the horizontal poses).
LayoutTally tally_layout(std::span<const DeviceView> views, std::span<const PreparedFrame> frames,
                         const VisibilityLimits& limits, double axis_cut_mm = kAxisCutMm,
                         std::span<const int> frame_subset = {});
// A mixed rig: device d through limits[d] (one entry per view), its axis cut limits[d].axis_cut_mm.
LayoutTally tally_layout(std::span<const DeviceView> views, std::span<const PreparedFrame> frames,
                         std::span<const VisibilityLimits> limits, std::span<const int> frame_subset = {});

// `devices` copies of one device's limits, with the axis cut `axis_cut_mm` when it is given: the
// uniform rig as a mixed one.
std::vector<VisibilityLimits> same_limits(const VisibilityLimits& limits, size_t devices, double axis_cut_mm = -1.0);

}  // namespace lmc
