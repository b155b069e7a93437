#pragma once
// The layout report (core/metric/layout_report.h) as one Markdown page: the verdict, the metric
// terms split by palm orientation, what each controller contributes, and per reference pose how
// often each finger is seen by one and by two or more controllers. `lmc evaluate --report DIR` and
// the Layout tab write it through write_layout_report_files (layout_report_files.h).
#include <string>
#include <utility>
#include <vector>

#include "core/metric/layout_report.h"

namespace lmc {

// `figures`: (caption, file name) of pictures written beside the report; each is shown with its caption under it.
std::string format_layout_report_markdown(const LayoutReport& report,
                                          const std::vector<std::pair<std::string, std::string>>& figures = {});

}  // namespace lmc
