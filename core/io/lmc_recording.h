#pragma once
// The study's LMC recording format (docs/formats.md), read and written by one module so
// the recorder, processing and `lmc info` agree:
//  * raw:        tab-separated; `Device ID, Frame ID, Frame Rate, Time Stamp`, then 30 fields each
//                "x,y,z"; a row whose device saw no hand ends after the timestamp; trailing tab.
//  * resampled:  same columns; Frame ID 0, Frame Rate 100; no hand is written "nan,nan,nan".
//  * raytraced:  the resampled columns split into single numbers plus visibility_thumb …
//                visibility_pinky (1 visible, 0 not, −1 no hand), space-padded.
#include <array>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "core/hand/hand_frame.h"

namespace lmc {

enum class RecordingKind { kRaw, kResampled, kRaytraced };

// Per-finger visibility label of one row: 1 visible, 0 hidden (internal-model guess), −1 no hand.
using FingerLabels = std::array<std::int8_t, kNumDigits>;

struct LmcRecording {
  RecordingKind kind = RecordingKind::kRaw;
  std::vector<HandFrame> rows;           // in file order (not sorted by time)
  std::vector<FingerLabels> visibility;  // one per row when kind == kRaytraced, else empty
  std::vector<std::string> warnings;     // problems that were survivable, e.g. a truncated last line
  // Where the rows came from, so later stages can name file and line: the reader fills both
  // (`lines` holds each row's 1-based file line); recordings built in code may leave them empty.
  std::string source;
  std::vector<long> lines;

  // Device ids present, ascending.
  std::vector<int> device_ids() const;
};

// Reads any of the three variants (detected from the header). Throws lmc::Error naming file,
// line and column for malformed content; a truncated last line is dropped with a warning and
// the complete rows before it are kept.
LmcRecording read_lmc_recording(const std::filesystem::path& path);
LmcRecording parse_lmc_recording(std::istream& in, const std::string& source_name);
LmcRecording parse_lmc_recording_text(std::string_view content, const std::string& source_name);

// Writes `recording` in the variant given by recording.kind; numbers are written so that
// reading them back gives the same doubles.
void write_lmc_recording(std::ostream& out, const LmcRecording& recording);
// The same text as one string, built without a stream (a batch writes 80 of these).
std::string format_lmc_recording(const LmcRecording& recording);
// Atomic file write (temporary file + rename).
void save_lmc_recording(const std::filesystem::path& path, const LmcRecording& recording);

// Streaming pieces for writers that append row by row (the recorder): the header line and one
// row, each including its trailing newline.
std::string lmc_recording_header(RecordingKind kind);
std::string format_lmc_row(const HandFrame& frame, RecordingKind kind, const FingerLabels* labels = nullptr);
void append_lmc_row(std::string& out, const HandFrame& frame, RecordingKind kind, const FingerLabels* labels = nullptr);

}  // namespace lmc
