#include "core/processing/resample.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>

#include "core/common/error.h"

namespace lmc {
namespace {

constexpr int kDims = kNumHandPoints * 3;
constexpr size_t kMaxListedIssuesPerKind = 5;

struct Sample {
  std::int64_t t_us;  // after re-basing
  long row;           // 1-based data row
  const HandFrame* frame;
  bool hand;
};

bool frame_has_hand(const HandFrame& f) {
  return f.hand_present && is_finite(f.point(kPalm));
}

bool same_points(const HandFrame& a, const HandFrame& b) {
  if (a.hand_present != b.hand_present) return false;
  if (!a.hand_present) return true;
  for (int i = 0; i < kNumHandPoints; ++i) {
    if (a.point(i) != b.point(i)) return false;
  }
  return true;
}

std::string lmc_label(int device_id) {
  return "LMC" + std::to_string(device_id);
}

// Timestamps after re-basing stay within ±2^62 µs, so the difference of any two fits in int64.
constexpr std::int64_t kMaxRebasedUs = std::int64_t{1} << 62;

// Names the row of a recording in errors: the file and line when the reader recorded them.
class RowPlace {
 public:
  explicit RowPlace(const LmcRecording& r) : r_(r) {}
  [[noreturn]] void fail(long row, const std::string& what) const {
    const auto i = static_cast<size_t>(row - 1);
    const long line = r_.lines.size() == r_.rows.size() && i < r_.lines.size() ? r_.lines[i] : 0;
    const std::string where = line > 0 ? "" : "row " + std::to_string(row) + ": ";
    if (r_.source.empty() && line == 0) throw Error("resample: " + where + what);
    throw Error(ErrorLocation(r_.source.empty() ? std::string("<recording>") : r_.source, line), where + what);
  }

 private:
  const LmcRecording& r_;
};

std::int64_t add_checked(std::int64_t a, std::int64_t b, const RowPlace& place, long row) {
  // The sum is formed only when it cannot overflow (signed overflow is undefined behaviour).
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  const bool overflows = b > 0 ? a > kMax - b : a < kMin - b;
  const std::int64_t out = overflows ? 0 : a + b;
  if (overflows || out > kMaxRebasedUs || out < -kMaxRebasedUs) {
    place.fail(row, "timestamp arithmetic leaves the plausible range (|t| > 2^62 µs); the time stamps are corrupt");
  }
  return out;
}

void add_issue(ResampleReport* report, std::map<std::pair<int, int>, size_t>& listed, StreamIssue issue) {
  if (report == nullptr) return;
  auto& n = listed[{issue.device_id, static_cast<int>(issue.kind)}];
  if (n++ < kMaxListedIssuesPerKind) report->issues.push_back(std::move(issue));
}

// A grid this long would need gigabytes per device whatever the recording says.
constexpr long kMaxGridFrames = 100'000'000;

// Refuses a grid far longer than the rows can fill (one row whose timestamp jumped by
// 10^4 s made a 10 s recording ask for a multi-GB grid). The recorder writes every frame a
// controller sends, hand or not, at 10–120 Hz per controller; a recording that averages less than
// one row per `max_seconds_per_row` over more than `min_plausible_span_s` has a corrupt clock.
// The message names the largest forward jump, which is where the clock went wrong.
void check_plausible_span(const LmcRecording& recording, const std::vector<std::vector<Sample>>& streams,
                          std::int64_t t_start, std::int64_t t_end, const ResampleOptions& options,
                          const RowPlace& place) {
  const double span_s = (static_cast<double>(t_end) - static_cast<double>(t_start)) * 1e-6;
  const double limit_s =
      options.min_plausible_span_s + options.max_seconds_per_row * static_cast<double>(recording.rows.size());
  if (span_s <= limit_s) return;
  // Every sample inside the grid's span, all devices, in time order; the grid start counts as one.
  std::vector<std::pair<std::int64_t, const Sample*>> all;
  for (const auto& s : streams) {
    for (const Sample& smp : s) {
      if (smp.t_us >= t_start && smp.t_us <= t_end) all.emplace_back(smp.t_us, &smp);
    }
  }
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::int64_t prev = t_start;
  double worst_s = -1.0;
  const Sample* worst = nullptr;
  for (const auto& [t, smp] : all) {
    const double jump_s = static_cast<double>(t - prev) * 1e-6;
    if (jump_s > worst_s) {
      worst_s = jump_s;
      worst = smp;
    }
    prev = t;
  }
  std::ostringstream msg;
  msg.precision(6);
  msg << "the hand samples span " << span_s << " s but the file has only " << recording.rows.size() << " rows (at most "
      << limit_s << " s is plausible: " << options.min_plausible_span_s << " s + " << options.max_seconds_per_row
      << " s per row); ";
  if (worst == nullptr) {
    msg << "the grid start lies far before the first sample";
    throw Error("resample: " + msg.str());
  }
  msg << lmc_label(worst->frame->device_id) << "'s timestamp " << worst->frame->timestamp_us << " µs jumps " << worst_s
      << " s past the sample before it; refusing to build a " << span_s << " s grid";
  place.fail(worst->row, msg.str());
}

// The stream issues of one resampling: all counted by the caller, the first few of each kind and
// device listed in the report.
struct IssueLog {
  ResampleReport* report;
  std::map<std::pair<int, int>, size_t> listed;
  void add(StreamIssue issue) { add_issue(report, listed, std::move(issue)); }
};

// The median of `values` (reordered); `values` not empty.
std::int64_t median_of(std::vector<std::int64_t>& values) {
  auto mid = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

// Device `id`'s rows in file order, on one clock: a time going back by more than `reset_us` is a
// clock reset, and the rest of the stream is re-based to continue one typical interval after the
// latest time seen; a smaller step back is an out-of-order row. Sorted by time (stable).
std::vector<Sample> rebased_stream(const LmcRecording& recording, int id, std::int64_t reset_us, const RowPlace& place,
                                   DeviceStreamStats& st, IssueLog& issues) {
  std::vector<Sample> s;
  std::int64_t rebase = 0, prev = 0, running_max = 0;
  std::vector<std::int64_t> steps;
  bool first = true;
  for (size_t r = 0; r < recording.rows.size(); ++r) {
    const HandFrame& f = recording.rows[r];
    if (f.device_id != id) continue;
    const long row = static_cast<long>(r) + 1;
    ++st.rows;
    std::int64_t t = add_checked(f.timestamp_us, rebase, place, row);
    if (!first && t < add_checked(prev, -reset_us, place, row)) {
      // Clock reset: continue one typical interval after the latest time seen so far.
      const std::int64_t typical = steps.empty() ? 33333 : std::max<std::int64_t>(1, median_of(steps));
      const std::int64_t shift = add_checked(add_checked(running_max, typical, place, row), -t, place, row);
      rebase = add_checked(rebase, shift, place, row);
      t = add_checked(t, shift, place, row);
      ++st.clock_resets;
      issues.add({StreamIssueKind::kClockReset, id, row, f.timestamp_us,
                  lmc_label(id) + " row " + std::to_string(row) + ": clock went back by " +
                      std::to_string((prev - (t - shift)) / 1000) + " ms; stream split and re-based"});
    } else if (!first && t < running_max) {
      ++st.out_of_order;
      issues.add({StreamIssueKind::kOutOfOrder, id, row, f.timestamp_us,
                  lmc_label(id) + " row " + std::to_string(row) + ": timestamp " + std::to_string(f.timestamp_us) +
                      " is earlier than a previous row's; sorted"});
    }
    if (!first && t > prev) steps.push_back(t - prev);
    running_max = first ? t : std::max(running_max, t);
    prev = t;
    first = false;
    s.push_back({t, row, &f, frame_has_hand(f)});
  }
  std::stable_sort(s.begin(), s.end(), [](const Sample& a, const Sample& b) { return a.t_us < b.t_us; });
  return s;
}

// Duplicates: keeps the first row of a timestamp, drops and reports the others.
void drop_duplicate_timestamps(std::vector<Sample>& s, DeviceStreamStats& st, IssueLog& issues) {
  std::vector<Sample> kept;
  kept.reserve(s.size());
  for (const Sample& smp : s) {
    if (!kept.empty() && kept.back().t_us == smp.t_us) {
      const bool same = same_points(*kept.back().frame, *smp.frame);
      ++st.duplicates;
      issues.add({same ? StreamIssueKind::kDuplicate : StreamIssueKind::kConflictingDuplicate, st.device_id, smp.row,
                  smp.frame->timestamp_us,
                  lmc_label(st.device_id) + " row " + std::to_string(smp.row) + ": duplicate timestamp " +
                      std::to_string(smp.frame->timestamp_us) + (same ? "" : " with different data") +
                      "; row dropped"});
      continue;
    }
    kept.push_back(smp);
  }
  s.swap(kept);
}

// The stream's hand rows, the median interval between consecutive hand samples, and the gap
// limit that follows from it (adaptive: a number of those intervals, at least max_gap_ms).
void measure_hand_intervals(const std::vector<Sample>& s, const ResampleOptions& options, DeviceStreamStats& st) {
  for (const Sample& smp : s) st.hand_rows += smp.hand ? 1 : 0;
  std::vector<std::int64_t> hand_steps;
  for (size_t j = 1; j < s.size(); ++j) {
    if (s[j].hand && s[j - 1].hand) hand_steps.push_back(s[j].t_us - s[j - 1].t_us);
  }
  if (!hand_steps.empty()) st.median_interval_ms = static_cast<double>(median_of(hand_steps)) / 1000.0;
  st.gap_limit_ms = options.max_gap_ms;
  if (options.adaptive_gap)
    st.gap_limit_ms = std::max(st.gap_limit_ms, options.gap_frame_intervals * st.median_interval_ms);
}

// The grid's first and last time: from the first hand sample of any device (or the given grid
// start) to the last.
std::pair<std::int64_t, std::int64_t> grid_span(const std::vector<std::vector<Sample>>& streams,
                                                const ResampleOptions& options) {
  bool any_hand = false;
  std::int64_t t_start = 0, t_end = 0;
  for (const auto& s : streams) {
    for (const Sample& smp : s) {
      if (!smp.hand) continue;
      if (!any_hand) {
        t_start = t_end = smp.t_us;
        any_hand = true;
      }
      t_start = std::min(t_start, smp.t_us);
      t_end = std::max(t_end, smp.t_us);
    }
  }
  if (!any_hand) throw Error("resample: no device saw a hand in this recording");
  if (options.grid_start_us) {
    t_start = *options.grid_start_us;
    if (t_start > kMaxRebasedUs || t_start < -kMaxRebasedUs)
      throw Error("resample: the given grid start is out of range");
    if (t_end < t_start) throw Error("resample: every hand sample precedes the given grid start");
  }
  return {t_start, t_end};
}

// A grid from t_start to t_end at step_us, one empty (NaN) track per device of `ids`.
GridTrial empty_grid(std::int64_t t_start, std::int64_t t_end, double step_us, double rate_hz,
                     const std::vector<int>& ids) {
  GridTrial grid;
  grid.start_us = t_start;
  grid.step_us = step_us;
  const double frames = std::floor(static_cast<double>(t_end - t_start) / step_us + 1e-9) + 1.0;
  if (!(frames <= static_cast<double>(kMaxGridFrames))) {
    throw Error("resample: a grid of " + std::to_string(frames) + " frames at " + std::to_string(rate_hz) +
                " Hz is too large (at most " + std::to_string(kMaxGridFrames) + ")");
  }
  grid.frame_count = static_cast<int>(frames);
  grid.devices.resize(ids.size());
  for (size_t di = 0; di < ids.size(); ++di) {
    grid.devices[di].device_id = ids[di];
    grid.devices[di].track = HandTrack(grid.frame_count);
  }
  return grid;
}

// Scratch space of one device's interpolation, reused piece to piece.
struct PieceBuffers {
  std::vector<double> pt, py, qt, qv;
  std::vector<int> qf;
};

// The natural cubic spline through samples s[k, end) (one piece: hand samples without a hand-less
// row or a long gap between them), evaluated at the grid times the piece spans, into `track`.
void interpolate_piece(const std::vector<Sample>& s, size_t k, size_t end, std::int64_t t_start, double step_us,
                       int frame_count, HandTrack& track, PieceBuffers& b) {
  // Fit times are relative to the grid start, in seconds, for conditioning.
  b.pt.resize(end - k);
  b.py.resize((end - k) * kDims);  // every value written below
  for (size_t j = k; j < end; ++j) {
    b.pt[j - k] = static_cast<double>(s[j].t_us - t_start) * 1e-6;
    double* row = b.py.data() + (j - k) * kDims;
    for (int i = 0; i < kNumHandPoints; ++i) {
      const Vec3& p = s[j].frame->point(i);
      row[3 * i] = p.x();
      row[3 * i + 1] = p.y();
      row[3 * i + 2] = p.z();
    }
  }
  const double step_s = step_us * 1e-6;
  const auto f0 = static_cast<int>(std::ceil(b.pt.front() / step_s - 1e-9));
  const auto f1 = static_cast<int>(std::floor(b.pt.back() / step_s + 1e-9));
  b.qt.clear();
  b.qf.clear();
  for (int f = std::max(f0, 0); f <= std::min(f1, frame_count - 1); ++f) {
    double tq = f * step_s;
    // A grid time within rounding of a sample end counts as inside.
    tq = std::clamp(tq, b.pt.front(), b.pt.back());
    b.qt.push_back(tq);
    b.qf.push_back(f);
  }
  if (b.pt.size() == 1 && b.qt.empty()) {
    // An isolated sample between grid times is placed on the nearest grid time.
    const auto f = static_cast<int>(std::lround(b.pt.front() / step_s));
    if (f >= 0 && f < frame_count) {
      b.qt.push_back(b.pt.front());
      b.qf.push_back(f);
    }
  }
  b.qv.assign(b.qt.size() * kDims, kNaN);
  cubic_spline_eval(b.pt, b.py, kDims, b.qt, b.qv);
  for (size_t q = 0; q < b.qf.size(); ++q) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      const size_t at = q * kDims + static_cast<size_t>(i) * 3;
      track.at(b.qf[q], i) = Vec3(b.qv[at], b.qv[at + 1], b.qv[at + 2]);
    }
  }
}

// One device's stream onto the grid, piece by piece (maximal runs of hand samples with no
// hand-less row and no gap over the device's limit inside); each long gap is counted and reported.
void interpolate_device(const std::vector<Sample>& s, std::int64_t t_start, double step_us, int frame_count,
                        HandTrack& track, DeviceStreamStats& st, IssueLog& issues) {
  const auto gap_us = static_cast<std::int64_t>(std::llround(st.gap_limit_ms * 1000.0));
  std::int64_t first_hand = -1, last_hand = -1;
  PieceBuffers buffers;
  size_t k = 0;
  while (k < s.size()) {
    if (!s[k].hand) {
      ++k;
      continue;
    }
    size_t end = k + 1;
    while (end < s.size() && s[end].hand && s[end].t_us - s[end - 1].t_us <= gap_us) ++end;
    if (end < s.size() && s[end].hand) {
      ++st.gaps;
      issues.add({StreamIssueKind::kGap, st.device_id, s[end].row, s[end].frame->timestamp_us,
                  lmc_label(st.device_id) + " row " + std::to_string(s[end].row) + ": " +
                      std::to_string((s[end].t_us - s[end - 1].t_us) / 1000) +
                      " ms without a sample; not interpolated"});
    }
    if (first_hand < 0) first_hand = s[k].t_us;
    last_hand = s[end - 1].t_us;
    interpolate_piece(s, k, end, t_start, step_us, frame_count, track, buffers);
    k = end;
  }
  if (first_hand >= 0 && last_hand > first_hand) {
    st.mean_rate_hz = (st.hand_rows - 1) / (static_cast<double>(last_hand - first_hand) * 1e-6);
  }
}

}  // namespace

void cubic_spline_eval(const std::vector<double>& t, const std::vector<double>& y, int dims,
                       const std::vector<double>& query_t, std::vector<double>& out) {
  const size_t n = t.size();
  if (n == 0) return;
  const auto d = static_cast<size_t>(dims);
  if (n == 1) {
    for (size_t q = 0; q < query_t.size(); ++q) {
      if (query_t[q] == t[0]) std::copy_n(y.begin(), d, out.begin() + static_cast<long>(q * d));
    }
    return;
  }
  // Second derivatives M with natural ends (M_0 = M_{n-1} = 0): tridiagonal system solved once
  // for all `dims` right-hand sides (Thomas algorithm; the matrix is diagonally dominant).
  std::vector<double> h(n - 1);
  for (size_t k = 0; k + 1 < n; ++k) h[k] = t[k + 1] - t[k];
  std::vector<double> m(n * d, 0.0);
  if (n > 2) {
    const size_t inner = n - 2;
    std::vector<double> cprime(inner);
    std::vector<double> denom(inner);
    for (size_t i = 0; i < inner; ++i) {
      const double a = h[i], b = 2.0 * (h[i] + h[i + 1]), c = h[i + 1];
      denom[i] = b - (i > 0 ? a * cprime[i - 1] : 0.0);
      cprime[i] = c / denom[i];
    }
    for (size_t i = 0; i < inner; ++i) {
      const size_t k = i + 1;  // sample index
      for (size_t c = 0; c < d; ++c) {
        double rhs =
            6.0 * ((y[(k + 1) * d + c] - y[k * d + c]) / h[k] - (y[k * d + c] - y[(k - 1) * d + c]) / h[k - 1]);
        if (i > 0) rhs -= h[i] * m[k * d - d + c];  // a_i · d'_{i-1}, stored in m temporarily
        m[k * d + c] = rhs / denom[i];
      }
    }
    for (size_t i = inner - 1; i-- > 0;) {
      const size_t k = i + 1;
      for (size_t c = 0; c < d; ++c) m[k * d + c] -= cprime[i] * m[(k + 1) * d + c];
    }
  }
  // A segment's terms that do not depend on the query time, computed once for all the queries in
  // it (a 100 Hz grid puts three or four in each segment of a 25–30 Hz recording), each by the
  // same operations as in the formula, so the values are the same.
  std::vector<double> slope0(d), slope1(d);
  size_t seg = 0;
  size_t prepared = static_cast<size_t>(-1);
  for (size_t q = 0; q < query_t.size(); ++q) {
    const double tq = query_t[q];
    if (tq < t.front() || tq > t.back()) continue;
    while (seg + 2 < n && tq > t[seg + 1]) ++seg;
    const double hs = h[seg];
    if (seg != prepared) {
      for (size_t c = 0; c < d; ++c) {
        slope0[c] = y[seg * d + c] / hs - m[seg * d + c] * hs / 6.0;
        slope1[c] = y[(seg + 1) * d + c] / hs - m[(seg + 1) * d + c] * hs / 6.0;
      }
      prepared = seg;
    }
    const double a = t[seg + 1] - tq, b = tq - t[seg];
    const double six_h = 6.0 * hs;
    for (size_t c = 0; c < d; ++c) {
      const double m0 = m[seg * d + c], m1 = m[(seg + 1) * d + c];
      out[q * d + c] = (m0 * a * a * a + m1 * b * b * b) / six_h + slope0[c] * a + slope1[c] * b;
    }
  }
}

std::vector<std::string> ResampleReport::summary_lines() const {
  std::vector<std::string> lines;
  for (const auto& d : devices) {
    std::ostringstream s;
    bool any = false;
    auto part = [&](int n, const char* what) {
      if (n == 0) return;
      s << (any ? ", " : "") << n << ' ' << what;
      any = true;
    };
    part(d.out_of_order, "out-of-order row(s) (sorted by time)");
    part(d.duplicates, "duplicate timestamp(s) (second row dropped)");
    part(d.clock_resets, "clock reset(s) (stream split and re-based)");
    const std::string gap_text = "gap(s) longer than the interpolation limit of " +
                                 std::to_string(static_cast<long>(std::lround(d.gap_limit_ms))) + " ms (NaN there)";
    part(d.gaps, gap_text.c_str());
    if (any) lines.push_back(lmc_label(d.device_id) + ": " + s.str());
  }
  return lines;
}

GridTrial resample_recording(const LmcRecording& recording, const ResampleOptions& options, ResampleReport* report) {
  if (!(options.rate_hz > 0.0) || !(options.max_gap_ms > 0.0) || !(options.gap_frame_intervals > 0.0)) {
    throw Error("resample: rate and gap limit must be positive");
  }
  const double step_us = 1e6 / options.rate_hz;
  const auto reset_us = static_cast<std::int64_t>(std::llround(options.clock_reset_ms * 1000.0));
  IssueLog issues{report, {}};

  const RowPlace place(recording);
  const std::vector<int> ids = recording.device_ids();
  std::vector<std::vector<Sample>> streams(ids.size());
  std::vector<DeviceStreamStats> stats(ids.size());
  for (size_t di = 0; di < ids.size(); ++di) {
    auto& st = stats[di];
    st.device_id = ids[di];
    streams[di] = rebased_stream(recording, ids[di], reset_us, place, st, issues);
    drop_duplicate_timestamps(streams[di], st, issues);
    measure_hand_intervals(streams[di], options, st);
  }

  const auto [t_start, t_end] = grid_span(streams, options);
  check_plausible_span(recording, streams, t_start, t_end, options, place);
  GridTrial grid = empty_grid(t_start, t_end, step_us, options.rate_hz, ids);
  for (size_t di = 0; di < ids.size(); ++di) {
    interpolate_device(streams[di], t_start, step_us, grid.frame_count, grid.devices[di].track, stats[di], issues);
  }
  if (report != nullptr) report->devices = std::move(stats);
  return grid;
}

GridTrial grid_from_resampled(const LmcRecording& recording, std::vector<std::string>* warnings) {
  const std::vector<int> ids = recording.device_ids();
  std::vector<std::vector<const HandFrame*>> rows(ids.size());
  for (const HandFrame& f : recording.rows) {
    const auto it = std::lower_bound(ids.begin(), ids.end(), f.device_id);
    rows[static_cast<size_t>(it - ids.begin())].push_back(&f);
  }
  GridTrial grid;
  size_t n = 0;
  for (const auto& r : rows) n = std::max(n, r.size());
  grid.frame_count = static_cast<int>(n);
  grid.step_us = 10000.0;
  if (!recording.rows.empty()) grid.start_us = recording.rows.front().timestamp_us;
  for (size_t di = 0; di < ids.size(); ++di) {
    DeviceTrack dev;
    dev.device_id = ids[di];
    dev.track = HandTrack(grid.frame_count);
    for (size_t f = 0; f < rows[di].size(); ++f) {
      const HandFrame& hf = *rows[di][f];
      if (!hf.hand_present) continue;
      for (int i = 0; i < kNumHandPoints; ++i) dev.track.at(static_cast<int>(f), i) = hf.point(i);
    }
    if (rows[di].size() < n && warnings != nullptr) {
      warnings->push_back(lmc_label(ids[di]) + " has " + std::to_string(rows[di].size()) + " rows, others up to " +
                          std::to_string(n) + "; its missing frames are NaN");
    }
    grid.devices.push_back(std::move(dev));
  }
  const bool any_hand =
      std::any_of(recording.rows.begin(), recording.rows.end(), [](const HandFrame& f) { return f.hand_present; });
  if (!any_hand && warnings != nullptr)
    warnings->push_back("no device saw the hand in any row: every LMC measure is NaN");
  return grid;
}

}  // namespace lmc
