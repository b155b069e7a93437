// lmc report — aggregate processed sessions (folders written by `lmc process`) across trials and
// subjects into CSV tables and a Markdown summary (core/reports/session_report.h).
#include <algorithm>
#include <filesystem>
#include <iostream>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/io/atomic_write.h"
#include "core/io/json_checked.h"
#include "core/reports/session_report.h"

namespace {

struct ReportArgs {
  std::vector<std::string> sessions;
  std::string out;
};

void run_report(const ReportArgs& a) {
  namespace fs = std::filesystem;
  std::vector<lmc::ReportInput> inputs;
  for (const auto& s : a.sessions) {
    const fs::path root(s);
    if (!fs::is_directory(root))
      throw lmc::Error(lmc::ErrorLocation(s), "not a folder (give folders written by lmc process)");
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      const std::string name = e.path().filename().string();
      if (e.is_regular_file() && name.size() > 13 && name.ends_with(".summary.json")) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) std::cout << "warning: " << s << " holds no <trial>.summary.json (run lmc process first)\n";
    const std::string subject =
        root.filename().empty() ? root.parent_path().filename().string() : root.filename().string();
    for (const auto& f : files) {
      try {
        inputs.push_back({subject, lmc::read_json_file(f)});
      } catch (const std::exception& e) {
        std::cout << "skipped " << f.string() << ": " << e.what() << "\n";
      }
    }
  }
  if (inputs.empty()) throw lmc::Error("no processed trials found in the given folder(s)");
  const lmc::SessionReport rep = lmc::build_session_report(inputs);
  const fs::path out(a.out);
  fs::create_directories(out);
  lmc::write_file_atomically(out / "trials.csv", rep.trials_csv);
  lmc::write_file_atomically(out / "finger_length.csv", rep.finger_length_csv);
  lmc::write_file_atomically(out / "joint_angles.csv", rep.joint_angle_csv);
  lmc::write_file_atomically(out / "visibility.csv", rep.visibility_csv);
  lmc::write_file_atomically(out / "report.md", rep.markdown);
  std::cout << "report of " << rep.trials << " trial(s) (" << rep.trials_with_vicon << " with Vicon) written to "
            << a.out << ": report.md, trials.csv, finger_length.csv, joint_angles.csv, visibility.csv\n";
}

void setup_report(CLI::App& app) {
  auto a = std::make_shared<ReportArgs>();
  app.add_option("sessions", a->sessions, "Folders written by lmc process (one per subject/session)")->required();
  app.add_option("-o,--output", a->out, "Output folder")->required();
  app.callback([a] { run_report(*a); });
}

const lmc::cli::CommandRegistration report_command{
    "report", "Aggregate processed trials across sessions: CSV + Markdown", 45, setup_report};

}  // namespace
