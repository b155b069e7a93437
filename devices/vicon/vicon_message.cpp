#include "devices/vicon/vicon_message.h"

#include <charconv>
#include <system_error>

#include "core/common/xml_text.h"

namespace lmc::devices {
namespace {

std::string unescape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') {
      out += s[i];
      continue;
    }
    const size_t semi = s.find(';', i);
    if (semi == std::string_view::npos) {
      out += s[i];
      continue;
    }
    const std::string_view ent = s.substr(i + 1, semi - i - 1);
    if (ent == "amp")
      out += '&';
    else if (ent == "lt")
      out += '<';
    else if (ent == "gt")
      out += '>';
    else if (ent == "quot")
      out += '"';
    else if (ent == "apos")
      out += '\'';
    else {
      out += s.substr(i, semi - i + 1);
    }
    i = semi;
  }
  return out;
}

// VALUE of the first <tag VALUE="..."/> element, or nullopt.
std::optional<std::string> element_value(std::string_view xml, std::string_view tag) {
  const std::string open = "<" + std::string(tag);
  size_t pos = 0;
  while ((pos = xml.find(open, pos)) != std::string_view::npos) {
    const size_t after = pos + open.size();
    if (after < xml.size() && (xml[after] == ' ' || xml[after] == '/' || xml[after] == '>')) break;
    pos = after;
  }
  if (pos == std::string_view::npos) return std::nullopt;
  const size_t end = xml.find('>', pos);
  if (end == std::string_view::npos) return std::nullopt;
  const std::string_view elem = xml.substr(pos, end - pos);
  const size_t v = elem.find("VALUE=\"");
  if (v == std::string_view::npos) return std::string();
  const size_t q = elem.find('"', v + 7);
  if (q == std::string_view::npos) return std::nullopt;
  return unescape(elem.substr(v + 7, q - v - 7));
}

}  // namespace

namespace {

// Tab kept, line breaks dropped (core/common/xml_text.h says why the Vicon rule differs there).
std::string vicon_escaped(std::string_view value) {
  return xml_escape(value, XmlBreaks::kKeepTabDropLineBreaks);
}

}  // namespace

std::string format_vicon_message(const ViconMessage& m) {
  auto field = [](const char* tag, std::string_view value) {
    return "<" + std::string(tag) + " VALUE=\"" + vicon_escaped(value) + "\"/>";
  };
  std::string xml = R"(<?xml version="1.0" encoding="UTF-8" standalone="no" ?>)";
  if (m.type == ViconMessage::Type::kStart) {
    xml += "<CaptureStart>";
    xml += field("Name", m.name);
    xml += field("Notes", m.notes);
    xml += field("Description", m.description);
    xml += field("DatabasePath", m.database_path);
    xml += field("Delay", std::to_string(m.delay_ms));
    xml += field("PacketID", std::to_string(m.packet_id));
    xml += "</CaptureStart>";
  } else {
    xml += "<CaptureStop RESULT=\"" + vicon_escaped(m.result) + "\">";
    xml += field("Name", m.name);
    xml += field("DatabasePath", m.database_path);
    xml += field("Delay", std::to_string(m.delay_ms));
    xml += field("PacketID", std::to_string(m.packet_id));
    xml += "</CaptureStop>";
  }
  xml.push_back('\0');
  return xml;
}

std::optional<ViconMessage> parse_vicon_message(std::string_view d, std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<ViconMessage> {
    if (error != nullptr) *error = why;
    return std::nullopt;
  };
  while (!d.empty() && (d.back() == '\0' || d.back() == ' ' || d.back() == '\n' || d.back() == '\r'))
    d.remove_suffix(1);
  ViconMessage m;
  const size_t start = d.find("<CaptureStart");
  const size_t stop = d.find("<CaptureStop");
  if (start != std::string_view::npos) {
    m.type = ViconMessage::Type::kStart;
    if (d.find("</CaptureStart>") == std::string_view::npos) return fail("CaptureStart is not closed");
  } else if (stop != std::string_view::npos) {
    m.type = ViconMessage::Type::kStop;
    if (d.find("</CaptureStop>") == std::string_view::npos) return fail("CaptureStop is not closed");
    const size_t tag_end = d.find('>', stop);
    const std::string_view tag = d.substr(stop, tag_end - stop);
    const size_t r = tag.find("RESULT=\"");
    if (r != std::string_view::npos) {
      const size_t q = tag.find('"', r + 8);
      if (q != std::string_view::npos) m.result = unescape(tag.substr(r + 8, q - r - 8));
    }
  } else {
    return fail("not a CaptureStart or CaptureStop message");
  }
  auto name = element_value(d, "Name");
  if (!name) return fail("no Name element");
  m.name = *name;
  m.notes = element_value(d, "Notes").value_or("");
  m.description = element_value(d, "Description").value_or("");
  m.database_path = element_value(d, "DatabasePath").value_or("");
  auto number = [&](const char* tag, auto& out) -> bool {
    auto v = element_value(d, tag);
    if (!v || v->empty()) return true;
    const auto* b = v->data();
    const auto* e = v->data() + v->size();
    auto [p, ec] = std::from_chars(b, e, out);
    return ec == std::errc() && p == e;
  };
  if (!number("Delay", m.delay_ms)) return fail("Delay is not an integer");
  if (!element_value(d, "PacketID")) return fail("no PacketID element");
  if (!number("PacketID", m.packet_id)) return fail("PacketID is not an unsigned integer");
  return m;
}

}  // namespace lmc::devices
