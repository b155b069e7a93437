#pragma once
// The append-only journal of a subject session, `journal.jsonl`: one JSON object a line, each
// line written whole, flushed and fsynced before the call returns, so a state change that was
// reported has reached the disk. Reading tolerates what a crash can leave — a cut last line is
// dropped with a warning — and refuses what it cannot: a broken line in the middle is an error
// naming the file and the line, never silently skipped.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/platform/durable_file.h"

namespace lmc {

class JournalWriter {
 public:
  // Opens for appending (creates the file when `create`; then it must not exist yet).
  JournalWriter(const std::filesystem::path& path, bool create);
  JournalWriter(JournalWriter&& other) noexcept = default;
  JournalWriter& operator=(JournalWriter&&) = delete;
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;

  // Writes one line and fsyncs. Throws lmc::Error naming the file (disk full, I/O error); the
  // journal then still ends with a complete line or a cut one, which readers drop.
  void append(const nlohmann::json& event);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  platform::DurableFile file_;
};

struct JournalContents {
  std::vector<nlohmann::json> events;
  std::vector<int> lines;  // the file line of each event (1-based), for messages
  std::vector<std::string> warnings;
  bool cut_last_line = false;         // a crash left a partial line at the end
  std::uintmax_t complete_bytes = 0;  // bytes up to the end of the last complete line
};

// Reads every complete line. A journal larger than `max_bytes` is refused (it would be millions
// of events: not a journal this program wrote).
JournalContents read_journal(const std::filesystem::path& path, std::uintmax_t max_bytes = 256u << 20);
// The same from text already in memory; `source` names it in messages (the fuzzer feeds this).
JournalContents parse_journal_text(std::string_view text, const std::string& source);

}  // namespace lmc
