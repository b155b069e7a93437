#include "core/session/session_journal.h"

#include <fstream>
#include <sstream>

#include "core/common/error.h"
#include "core/io/json_checked.h"

namespace fs = std::filesystem;

namespace lmc {

JournalWriter::JournalWriter(const fs::path& path, bool create)
    : path_(path), file_(path, create ? platform::OpenMode::append_new : platform::OpenMode::append) {}

void JournalWriter::append(const nlohmann::json& event) {
  // One write of the whole line to a file opened for appending: a line is never interleaved with
  // another writer's, and a crash leaves at most this one line cut.
  const std::string line = event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  if (!file_.write(line))
    throw Error(ErrorLocation{path_.string()}, "cannot append to the journal: " + file_.last_error());
  if (!file_.sync()) throw Error(ErrorLocation{path_.string()}, "cannot sync the journal: " + file_.last_error());
}

JournalContents read_journal(const fs::path& path, std::uintmax_t max_bytes) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw Error(ErrorLocation{path.string()}, "cannot read the journal: " + ec.message());
  if (size > max_bytes)
    throw Error(ErrorLocation{path.string()},
                "the journal is " + std::to_string(size >> 20) + " MB, more than any session writes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorLocation{path.string()}, "cannot open the journal");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_journal_text(text, path.string());
}

JournalContents parse_journal_text(std::string_view text, const std::string& source) {
  JournalContents out;
  size_t pos = 0;
  int line_no = 0;
  while (pos < text.size()) {
    ++line_no;
    const size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) {
      // No newline: the process died in the middle of this line. Everything before it stands.
      out.cut_last_line = true;
      out.warnings.push_back(source + ":" + std::to_string(line_no) +
                             ": a cut last line was ignored (the program stopped while writing it)");
      break;
    }
    const std::string line(text.substr(pos, nl - pos));
    pos = nl + 1;
    if (line.empty()) continue;
    nlohmann::json event;
    try {
      event = parse_json_text(line, source);
    } catch (const Error&) {
      event = nullptr;
    }
    if (!event.is_object())
      throw Error(ErrorLocation{source, line_no},
                  "this journal line is not a JSON object; the journal was edited or damaged");
    out.events.push_back(std::move(event));
    out.lines.push_back(line_no);
    out.complete_bytes = pos;
  }
  return out;
}

}  // namespace lmc
