#include "ui/model/layout/layout_report_job.h"

#include <thread>

#include "core/metric/layout_report.h"
#include "core/reports/layout_report_files.h"

namespace lmc::ui {

void LayoutReportJob::start(const Layout& layout, PoseSetPtr poses, const std::filesystem::path& dir) {
  job_.start([layout, poses, dir](std::stop_token stop, JobChannel<Report>&) {
    // Nothing is written once a stop is asked for: the report's files are written together or not.
    if (stop.stop_requested()) return std::filesystem::path();
    const LayoutReport report = build_layout_report(layout, poses->set, poses->prepared);
    if (stop.stop_requested()) return std::filesystem::path();
    return write_layout_report_files(dir, layout, poses->set, report, 10.0);
  });
}

void LayoutReportJob::wait() {
  while (job_.running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

std::string LayoutReportJob::message() const {
  switch (job_.state()) {
    case JobState::kIdle:
      return {};
    case JobState::kStarting:
    case JobState::kRunning:
      return "writing the layout report...";
    case JobState::kFailed:
      return "report not written: " + job_.error();
    case JobState::kCancelled:
      return "report cancelled";
    case JobState::kCompleted: {
      const auto path = job_.result();
      return path ? "wrote " + path->string() + " (with top-view.svg and pose-redundancy.svg)" : std::string();
    }
  }
  return {};
}

}  // namespace lmc::ui
