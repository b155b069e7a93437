#pragma once
// Names that come from outside (a subject id typed by an operator, a trial name from a protocol
// file or a Vicon packet) become parts of file names only after this check: letters, digits, '_'
// and '-', 1–64 characters, not starting with '-'. That excludes '/', '..', NUL, spaces and
// anything a shell or another operating system would read differently. One rule for every kind
// of name; `what` ("trial name", "subject id") only words the message.
#include <string>

namespace lmc {

inline constexpr size_t kMaxSafeNameLength = 64;

// Empty when the name is fine, else what is wrong, starting with `what`.
std::string safe_name_problem(const std::string& name, const std::string& what);

// Throws lmc::Error with the problem above unless the name is fine.
void require_safe_name(const std::string& name, const std::string& what);

}  // namespace lmc
