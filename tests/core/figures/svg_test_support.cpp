#include "tests/core/figures/svg_test_support.h"

#include <cstdlib>

namespace lmc::svg_test_support {

std::string xml_balance_problem(const std::string& doc) {
  std::vector<std::string> open;
  size_t i = 0;
  while (i < doc.size()) {
    if (doc[i] == '&') {
      const size_t semi = doc.find(';', i);
      const std::string ent = semi == std::string::npos ? "" : doc.substr(i, semi - i + 1);
      if (ent != "&amp;" && ent != "&lt;" && ent != "&gt;" && ent != "&quot;" && ent != "&apos;")
        return "bare & at " + std::to_string(i);
      i = semi + 1;
      continue;
    }
    if (doc[i] != '<') {
      if (doc[i] == '>') return "bare > at " + std::to_string(i);
      ++i;
      continue;
    }
    if (doc.compare(i, 2, "<?") == 0) {
      const size_t end = doc.find("?>", i);
      if (end == std::string::npos) return "unterminated <?";
      i = end + 2;
      continue;
    }
    if (doc.compare(i, 4, "<!--") == 0) {
      const size_t end = doc.find("-->", i);
      if (end == std::string::npos) return "unterminated comment";
      i = end + 3;
      continue;
    }
    // A tag: find its end outside quoted attribute values.
    size_t j = i + 1;
    char quote = 0;
    for (; j < doc.size(); ++j) {
      if (quote) {
        if (doc[j] == quote)
          quote = 0;
        else if (doc[j] == '<')
          return "< inside an attribute at " + std::to_string(j);
      } else if (doc[j] == '"' || doc[j] == '\'') {
        quote = doc[j];
      } else if (doc[j] == '>') {
        break;
      }
    }
    if (j >= doc.size()) return "unterminated tag at " + std::to_string(i);
    const std::string tag = doc.substr(i + 1, j - i - 1);
    i = j + 1;
    if (tag.empty()) return "empty tag";
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name)
        return "</" + name + "> closes " + (open.empty() ? "nothing" : open.back());
      open.pop_back();
      continue;
    }
    if (tag.back() == '/') continue;
    open.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
  }
  if (!open.empty()) return "<" + open.back() + "> never closed";
  return {};
}

std::vector<std::string> attribute_values(const std::string& doc, const std::string& tag, const std::string& name) {
  std::vector<std::string> out;
  const std::string start = "<" + tag + " ", key = " " + name + "=\"";
  for (size_t i = doc.find(start); i != std::string::npos; i = doc.find(start, i + 1)) {
    const size_t end = doc.find('>', i);
    const size_t k = doc.find(key, i);
    if (k == std::string::npos || k > end) continue;
    const size_t v = k + key.size();
    out.push_back(doc.substr(v, doc.find('"', v) - v));
  }
  return out;
}

std::vector<std::string> text_contents(const std::string& doc) {
  std::vector<std::string> out;
  for (size_t i = doc.find("<text"); i != std::string::npos; i = doc.find("<text", i + 1)) {
    const size_t open_end = doc.find('>', i);
    const size_t close = doc.find("</text>", open_end);
    out.push_back(doc.substr(open_end + 1, close - open_end - 1));
  }
  return out;
}

std::vector<double> path_numbers(const std::string& d) {
  std::vector<double> out;
  const char* p = d.c_str();
  while (*p) {
    if ((*p >= '0' && *p <= '9') || *p == '-' || *p == '.') {
      char* end = nullptr;
      out.push_back(std::strtod(p, &end));
      p = end;
    } else {
      ++p;
    }
  }
  return out;
}

}  // namespace lmc::svg_test_support
