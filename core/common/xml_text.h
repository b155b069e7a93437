#pragma once
// Text placed in an XML document — an SVG's titles, series names and labels, a Vicon trigger's
// attribute values — comes from files and operators: escaped so no text can close a tag or start
// one, and cleaned so the document stays well-formed XML 1.0.
#include <string>
#include <string_view>

namespace lmc {

// What a tab, a line feed and a carriage return become.
enum class XmlBreaks {
  kSpace,  // each becomes a space: a figure's label is one line
  // Tab kept, line feed and carriage return dropped: the Vicon trigger's attribute values
  // (devices/vicon/vicon_message.cpp). A Vicon system names its capture and stores its notes from
  // them, so the bytes it receives for any valid name or note must stay what they always were.
  kKeepTabDropLineBreaks,
};

// & < > " ' become entities; the other control characters XML 1.0 forbids are dropped; a byte that
// is not part of valid UTF-8 becomes U+FFFD.
std::string xml_escape(std::string_view text, XmlBreaks breaks = XmlBreaks::kSpace);

}  // namespace lmc
