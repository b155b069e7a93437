// The quality verdict right after a trial (trial_quality.h). This file turns the
// measurements of trial_quality_devices.cpp and trial_quality_grid.cpp into the report and into
// reasons a person can act on. The line it keeps: fail only for faults of the recording itself,
// so a redo can fix them; what the study sets out to measure is reported as a warn at most.
#include "core/session/trial_quality.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "core/processing/measures.h"
#include "core/session/trial_quality_parts.h"

namespace lmc {

namespace {

// The grid that hand presence, finger visibility and range of motion are read on: 100 Hz, the
// processing grid's rate (docs/algorithms/processing.md).
constexpr double kGridStepUs = 10000.0;
// A backwards timestamp step larger than this is a clock reset, not USB reordering (the
// resampler's default, resample.h).
constexpr std::int64_t kClockResetUs = 500000;
// A bound on the grid (one hour at 100 Hz): a stray timestamp far in the future must coarsen the
// grid, not allocate gigabytes.
constexpr double kMaxGridBins = 360000.0;
// Slices of the verdict's plot: about two pixel columns each in the Record tab's small plot; a
// 5 s trial gives 42 ms slices, a 60 s one half a second.
constexpr int kTimelineSlices = 120;

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}
// Tenths of a second read well for long spans; a short gap keeps its hundredths so it never
// prints below the threshold it crossed ("0.25 s", not "0.2 s").
std::string secs(double s) {
  return fixed(s, s < 1.0 ? 2 : 1) + " s";
}
std::string percent_text(double fraction) {
  return fixed(100.0 * fraction, 0) + " %";
}
std::string degrees(double deg) {
  return fixed(deg, 0) + "°";
}
std::string rate(double hz) {
  return fixed(hz, 1) + " frames/s";
}

// Reasons collected by severity, so fails come first whatever order they were found in.
struct Reasons {
  std::vector<std::string> fails, warns;
  void fail(std::string r) { fails.push_back(std::move(r)); }
  void warn(std::string r) { warns.push_back(std::move(r)); }
};

std::string layout_slot_name(const Layout& layout, int device_id) {
  if (device_id >= 1 && device_id <= layout.device_count()) {
    const std::string& slot = layout.devices[static_cast<size_t>(device_id - 1)].slot;
    if (!slot.empty()) return slot;
  }
  return "LMC" + std::to_string(device_id);
}

const SidecarDevice* sidecar_device(const RecorderSidecar& sidecar, int device_id, const std::string& slot) {
  // By slot number first, then by slot name (a sidecar written before ids were kept).
  for (const SidecarDevice& d : sidecar.devices) {
    if (d.device_id == device_id) return &d;
  }
  for (const SidecarDevice& d : sidecar.devices) {
    if (d.slot == slot) return &d;
  }
  return nullptr;
}

void judge_sidecar(const RecorderSidecar& sidecar, Reasons& reasons) {
  const std::string why = sidecar.error.empty() ? std::string() : ": " + sidecar.error;
  if (sidecar.status == "failed") {
    reasons.fail("the recording failed" + why);
  } else if (sidecar.status == "aborted") {
    reasons.fail("the trial was aborted" +
                 (why.empty() && !sidecar.stopped_by.empty() ? " by " + sidecar.stopped_by : why));
  } else if (sidecar.status == "recording") {
    // The recorder finalises the sidecar when it stops; still "recording" means it never did.
    reasons.fail("the recorder did not finish (its sidecar still says \"recording\")" + why);
  }
  // Controllers whose stream had not passed the trial's end when the recorder closed: a frame
  // stamped inside the trial may have come too late to be written.
  const nlohmann::json& w = sidecar.trial_window;
  if (w.is_object() && w.contains("streams_behind_end") && w["streams_behind_end"].is_array()) {
    std::string slots;
    for (const auto& slot : w["streams_behind_end"])
      if (slot.is_string()) slots += (slots.empty() ? "" : ", ") + slot.get<std::string>();
    if (!slots.empty())
      reasons.warn(slots +
                   ": no frame from after the trial's end reached the recorder before it closed; the "
                   "last frames of the trial may be missing");
  }
}

// The frames are kept (the hand is the subject's), but the operator should know the controller
// doubted which hand it saw: its mounting or tracking mode may be wrong.
void judge_hand_side(const DeviceQuality& q, Reasons& reasons) {
  if (q.other_side_hand_frames <= 0) return;
  const std::int64_t n = q.other_side_hand_frames;
  reasons.warn(q.slot + " classified the hand as the other side in " + std::to_string(n) +
               (n == 1 ? " frame" : " frames") + " (kept: it was the only hand in view)");
}

void judge_device(const DeviceQuality& q, const SidecarDevice* sd, const QualityThresholds& t, Reasons& reasons) {
  const std::string& s = q.slot;
  if (q.frames == 0) {
    reasons.fail(s + " sent no frames");
    return;
  }
  // Starved or silent: the controller (or its USB share) failed the recording; redo.
  if (q.median_rate_hz < t.fail_min_rate_hz) {
    reasons.fail(s + " is starved: " + rate(q.median_rate_hz) + " (median)");
  } else if (q.median_rate_hz < t.warn_min_rate_hz) {
    reasons.warn(s + " ran slowly: " + rate(q.median_rate_hz) + " (median)");
  }
  if (q.longest_gap_s >= t.fail_max_gap_s) {
    reasons.fail(s + " sent no frames for " + secs(q.longest_gap_s));
  } else if (q.longest_gap_s >= t.warn_max_gap_s) {
    reasons.warn(s + " sent no frames for " + secs(q.longest_gap_s));
  }
  // One controller losing the hand is often the layout at work (a vertical hand edge-on to a
  // controller): another may have seen it, and the hand-absent check below judges the whole.
  if (q.hand_fraction < t.warn_min_hand_fraction) {
    reasons.warn(s + " saw the hand in " + percent_text(q.hand_fraction) + " of its frames");
  } else if (q.longest_no_hand_s >= t.fail_max_gap_s) {  // reported frames, no hand
    reasons.warn(s + " saw no hand for " + secs(q.longest_no_hand_s));
  }
  if (q.dropped > 0) {
    reasons.warn(s + ": the recorder dropped " + std::to_string(q.dropped) + " frames (queue full)");
  }
  if (q.disconnects > 0 && sd != nullptr) {
    const SidecarDisconnect& first = sd->disconnects.front();
    const bool back = std::all_of(sd->disconnects.begin(), sd->disconnects.end(),
                                  [](const SidecarDisconnect& d) { return !d.reconnected_host_time_utc.empty(); });
    reasons.warn(s + " disconnected " + std::to_string(q.disconnects) + (q.disconnects == 1 ? " time" : " times") +
                 (back ? "" : " and did not come back") + (first.message.empty() ? "" : " (" + first.message + ")"));
  }
  judge_hand_side(q, reasons);
  // Frame-id gaps are not judged: with several controllers on one bus the service skips frames
  // as a matter of course; the rate and gap checks above catch a controller that really lagged.
  if (sd != nullptr && sd->frames_written > 0 && sd->frames_written != q.frames) {
    reasons.warn(s + ": " + std::to_string(q.frames) + " frames in the file, the recorder wrote " +
                 std::to_string(sd->frames_written));
  }
}

ViconQuality vicon_quality(const QualityInputs& in, const std::string& trial) {
  ViconQuality v;
  v.expected = in.vicon_expected;
  for (const SidecarViconPacket& p : in.sidecar->vicon_packets) {
    const bool ok = p.error.empty() && p.datagrams_sent > 0;
    if (p.type == "CaptureStart") v.start_sent = v.start_sent || ok;
    if (p.type == "CaptureStop") v.stop_sent = v.stop_sent || ok;
    if (v.error.empty() && !p.error.empty()) v.error = p.error;
  }
  if (const auto& l = in.sidecar->vicon_listen) {
    v.listened = true;
    v.trigger_host = l->trigger_host;
    v.any_sender = l->any_sender;
    v.refused_datagrams = l->refused_datagrams;
    for (const auto& [host, count] : l->refused_senders) v.refused_hosts.push_back(host);
  }
  // Only a trial that triggered Vicon can have a Vicon file; looking for one otherwise would
  // only ever report "missing".
  if (in.vicon_export_dir && v.expected) {
    for (const char* ext : {".trc", ".c3d"}) {
      const std::filesystem::path file = *in.vicon_export_dir / (trial + ext);
      std::error_code ec;
      if (std::filesystem::is_regular_file(file, ec)) {
        v.export_found = true;
        v.export_file = file.string();
        break;
      }
    }
    if (!v.export_found) v.export_found = false;
  }
  return v;
}

// Listen mode: the trial is as good as any, but someone else on the network tried to start or
// stop it, or nobody made sure only the lab's Vicon could: the operator should know either way.
void judge_vicon_listen(const ViconQuality& v, Reasons& reasons) {
  if (!v.listened) return;
  if (v.refused_datagrams > 0) {
    std::string hosts;
    for (const std::string& h : v.refused_hosts) hosts += (hosts.empty() ? "" : ", ") + h;
    reasons.warn(std::to_string(v.refused_datagrams) +
                 " Vicon datagram(s) from hosts that may not trigger were refused" +
                 (hosts.empty() ? std::string() : " (" + hosts + ")"));
  }
  if (v.any_sender) {
    reasons.warn("Vicon listen mode obeyed any sender" +
                 (v.trigger_host.empty() ? std::string() : " (CaptureStart came from " + v.trigger_host + ")") +
                 ": no Vicon host was configured");
  }
}

void judge_vicon(const ViconQuality& v, const QualityInputs& in, const std::string& trial, Reasons& reasons) {
  judge_vicon_listen(v, reasons);
  if (!v.expected) return;
  if (!v.start_sent) {
    reasons.fail("Vicon was not triggered: " + (v.error.empty() ? std::string("no CaptureStart was sent") : v.error));
    return;
  }
  if (!v.stop_sent) {
    reasons.warn("Vicon was not stopped (no CaptureStop sent" + (v.error.empty() ? "" : ": " + v.error) +
                 "); stop its capture by hand");
  }
  // Vicon writes its export after the capture stops, sometimes only when an operator runs the
  // pipeline, so a missing file this soon is a prompt to check, not proof of a fault.
  if (v.export_found.has_value() && !*v.export_found) {
    reasons.warn("the Vicon file " + trial + ".trc or .c3d has not appeared in " + in.vicon_export_dir->string());
  }
}

// "index_mcp" → "index MCP", "wrist" → "wrist": the joint as a person says it.
std::string joint_words(std::string_view angle) {
  std::string out(angle);
  const size_t cut = out.find('_');
  if (cut == std::string::npos) return out;
  out[cut] = ' ';
  for (size_t i = cut + 1; i < out.size(); ++i)
    out[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[i])));
  return out;
}

// The verdict is the worst reason; fails are listed first.
QualityReport finish(QualityReport report, Reasons reasons) {
  report.verdict = !reasons.fails.empty() ? "fail" : !reasons.warns.empty() ? "warn" : "pass";
  report.reasons = std::move(reasons.fails);
  report.reasons.insert(report.reasons.end(), reasons.warns.begin(), reasons.warns.end());
  return report;
}

// The caller passes the block's layout; a caller that has only the sidecar gets the layout the
// recorder wrote into it.
Layout layout_to_assess(const QualityInputs& in, Reasons& reasons) {
  Layout layout = in.layout;
  const RecorderSidecar& sidecar = *in.sidecar;
  if (layout.devices.empty() && sidecar.layout.is_object()) {
    try {
      layout = layout_from_json(sidecar.layout, "LMC_" + sidecar.trial + ".session.json (layout)");
    } catch (const std::exception& e) {
      reasons.fail(std::string("the layout in the sidecar cannot be read: ") + e.what());
    }
  }
  return layout;
}

// The trial's span on the device clocks (LeapGetNow is shared by every controller on a host);
// `any` is false when no device has a row.
struct TrialSpan {
  std::int64_t first_us = 0, last_us = 0;
  bool any = false;
};
TrialSpan trial_span(const std::vector<trial_quality_detail::DeviceRows>& rows) {
  TrialSpan span;
  for (const auto& d : rows) {
    for (const HandFrame* r : d.rows) {
      span.first_us = span.any ? std::min(span.first_us, r->timestamp_us) : r->timestamp_us;
      span.last_us = span.any ? std::max(span.last_us, r->timestamp_us) : r->timestamp_us;
      span.any = true;
    }
  }
  return span;
}

// Every layout slot is expected to deliver; a device the layout lacks is a set-up fault. The
// devices are judged only on one clock (`judge`), their counts listed either way.
void assess_devices(const std::vector<trial_quality_detail::DeviceRows>& rows, const TrialSpan& span,
                    const Layout& layout, const QualityInputs& in, bool judge, QualityReport& report,
                    Reasons& reasons) {
  const int slots = std::max(layout.device_count(), rows.empty() ? 0 : rows.back().device_id);
  for (int id = 1; id <= slots; ++id) {
    const auto it = std::find_if(rows.begin(), rows.end(),
                                 [id](const trial_quality_detail::DeviceRows& d) { return d.device_id == id; });
    DeviceQuality q = it != rows.end() ? trial_quality_detail::device_stream_quality(*it, span.first_us, span.last_us)
                                       : trial_quality_detail::device_stream_quality(
                                             trial_quality_detail::DeviceRows{id, {}}, span.first_us, span.last_us);
    q.slot = layout_slot_name(layout, id);
    const SidecarDevice* sd = sidecar_device(*in.sidecar, id, q.slot);
    if (sd != nullptr) {
      q.serial = sd->serial;
      q.frame_id_gaps = sd->frame_id_gaps;
      q.dropped = sd->frames_dropped_queue;
      q.disconnects = static_cast<int>(sd->disconnects.size());
      q.other_side_hand_frames = sd->frames_other_side_hand;
    }
    if (id > layout.device_count()) {
      reasons.fail("the recording has device " + std::to_string(id) + " but layout '" + layout.name + "' has only " +
                   std::to_string(layout.device_count()));
    }
    if (judge) judge_device(q, sd, in.thresholds, reasons);
    report.devices.push_back(std::move(q));
  }
}

// Hand presence and finger visibility over every controller at once.
void assess_coverage(const trial_quality_detail::HeldGrid& grid,
                     const std::vector<trial_quality_detail::TracedDevice>& traced, bool any_row,
                     const QualityThresholds& t, QualityReport& report, Reasons& reasons) {
  const trial_quality_detail::Coverage cov = trial_quality_detail::coverage(grid, traced);
  report.hand_fraction = cov.hand_fraction;
  if (any_row && cov.hand_fraction < t.fail_min_hand_fraction) {
    reasons.fail("no controller saw the hand in " + percent_text(1.0 - cov.hand_fraction) + " of the trial");
  }
  report.finger_seen_fraction.assign(cov.finger_seen.begin(), cov.finger_seen.end());
  report.timeline = trial_quality_detail::timeline(grid, traced, kTimelineSlices);
  for (int k = 0; k < kNumDigits; ++k) {
    const double unseen = 1.0 - cov.finger_seen[static_cast<size_t>(k)];
    if (std::isfinite(unseen) && unseen > t.warn_max_finger_unseen) {
      reasons.warn(std::string(digit_name(k)) + " finger unseen by every controller in " + percent_text(unseen) +
                   " of frames");
    }
  }
}

// Range of motion of the trial's joint (a trial type moves one joint; the first is judged).
RomQuality assess_rom(const RomExpectation& want, const trial_quality_detail::HeldGrid& grid,
                      const std::vector<trial_quality_detail::TracedDevice>& traced, const Layout& layout,
                      const QualityThresholds& t, Reasons& reasons) {
  RomQuality rom{want.joint, want.expected_deg, kNaN};
  const int angle = trial_quality_detail::angle_index(want.joint);
  if (angle < 0) {
    reasons.warn("range of motion not checked: unknown joint '" + want.joint + "'");
    return rom;
  }
  rom.reached_deg = trial_quality_detail::reached_rom_deg(grid, traced, layout, angle);
  const std::string name = joint_words(angle_name(angle));
  if (!std::isfinite(rom.reached_deg)) {
    reasons.warn(name + " range of motion unknown: the hand was never tracked");
  } else if (rom.reached_deg < t.warn_min_rom_fraction * want.expected_deg) {
    reasons.warn(name + " moved through " + degrees(rom.reached_deg) + " of the " + degrees(want.expected_deg) +
                 " expected");
  }
  return rom;
}

}  // namespace

QualityReport assess_trial(const QualityInputs& in) {
  if (in.recording == nullptr || in.sidecar == nullptr) {
    throw Error("assess_trial: the recording and the recorder sidecar are both required");
  }
  const LmcRecording& rec = *in.recording;
  const QualityThresholds& t = in.thresholds;
  const std::string trial = in.sidecar->trial;
  QualityReport report;
  report.planned_s = in.planned_s;
  Reasons reasons;

  judge_sidecar(*in.sidecar, reasons);
  for (const std::string& w : rec.warnings) reasons.warn("recording file: " + w);
  const Layout layout = layout_to_assess(in, reasons);

  const std::vector<trial_quality_detail::DeviceRows> rows = trial_quality_detail::rows_by_device(rec);
  const TrialSpan span = trial_span(rows);
  report.duration_s = static_cast<double>(span.last_us - span.first_us) * 1e-6;
  if (in.planned_s > 0 && report.duration_s < t.fail_min_duration_fraction * in.planned_s) {
    reasons.fail("recorded " + secs(report.duration_s) + " of the planned " + secs(in.planned_s));
  }

  // Timestamps from two clocks (a service restart mid-trial): spans measured across them are
  // meaningless, so that one reason replaces the gap and hand checks (the counts stay listed).
  const std::vector<trial_quality_detail::ClockJump> jumps = trial_quality_detail::clock_jumps(rec, kClockResetUs);
  const bool one_clock = jumps.empty();
  for (const trial_quality_detail::ClockJump& jump : jumps) {
    reasons.fail(layout_slot_name(layout, jump.device_id) + "'s clock jumped back " +
                 secs(static_cast<double>(jump.back_us) * 1e-6) + " (the tracking service restarted?)");
  }
  assess_devices(rows, span, layout, in, one_clock, report, reasons);

  if (one_clock) {
    std::vector<trial_quality_detail::TracedDevice> traced;
    traced.reserve(rows.size());
    for (const auto& d : rows) traced.push_back(trial_quality_detail::trace_device(d));
    const double step_us = std::max(kGridStepUs, static_cast<double>(span.last_us - span.first_us) / kMaxGridBins);
    const trial_quality_detail::HeldGrid grid =
        trial_quality_detail::hold_on_grid(rows, span.first_us, span.last_us, step_us);
    assess_coverage(grid, traced, span.any, t, report, reasons);
    if (!in.rom.empty()) report.rom = assess_rom(in.rom.front(), grid, traced, layout, t, reasons);
  }

  report.vicon = vicon_quality(in, trial);
  judge_vicon(report.vicon, in, trial, reasons);
  return finish(std::move(report), std::move(reasons));
}

}  // namespace lmc
