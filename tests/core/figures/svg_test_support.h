#pragma once
// Small readers of the SVG text for the figures tests: enough XML to check well-formedness and
// pick out elements, not a parser.
#include <string>
#include <vector>

namespace lmc::svg_test_support {

// Empty when every tag is closed in order (self-closing tags, <?...?> and comments allowed) and
// every '&' starts an entity; else what is wrong.
std::string xml_balance_problem(const std::string& doc);

// The value of attribute `name` of every element `<tag ...>` in the document, in order.
std::vector<std::string> attribute_values(const std::string& doc, const std::string& tag, const std::string& name);

// The text between <text ...> and </text> of every text element, in order.
std::vector<std::string> text_contents(const std::string& doc);

// Numbers in a path's d attribute, "M1.00,2.00 L3.00,4.00" → {1, 2, 3, 4}.
std::vector<double> path_numbers(const std::string& d);

}  // namespace lmc::svg_test_support
