#pragma once
// Text placed in an SVG (titles, series names, labels) comes from files and operators: escaped so
// no name can close a tag or start one, and cleaned so the document stays well-formed XML 1.0.
#include <string>
#include <string_view>

namespace lmc::figures {

// & < > " ' become entities; control characters XML 1.0 forbids are dropped (tab becomes a
// space, as do line breaks: a label is one line); a byte that is not part of valid UTF-8 becomes
// U+FFFD.
std::string xml_escape(std::string_view text);

}  // namespace lmc::figures
