#pragma once
// Vicon UDP capture trigger messages (docs/algorithms/vicon.md): one XML
// document per datagram, null-terminated, `<CaptureStart>` / `<CaptureStop RESULT="…">` whose
// children carry their value in a VALUE attribute. Values are XML-escaped on the way out and
// unescaped on the way in, so a trial name or note can never break the document.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace lmc::devices {

struct ViconMessage {
  enum class Type { kStart, kStop };
  Type type = Type::kStart;
  std::string name;         // trial name → the capture's file name
  std::string notes;        // start only
  std::string description;  // start only
  std::string database_path;
  int delay_ms = 0;
  std::uint32_t packet_id = 0;
  std::string result = "SUCCESS";  // stop only: SUCCESS or CANCEL

  bool operator==(const ViconMessage&) const = default;
};

// The datagram payload, including the terminating '\0'.
std::string format_vicon_message(const ViconMessage& message);
// Parses a datagram (a trailing '\0' and surrounding whitespace are allowed). Returns nullopt
// and sets *error when it is not a capture start/stop message.
std::optional<ViconMessage> parse_vicon_message(std::string_view datagram, std::string* error = nullptr);

}  // namespace lmc::devices
