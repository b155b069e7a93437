#pragma once
// The Layout tab's "Report...": the same one-page layout report as `lmc evaluate
// --report DIR` (core/reports/layout_report_files.h) for the layout being edited and the loaded pose
// set, built and written on a worker thread (about a second on 10,000 frames).
#include <filesystem>
#include <memory>
#include <string>

#include "core/layout/layout.h"
#include "ui/model/jobs/background_job.h"
#include "ui/model/layout/pose_set_store.h"

namespace lmc::ui {

class LayoutReportJob {
 public:
  // Copies the layout; the pose set is shared (immutable).
  void start(const Layout& layout, PoseSetPtr poses, const std::filesystem::path& dir);
  bool running() const { return job_.running(); }
  // Asks the worker to stop: a report not yet written is not written at all.
  void cancel() { job_.cancel(); }
  JobState state() const { return job_.state(); }
  void wait();  // tests
  // "wrote DIR/report.md (with top-view.svg and pose-redundancy.svg)", the error, or empty before a run.
  std::string message() const;

 private:
  struct Report {};
  BackgroundJob<std::filesystem::path, Report> job_;
};

}  // namespace lmc::ui
