// lmc session new|run|status — a whole subject session as one safe, resumable unit.
//   new     creates the session folder from a protocol (assets/protocols/) and prints its plan
//   run     records it: pre-flight per block, each trial through the trial engine, a quality
//           verdict after each, redo; a session that was cut off resumes where it stopped
//   status  the trial table (--json for scripts)
// The folder's journal is the truth (sessions/README.md); this file only talks to the operator.

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "app/lmc/command.h"
#include "app/lmc/sigint_flag.h"
#include "core/common/error.h"
#include "core/common/paths.h"
#include "core/session/protocol.h"
#include "core/session/session_folder.h"
#include "devices/session_runner/new_session_spec.h"
#include "devices/session_runner/session_runner.h"
#include "devices/sim/sim_config.h"
#include "devices/vicon/vicon_trigger.h"

namespace {

namespace fs = std::filesystem;
using namespace lmc::devices;
using lmc::SessionFolder;
using lmc::TrialStatus;

// ---- new ------------------------------------------------------------------------------------

struct NewArgs {
  std::string subject, protocol = "study", vicon, vicon_database, handedness = "right", operator_name, notes, out;
  double hand_length_mm = 0, hand_breadth_mm = 0, seconds = 0;
  long long counterbalance = -1;
};

void print_plan(const SessionFolder& folder) {
  const auto& st = folder.state();
  std::cout << "session " << folder.dir().string() << ": subject " << st.subject().subject_id << ", protocol "
            << st.protocol.name << ", " << st.trials.size() << " trials\n";
  std::string block;
  for (const auto& t : st.trials) {
    if (t.plan.layout_key != block) {
      block = t.plan.layout_key;
      std::cout << "  block " << block << ":\n";
    }
    std::cout << "    " << std::setw(3) << t.plan.index + 1 << "  " << t.plan.name << "\n";
  }
}

void run_new(const NewArgs& a) {
  NewSessionFields fields;
  fields.subject = a.subject;
  fields.handedness = a.handedness;
  fields.hand_length_mm = a.hand_length_mm;
  fields.hand_breadth_mm = a.hand_breadth_mm;
  fields.operator_name = a.operator_name;
  fields.notes = a.notes;
  fields.protocol = a.protocol;
  fields.vicon = a.vicon;
  fields.vicon_database = a.vicon_database;
  fields.seconds = a.seconds;
  fields.counterbalance = a.counterbalance;
  const lmc::NewSessionSpec spec = new_session_spec(fields);
  const fs::path dir = a.out.empty() ? lmc::default_session_dir(a.subject) : fs::path(a.out);
  const SessionFolder folder = SessionFolder::create(dir, spec);
  print_plan(folder);
  std::cout << "next: lmc session run " << dir.string() << " --backend sim|leapc\n";
}

// ---- status ---------------------------------------------------------------------------------

nlohmann::json status_json(const lmc::SessionState& st, const fs::path& dir) {
  nlohmann::json trials = nlohmann::json::array();
  for (const auto& t : st.trials) {
    nlohmann::json qc = nullptr;
    if (!t.attempts.empty() && t.attempts.back().quality.is_object()) {
      const auto& q = t.attempts.back().quality;
      qc = {{"verdict", q.value("verdict", std::string())}, {"reasons", q.value("reasons", nlohmann::json::array())}};
    }
    nlohmann::json attempts = nlohmann::json::array();
    for (const auto& a : t.attempts)
      attempts.push_back({{"attempt", a.number},
                          {"outcome", a.outcome},
                          {"reason", a.reason},
                          {"verdict", a.verdict()},
                          {"files", a.superseded_dir.empty() ? std::string(".") : a.superseded_dir}});
    trials.push_back({{"index", t.plan.index + 1},
                      {"name", t.plan.name},
                      {"block", t.plan.layout_key},
                      {"status", lmc::trial_status_name(t.status)},
                      {"attempts", static_cast<int>(t.attempts.size())},
                      {"attempt_history", attempts},
                      {"qc", qc}});
  }
  nlohmann::json calibration = nlohmann::json::object();
  for (const auto& [block, c] : st.calibration)
    calibration[block] = {
        {"status", c.status}, {"attempt", c.attempt}, {"trial", c.trial}, {"reason", c.reason}, {"summary", c.summary}};
  return {
      {"subject", st.subject().subject_id},
      {"calibration", calibration},
      {"protocol", st.protocol.name},
      {"folder", dir.string()},
      {"next_trial", st.next_trial() < 0 ? nlohmann::json(nullptr)
                                         : nlohmann::json(st.trials[static_cast<size_t>(st.next_trial())].plan.name)},
      {"warnings", st.warnings},
      {"trials", trials}};
}

void print_status(const lmc::SessionState& st, const fs::path& dir) {
  const nlohmann::json j = status_json(st, dir);
  int accepted = 0;
  std::cout << "subject " << j["subject"].get<std::string>() << ", protocol " << j["protocol"].get<std::string>()
            << "\n";
  for (const auto& t : j["trials"]) {
    const std::string status = t["status"];
    accepted += status == "accepted" ? 1 : 0;
    std::cout << std::setw(4) << t["index"].get<int>() << "  " << std::left << std::setw(18)
              << t["name"].get<std::string>() << std::setw(12) << status << std::right << std::setw(2)
              << t["attempts"].get<int>() << " attempt(s)";
    if (!t["qc"].is_null()) {
      std::cout << "  " << t["qc"]["verdict"].get<std::string>();
      const auto& reasons = t["qc"]["reasons"];
      if (!reasons.empty()) std::cout << ": " << reasons[0].get<std::string>() << (reasons.size() > 1 ? " …" : "");
    }
    std::cout << "\n";
  }
  for (const auto& [block, c] : st.calibration) {
    std::cout << "calibration of block " << block << ": " << (c.status.empty() ? "not yet" : c.status);
    if (c.attempt > 0) std::cout << " (" << c.trial << ")";
    if (!c.reason.empty()) std::cout << ": " << c.reason;
    std::cout << "\n";
  }
  std::cout << accepted << " of " << j["trials"].size() << " trials accepted";
  if (!j["next_trial"].is_null()) std::cout << "; next: " << j["next_trial"].get<std::string>();
  std::cout << "\n";
  for (const auto& w : j["warnings"]) std::cout << "warning: " << w.get<std::string>() << "\n";
}

// ---- run ------------------------------------------------------------------------------------

struct RunArgs {
  std::string dir, backend = "sim", sim_config, override_reason, vicon_export, skip_calibration;
  bool fast = false, automatic = false, quiet = false;
  long long seed = -1;
  double countdown_s = 3, stream_timeout_s = 10;
};

std::string trial_status_line(const TrialSnapshot& s, const std::string& trial) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(1) << trial << "  ";
  switch (s.phase) {
    case TrialPhase::kWaitingForStreams:
      o << "waiting for every controller";
      break;
    case TrialPhase::kCountdown:
      o << "starts in " << s.countdown_remaining_s << " s";
      break;
    case TrialPhase::kRecording:
      o << "recording " << s.recording_s << " s, " << s.remaining_s << " s left";
      break;
    case TrialPhase::kFinishing:
      o << "finishing";
      break;
    default:
      o << "…";
      break;
  }
  for (const auto& d : s.hub.devices) {
    if (d.slot.empty()) continue;
    o << " | " << d.slot << ' ' << std::setprecision(0) << d.rate_hz << " Hz "
      << (!d.connected     ? "LOST"
          : d.hand_present ? "hand"
                           : "----");
  }
  o << " | written " << s.recorder.frames_written;
  return o.str();
}

void print_verdict(const AttemptResult& r, const std::string& name) {
  std::cout << name << " (attempt " << r.attempt << "): " << r.outcome << ", verdict " << r.verdict() << "\n";
  if (r.quality)
    for (const auto& why : r.quality->reasons) std::cout << "    " << why << "\n";
}

void print_preflight(const PreflightReport& report) {
  std::cout << "pre-flight, layout '" << report.layout_name << "':\n";
  for (const auto& item : report.items)
    std::cout << "  [" << (item.ok ? " ok " : "FAIL") << "] " << item.check << ": " << item.detail << "\n";
}

// Watches for Ctrl-C and turns it into a stop request for the trial in progress.
class InterruptWatch {
 public:
  explicit InterruptWatch(std::stop_source& source)
      : thread_([&source](std::stop_token own) {
          while (!own.stop_requested()) {
            if (lmc::cli::take_sigint()) source.request_stop();
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
          }
        }) {}

 private:
  std::jthread thread_;
};

// The trial with a status line on stderr (at most twice a second) and the verdict on stdout.
AttemptResult run_one(SessionRunner& runner, int i, bool quiet) {
  std::stop_source stop;
  InterruptWatch watch(stop);
  const std::string name = runner.plan()[static_cast<size_t>(i)].name;
  auto last = std::chrono::steady_clock::now() - std::chrono::seconds(1);
  AttemptResult r = runner.run_trial(i, stop.get_token(), [&](const TrialSnapshot& s) {
    const auto now = std::chrono::steady_clock::now();
    if (quiet || now - last < std::chrono::milliseconds(500)) return;
    last = now;
    std::cerr << "\r" << trial_status_line(s, name) << "\033[K" << std::flush;
  });
  if (!quiet) std::cerr << "\r\033[K";
  print_verdict(r, name);
  return r;
}

// Pre-flight for trial i's block when it needs one. False when the operator (or --auto) stops.
bool clear_preflight(SessionRunner& runner, int i, const RunArgs& a, bool interactive) {
  if (!runner.needs_preflight(i)) return true;
  std::cout << runner.block_instructions(i) << "\n";
  for (;;) {
    const PreflightReport report = runner.preflight(i);
    print_preflight(report);
    if (report.ok()) return true;
    if (!a.override_reason.empty()) {
      runner.override_preflight(i, a.override_reason);
      std::cout << "pre-flight overridden: " << a.override_reason << "\n";
      return true;
    }
    if (!interactive) {
      std::cout << "pre-flight failed; fix the lines above and run again, or pass --override-preflight REASON\n";
      return false;
    }
    std::cout << "Enter: check again · o REASON: go ahead anyway (journaled) · q: stop\n> " << std::flush;
    std::string line;
    if (!std::getline(std::cin, line) || line == "q") return false;
    if (line.rfind("o ", 0) == 0 && line.size() > 2) {
      runner.override_preflight(i, line.substr(2));
      return true;
    }
  }
}

// The block's calibration step when the protocol has one and it is not done. --auto
// applies a fit without warnings, calibrates once more otherwise, and then keeps the nominal
// layout saying why; interactively the operator reads the residual table and decides. False when
// the operator stops.
bool clear_calibration(SessionRunner& runner, int i, const RunArgs& a, bool interactive) {
  if (!runner.needs_calibration(i)) return true;
  const std::string block = runner.plan()[static_cast<size_t>(i)].layout_key;
  if (!a.skip_calibration.empty()) {
    runner.keep_nominal_layout(i, "calibration skipped: " + a.skip_calibration);
    std::cout << "block " << block << ": calibration skipped (" << a.skip_calibration << "), nominal layout kept\n";
    return true;
  }
  const auto& step = *runner.protocol().calibration;
  for (int tries = 0;; ++tries) {
    std::cout << "\ncalibration of block " << block << " (" << step.duration_s
              << " s)\n  operator: " << step.operator_cue << "\n  subject:  " << step.subject_cue << "\n";
    if (interactive) {
      std::cout << "Enter: record · n: keep the nominal layout · q: stop\n> " << std::flush;
      std::string line;
      if (!std::getline(std::cin, line) || line == "q") return false;
      if (line == "n") {
        runner.keep_nominal_layout(i, "the operator kept the nominal layout");
        return true;
      }
    }
    std::stop_source stop;
    InterruptWatch watch(stop);
    const BlockCalibration c = runner.calibrate_block(i, stop.get_token());
    if (!c.ok()) {
      std::cout << c.trial_name << ": no calibration: " << c.failure << "\n";
      if (lmc::cli::sigint_raised()) return false;
    } else {
      std::cout << c.trial_name << ":\n" << c.residual_table;
    }
    if (interactive) {
      std::cout << (c.ok() ? "a: apply · " : "") << "Enter: calibrate again · n: keep the nominal layout · q: stop\n> "
                << std::flush;
      std::string line;
      if (!std::getline(std::cin, line) || line == "q") return false;
      if (line == "a" && c.ok()) {
        runner.apply_calibration(c);
        std::cout << "block " << block << " now records with '" << c.fit->calibrated.name << "'\n";
        return true;
      }
      if (line == "n") {
        runner.keep_nominal_layout(i, "the operator kept the nominal layout", &c);
        return true;
      }
      continue;
    }
    if (c.ok() && c.warnings.empty()) {
      runner.apply_calibration(c);
      std::cout << "block " << block << " now records with '" << c.fit->calibrated.name << "'\n";
      return true;
    }
    if (tries >= 1) {
      const std::string why = c.ok() ? "warnings after two attempts: " + c.warnings.front() : c.failure;
      runner.keep_nominal_layout(i, "automatic run: " + why, c.ok() ? &c : nullptr);
      std::cout << "block " << block << ": nominal layout kept (" << why << ")\n";
      return true;
    }
  }
}

void announce_resume(const SessionFolder& folder) {
  const auto& st = folder.state();
  int accepted = 0;
  for (const auto& t : st.trials) accepted += t.status == TrialStatus::kAccepted ? 1 : 0;
  for (const auto& w : st.warnings) std::cout << "warning: " << w << "\n";
  for (const auto& name : folder.recovered())
    std::cout << "notice: trial " << name << " was cut off while recording (the program stopped); its partial files "
              << "are kept under superseded/ and it will be recorded again\n";
  if (accepted > 0 && st.next_trial() >= 0)
    std::cout << "resuming: " << accepted << " of " << st.trials.size() << " trials accepted, continuing at "
              << st.trials[static_cast<size_t>(st.next_trial())].plan.name << "\n";
}

// --auto: every remaining trial once, accepting pass and warn and retrying a failed trial once.
int run_auto(SessionRunner& runner, SessionFolder& folder, const RunArgs& a) {
  int failed = 0;
  for (size_t k = 0; k < runner.plan().size(); ++k) {
    const int i = static_cast<int>(k);
    if (folder.state().trials[k].status == TrialStatus::kAccepted) continue;
    if (!clear_preflight(runner, i, a, false)) return 3;
    if (!clear_calibration(runner, i, a, false)) return 130;
    bool ok = false;
    for (int tries = 0; tries < 2 && !ok; ++tries) {
      const AttemptResult r = run_one(runner, i, a.quiet);
      if (r.outcome == "interrupted" && lmc::cli::sigint_raised()) return 130;
      ok = r.verdict() != "fail";
      if (ok) runner.accept(i);
    }
    if (!ok) ++failed;
  }
  return failed == 0 ? 0 : 2;
}

int run_interactive(SessionRunner& runner, SessionFolder& folder, const RunArgs& a) {
  int last = -1;
  for (;;) {
    const int i = folder.state().next_trial();
    if (i < 0) {
      std::cout << "every trial is accepted.\n";
      return 0;
    }
    if (!clear_preflight(runner, i, a, true)) return 3;
    if (!clear_calibration(runner, i, a, true)) return 0;
    const auto& plan = runner.plan()[static_cast<size_t>(i)];
    const auto& type = runner.protocol().trial_types[static_cast<size_t>(plan.trial_type)];
    std::cout << "\nnext: " << plan.name << " (" << i + 1 << " of " << runner.plan().size() << ", " << type.duration_s
              << " s)\n  operator: " << type.operator_cue << "\n  subject:  " << type.subject_cue << "\n";
    std::cout << "Enter: start · r: redo the last trial · a: accept the last trial despite its verdict · q: stop\n> "
              << std::flush;
    std::string line;
    if (!std::getline(std::cin, line) || line == "q") return 0;
    if (line == "r" || line == "a") {
      if (last < 0) {
        std::cout << "no trial recorded in this run yet\n";
        continue;
      }
      if (line == "a") {
        runner.accept(last);
        std::cout << runner.plan()[static_cast<size_t>(last)].name << " accepted by the operator\n";
        continue;
      }
      runner.redo(last);
      std::cout << runner.plan()[static_cast<size_t>(last)].name
                << " will be recorded again (the earlier attempt is kept under superseded/)\n";
      continue;
    }
    const AttemptResult r = run_one(runner, i, a.quiet);
    last = i;
    if (r.verdict() != "fail") runner.accept(i);
    lmc::cli::clear_sigint();
  }
}

void run_run(const RunArgs& a) {
  SessionFolder folder = SessionFolder::open(a.dir);
  SessionRunOptions options;
  options.backend = a.backend;
  options.fast = a.fast;
  if (!a.sim_config.empty()) options.sim = load_sim_config(a.sim_config);
  if (a.seed >= 0) options.sim.seed = static_cast<std::uint64_t>(a.seed);
  options.countdown_s = a.countdown_s;
  options.stream_timeout_s = a.stream_timeout_s;
  if (!a.vicon_export.empty()) options.vicon_export_dir = a.vicon_export;
  SessionRunner runner(folder, options);
  announce_resume(folder);

  std::optional<lmc::cli::ScopedSigint> sigint(std::in_place);
  const int code = a.automatic ? run_auto(runner, folder, a) : run_interactive(runner, folder, a);
  sigint.reset();
  std::cout << "\n";
  print_status(folder.state(), folder.dir());
  lmc::cli::command_exit_code() = code;
}

void setup_session(CLI::App& app) {
  app.require_subcommand(1);

  auto n = std::make_shared<NewArgs>();
  CLI::App* cmd_new = app.add_subcommand("new", "Create a subject session folder from a protocol and print its plan");
  cmd_new
      ->add_option("--subject", n->subject, "Pseudonymous subject id (letters, digits, _ and -; it names the folder)")
      ->required();
  cmd_new->add_option("--protocol", n->protocol, "Protocol: study, quick or a protocol file")->capture_default_str();
  cmd_new->add_option("--vicon", n->vicon, "Send the Vicon capture trigger to HOST[:PORT] for every trial");
  cmd_new->add_option("--vicon-database", n->vicon_database, "DatabasePath field of the Vicon trigger");
  cmd_new->add_option("--hand-length-mm", n->hand_length_mm,
                      "Subject's hand length (wrist crease to middle fingertip)");
  cmd_new->add_option("--hand-breadth-mm", n->hand_breadth_mm, "Subject's hand breadth across the knuckles");
  cmd_new->add_option("--handedness", n->handedness, "Hand measured")
      ->check(CLI::IsMember({"right", "left"}))
      ->capture_default_str();
  cmd_new->add_option("--operator", n->operator_name, "Who runs the session");
  cmd_new->add_option("--notes", n->notes, "Free text kept in the manifest");
  cmd_new->add_option("--counterbalance", n->counterbalance,
                      "Seed for a counterbalanced trial order (default: the protocol's block order)");
  cmd_new
      ->add_option("--seconds", n->seconds,
                   "Every trial this long instead of the protocol's durations (rehearsals, demos)")
      ->check(CLI::PositiveNumber);
  cmd_new->add_option("-o,--output", n->out, "Session folder to create (default: the sessions folder / SUBJECT)");
  cmd_new->callback([n] { run_new(*n); });

  auto r = std::make_shared<RunArgs>();
  CLI::App* cmd_run = app.add_subcommand("run", "Record a session (resumes one that was cut off)");
  cmd_run->add_option("dir", r->dir, "Session folder made by lmc session new")->required();
  cmd_run->add_option("--backend", r->backend, "sim, leapc or replay:FILE")->capture_default_str();
  cmd_run->add_flag("--fast", r->fast, "Simulated time: the simulator (or a replay) runs as fast as it can");
  cmd_run->add_flag("--auto", r->automatic,
                    "No questions: start every trial, accept pass and warn, retry a failed trial once");
  cmd_run->add_option("--seed", r->seed, "Simulator seed (each trial and attempt derives its own from it)");
  cmd_run->add_option("--sim-config", r->sim_config, "Simulator settings (JSON)");
  cmd_run->add_option("--countdown", r->countdown_s, "Seconds of countdown before each trial (real time only)")
      ->capture_default_str();
  cmd_run
      ->add_option("--stream-timeout", r->stream_timeout_s,
                   "Abort a trial when not every controller streams within this many s")
      ->capture_default_str();
  cmd_run->add_option("--vicon-export", r->vicon_export,
                      "Folder where Vicon saves its files: each verdict says whether the trial's file appeared");
  cmd_run->add_option("--override-preflight", r->override_reason,
                      "Go ahead although the pre-flight fails; the reason is journaled");
  cmd_run->add_option(
      "--skip-calibration", r->skip_calibration,
      "When the protocol calibrates each block: keep the nominal layouts instead; the reason is journaled");
  cmd_run->add_flag("--quiet", r->quiet, "No live status line");
  cmd_run->callback([r] { run_run(*r); });

  auto s = std::make_shared<std::pair<std::string, bool>>();
  CLI::App* cmd_status = app.add_subcommand("status", "Print a session's trial table");
  cmd_status->add_option("dir", s->first, "Session folder")->required();
  cmd_status->add_flag("--json", s->second, "Machine-readable");
  cmd_status->callback([s] {
    // Read-only: status never takes the lock, repairs or rewrites anything, so it is safe
    // while `lmc session run` or the workbench records into the same folder.
    const auto st = lmc::read_session_state(s->first);
    if (s->second)
      std::cout << status_json(st, s->first).dump(2) << "\n";
    else
      print_status(st, s->first);
  });
}

const lmc::cli::CommandRegistration session_command{
    "session", "Create, run and inspect subject sessions (the protocol)", 22, setup_session};

}  // namespace
