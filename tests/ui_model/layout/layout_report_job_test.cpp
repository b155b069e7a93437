// The Layout tab's "Report...": the job writes the same files as lmc evaluate --report
// for the edited layout and the loaded pose set, and says where; a folder it cannot write is a
// message, not a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/io/layout_json.h"
#include "tests/support/reference_data.h"
#include "ui/model/layout/layout_report_job.h"

namespace lmc::ui {
namespace layout_report_job_test {  // named: test files share unity batches

TEST(LayoutReportJob, WritesTheReportAndItsPicturesOnAWorker) {
  PoseSetChoice choice;
  choice.frames = 200;
  const PoseSetPtr poses = load_pose_set_for(choice, 1);
  const Layout layout = load_layout(test::asset_file("layouts/paper-initial.json"));
  const auto dir = test::scratch_dir("layout_report_job") / "report";
  LayoutReportJob job;
  EXPECT_EQ(job.message(), "");
  job.start(layout, poses, dir);
  job.wait();
  EXPECT_NE(job.message().find("wrote " + (dir / "report.md").string()), std::string::npos) << job.message();
  for (const char* f : {"report.md", "top-view.svg", "top-view.csv", "pose-redundancy.svg", "pose-redundancy.json",
                        "finger-coverage.svg", "finger-coverage.csv", "finger-coverage.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
  // A file where the folder should be: the message names the problem.
  const auto blocked = test::scratch_dir("layout_report_job_blocked") / "file";
  { std::ofstream(blocked) << "x"; }
  job.start(layout, poses, blocked);
  job.wait();
  EXPECT_EQ(job.message().rfind("report not written: ", 0), 0u) << job.message();
}

}  // namespace layout_report_job_test
}  // namespace lmc::ui
