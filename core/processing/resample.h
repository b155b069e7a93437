#pragma once
// Stage 1 of the pipeline (docs/algorithms/processing.md): every device's raw, variable-rate stream
// onto one 100 Hz grid that starts at the first time any device saw the hand.
//
// Interpolation is a cubic spline through the samples (a cubic B-spline with a knot at every
// sample, natural end conditions), fitted per coordinate, one contiguous *piece* of samples at a
// time. A piece ends where the device lost the hand (a row without a hand) or where two samples
// are further apart than the gap limit; grid times between pieces are NaN, never bridged.
//
// The gap limit is `max_gap_ms` (50 ms), raised per device to `gap_frame_intervals` × that
// device's median sample interval when `adaptive_gap` is on (the default). Why: with four
// controllers on one bus each streams at 11–34 Hz, so 60–90 ms between two frames is the normal
// rhythm, not a lost hand; a fixed 50 ms would blank most of a study recording (77 of 100 grid
// frames of LMC1 in the published static trial). A device at 100 Hz keeps the 50 ms limit.
//
// Timestamp anomalies are found and reported, never merged silently:
//  * out-of-order rows (a device's timestamp goes back a little, as interleaved USB delivery can
//    do): the stream is sorted by time; each such row is counted;
//  * duplicate timestamps: the second row is dropped and reported (with whether it differed);
//  * clock resets (the timestamp jumps back by more than `clock_reset_ms`, e.g. the service
//    restarted): the stream is split there; the part after the reset is re-based so that it
//    continues one typical frame interval after the last sample before it (file order is the only
//    evidence of its real time), and the reset is reported.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/hand/hand_track.h"
#include "core/io/lmc_recording.h"

namespace lmc {

struct ResampleOptions {
  double rate_hz = 100.0;
  double max_gap_ms = 50.0;  // no interpolation across a longer gap between two samples
  bool adaptive_gap = true;  // raise the limit to gap_frame_intervals × the device's median interval
  double gap_frame_intervals = 2.5;
  double clock_reset_ms = 500.0;  // a backwards jump larger than this is a clock reset
  // When set, the grid starts here (device clock) instead of at the first hand sample: used when
  // the recording knows when the Vicon trigger fired (the simulator's sidecar notes the device
  // clock at ground-truth time zero), so grid frame f and Vicon frame f are the same instant.
  std::optional<std::int64_t> grid_start_us;
  // Plausibility of the span: the hand samples may span at most
  // min_plausible_span_s + max_seconds_per_row × rows; beyond it a timestamp jumped (the error
  // names the row) and the grid would cost memory out of all proportion to the file.
  double min_plausible_span_s = 60.0;
  double max_seconds_per_row = 0.25;
};

enum class StreamIssueKind { kOutOfOrder, kDuplicate, kConflictingDuplicate, kClockReset, kGap };

struct StreamIssue {
  StreamIssueKind kind;
  int device_id = 0;
  long row = 0;  // 1-based data row (file line − 1 for files with one header line)
  std::int64_t timestamp_us = 0;
  std::string message;
};

struct DeviceStreamStats {
  int device_id = 0;
  int rows = 0;
  int hand_rows = 0;
  int out_of_order = 0;
  int duplicates = 0;
  int clock_resets = 0;
  int gaps = 0;                     // gaps longer than the gap limit between hand samples
  double gap_limit_ms = 0.0;        // the limit used for this device (see ResampleOptions)
  double median_interval_ms = 0.0;  // between consecutive hand samples (0 with fewer than two)
  double mean_rate_hz = 0.0;        // hand samples per second over the device's span
};

struct ResampleReport {
  std::vector<DeviceStreamStats> devices;
  std::vector<StreamIssue> issues;  // at most a few per kind and device are listed; stats count all
  // One line per device with anomalies, e.g. "LMC2: 3 out-of-order rows (sorted), 1 duplicate ...".
  std::vector<std::string> summary_lines() const;
};

// Raw recording → grid. Devices are the recording's device ids (ascending); a device that never
// saw the hand gets an all-NaN track. Throws lmc::Error when no device saw a hand at all.
GridTrial resample_recording(const LmcRecording& recording, const ResampleOptions& options = {},
                             ResampleReport* report = nullptr);

// An already resampled (or ray-traced) recording: each device's rows, in file order, are the grid
// frames (the study's files interleave devices 1–4 per 10 ms step). Devices with fewer rows are
// padded with NaN and `warnings` says so.
GridTrial grid_from_resampled(const LmcRecording& recording, std::vector<std::string>* warnings = nullptr);

// Low-level piece: natural cubic spline through (t_k, y_k) with `dims` interleaved values per
// sample (y[k * dims + c]), evaluated at the sorted query times that lie inside [t_0, t_n];
// out[q * dims + c]. Queries outside are left untouched. Exposed for tests.
void cubic_spline_eval(const std::vector<double>& t, const std::vector<double>& y, int dims,
                       const std::vector<double>& query_t, std::vector<double>& out);

}  // namespace lmc
