#pragma once
// The operating system's words for an error: strerror(errno) on Linux, FormatMessage of
// GetLastError() on Windows (socket calls: WSAGetLastError(), passed to system_error_text).
#include <string>

namespace lmc::platform {

std::string system_error_text(long code);
std::string last_system_error();

}  // namespace lmc::platform
