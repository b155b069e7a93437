#pragma once
// One quoting rule for every CSV table core writes: the study's tables are read back by
// spreadsheets and pandas, and a free-text cell (a method description, a subject folder) may hold
// a comma or a quote.
#include <string>

namespace lmc {

// `s` as a CSV cell (RFC 4180): quoted, with inner quotes doubled, only when it holds , " or a
// newline.
std::string csv_cell(const std::string& s);

}  // namespace lmc
