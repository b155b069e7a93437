#include "core/results/trial_outputs.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/number_format.h"
#include "core/io/delimited_text.h"
#include "core/processing/trial_tag.h"

namespace lmc {

namespace {

template <size_t N>
void row(std::ostringstream& o, const std::array<double, N>& v, int decimals = 6) {
  for (size_t k = 0; k < N; ++k) o << (k ? "\t" : "") << format_fixed(v[k], decimals);
  o << '\n';
}

void stats_block(std::ostringstream& o, const MeasureStats& s) {
  o << "Segment Length (min, max, average per row) in mm\n";
  for (int k = 0; k < kNumSegments; ++k) o << (k ? "\t" : "") << segment_name(k);
  o << '\n';
  row(o, s.segment_min);
  row(o, s.segment_max);
  row(o, s.segment_mean);
  o << "Finger Length (min, max, average per row) in mm\n";
  o << "Thumb\tFinger\tMiddle\tRing\tLittle\n";
  row(o, s.finger_min);
  row(o, s.finger_max);
  row(o, s.finger_mean);
  o << "Angle Joint (min, max, range of motion per row in degree)\n";
  // The authors' header row reuses the finger names; the six columns are index MCP, PIP, DIP,
  // thumb MCP, thumb DIP, wrist (measures.h).
  o << "Thumb\tFinger\tMiddle\tRing\tLittle\n";
  row(o, s.angle_min);
  row(o, s.angle_max);
  row(o, s.angle_rom);
}

// The authors' "Filename:" line is the file name without its extension. Our own stage suffixes
// (`.raw`, `.resampled`, `.raytraced`) go too, so every variant of one trial names it the same.
std::string stem_of(const std::string& path, const std::string& fallback) {
  if (path.empty()) return fallback;
  return without_stage_suffix(std::filesystem::path(path).stem().string());
}

}  // namespace

std::string format_results_text(const TrialAnalysis& r) {
  std::ostringstream o;
  const std::string bar(72, '_');
  o << bar << "LMC Data" << bar << '\n';
  o << "Filename:\t" << stem_of(r.lmc_source, r.tag.trial) << '\n';
  stats_block(o, r.lmc_stats);
  o << '\n';
  for (const auto& v : r.visibility) {
    o << "Visibility LMC" << v.device_id << '\n';
    o << "Thumb\tFinger\tMiddle\tRing\tLittle\n";
    std::array<double, kNumDigits> a{}, b{}, c{};
    for (size_t k = 0; k < kNumDigits; ++k) {
      a[k] = v.n_no_hand[k];
      b[k] = v.n_hidden[k];
      c[k] = v.n_visible[k];
    }
    row(o, a, 2);
    row(o, b, 2);
    row(o, c, 2);
    row(o, v.rate, 2);
  }
  o << "\n\n";
  if (r.has_vicon) {
    o << bar << "VICON Data" << bar << '\n';
    o << "Filename:\t" << stem_of(r.vicon_source, r.tag.trial) << '\n';
    stats_block(o, r.vicon_stats);
    o << "\n\n";
  }
  return o.str();
}

std::string format_measures_tsv(const TrialAnalysis& r) {
  // One string appended to, not a stream: the table holds ~80,000 numbers a trial, and a stream's
  // per-value insertion cost more than formatting them.
  std::string o;
  o.reserve(r.lmc_frames.size() * 512);
  const auto add = [&o](const auto&... parts) { ((o += parts), ...); };
  o += "frame\ttime_s";
  auto names = [&](const char* prefix) {
    for (int k = 0; k < kNumSegments; ++k) add('\t', prefix, "segment_", segment_name(k), "_mm");
    static const char* fingers[] = {"thumb", "index", "middle", "ring", "pinky"};
    for (const char* f : fingers) add('\t', prefix, "finger_", f, "_mm");
    for (int k = 0; k < kNumAngles; ++k) add('\t', prefix, "angle_", angle_name(k), "_deg");
  };
  names("lmc_");
  if (r.has_vicon) names("vicon_");
  for (const auto& d : r.device_frame.devices) {
    for (int k = 0; k < kNumDigits; ++k) add("\tvis_LMC", std::to_string(d.device_id), '_', digit_name(k));
  }
  o += '\n';
  // Each row is built in a buffer of its own and appended once (as the fused file's rows are,
  // lmc_recording.cpp): appending number by number costs a check per number. A value the
  // quick writer does not take (1e15 mm, say) is appended the general way, the row so far first.
  constexpr size_t kValues = kNumSegments + kNumFingers + kNumAngles;
  const size_t row_room = (2 + 2 * kValues + r.labels.size() * kNumDigits) * 32 + static_cast<size_t>(kFixedQuickRoom);
  const std::unique_ptr<char[]> row(new char[row_room]);
  char* at = row.get();
  const auto put_fixed = [&](double v, int decimals) {
    *at++ = '\t';
    if (char* end = write_fixed(at, v, decimals)) {
      at = end;
      return;
    }
    o.append(row.get(), at);
    append_fixed(o, v, decimals);
    at = row.get();
  };
  const auto put_int = [&](std::int64_t v) { at = std::to_chars(at, at + 24, v).ptr; };
  auto values = [&](const FrameMeasures& m) {
    for (double v : m.segment_mm) put_fixed(v, 4);
    for (double v : m.finger_mm) put_fixed(v, 4);
    for (double v : m.angle_deg) put_fixed(v, 4);
  };
  for (size_t f = 0; f < r.lmc_frames.size(); ++f) {
    at = row.get();
    put_int(static_cast<std::int64_t>(f));
    put_fixed(static_cast<double>(f) * 0.01, 2);
    values(r.lmc_frames[f]);
    if (r.has_vicon) {
      if (f < r.vicon_frames.size()) {
        values(r.vicon_frames[f]);
      } else {
        for (size_t k = 0; k < kValues; ++k) {
          std::memcpy(at, "\tnan", 4);
          at += 4;
        }
      }
    }
    for (const auto& lab : r.labels) {
      for (int k = 0; k < kNumDigits; ++k) {
        *at++ = '\t';
        put_int(lab[f][static_cast<size_t>(k)]);
      }
    }
    *at++ = '\n';
    o.append(row.get(), at);
  }
  return o;
}

std::string format_fused_points(const TrialAnalysis& r) {
  LmcRecording rec;
  rec.kind = RecordingKind::kResampled;
  rec.rows.reserve(static_cast<size_t>(std::max(r.fused.frame_count, 0)));
  for (int f = 0; f < r.fused.frame_count; ++f) {
    HandFrame hf;
    hf.device_id = 1;  // one fused stream; the reader accepts ids 1…8 only
    hf.frame_id = 0;
    hf.frame_rate_hz = 100;
    hf.timestamp_us = r.device_frame.start_us + static_cast<std::int64_t>(std::llround(f * r.device_frame.step_us));
    hf.hand_present = r.fused.has_hand(f);
    for (int i = 0; i < kNumHandPoints; ++i) hf.point(i) = r.fused.at(f, i);
    rec.rows.push_back(hf);
  }
  return format_lmc_recording(rec);
}

std::vector<TrialOutputFile> trial_output_files(const TrialAnalysis& r, const nlohmann::json& summary) {
  const std::string& base = r.tag.trial;
  std::vector<TrialOutputFile> files;
  files.push_back({base + ".results.txt", format_results_text(r)});
  files.push_back({base + ".measures.tsv", format_measures_tsv(r)});
  files.push_back({base + ".fused.txt", format_fused_points(r)});
  files.push_back({base + ".summary.json", summary.dump(2) + "\n"});
  return files;
}

}  // namespace lmc
