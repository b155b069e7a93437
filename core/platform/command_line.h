#pragma once
// Whether the program's arguments reached it as they were typed. On Linux they always do. On
// Windows, MinGW's C runtime hands main() its arguments in the ANSI code page, putting a look-alike
// for a character the page lacks ("Ł" becomes "L", a Chinese name question marks), and
// std::filesystem::path then reads a std::string's bytes as Latin-1: a folder named so would
// silently become another folder. The programs refuse such an argument with this message instead.
#include <string>

namespace lmc::platform {

// Empty when every argument is intact; else a message naming the first one that is not.
std::string arguments_changed_by_code_page();

}  // namespace lmc::platform
