#include "ui/model/devices/live_rig.h"

#include <sstream>
#include <utility>

#include "devices/host_clock.h"
#include "devices/record/trial_name.h"
#include "devices/source_factory.h"

namespace lmc::ui {
namespace {

constexpr size_t kMaxMessages = 200;

// The new layout with the serials the operator bound on the rig, slot by slot, where the new
// layout binds none of its own: a layout edit in the Layout tab must not unplug controllers.
Layout keep_bindings(Layout next, const Layout& previous) {
  for (auto& d : next.devices) {
    if (d.serial) continue;
    for (const auto& p : previous.devices) {
      if (p.slot == d.slot && p.serial) d.serial = p.serial;
    }
  }
  return next;
}

std::string summary_of(const devices::TrialResult& r) {
  std::ostringstream s;
  s << "trial " << r.trial << " " << devices::trial_outcome_name(r.outcome);
  if (!r.reason.empty()) s << ": " << r.reason;
  if (r.recorded) {
    // Plain punctuation: the workbench's default font has Latin-1 glyphs only (an em dash shows as "?").
    s << "; " << r.recorder.frames_written << " frames from " << r.recorder.devices.size() << " devices in "
      << r.paths.recording.string();
  }
  return s.str();
}

}  // namespace

LiveRig::LiveRig(const CurrentLayout& layout)
    : current_(layout), layout_version_(layout.version()), layout_(layout.get()) {}

LiveRig::~LiveRig() {
  lent_ = false;  // whoever borrowed the hub is gone by now (the shell destroys the tabs first)
  stop();
}

std::string LiveRig::start(const std::string& backend, const devices::SimConfig& sim) {
  if (lent_) return "the Record tab's session records through the running controllers; close it first";
  stop();
  // A start always uses the workbench's latest layout, even before the first poll() saw it.
  if (current_.version() != layout_version_) {
    layout_version_ = current_.version();
    layout_change_pending_ = false;
    layout_ = keep_bindings(current_.get(), layout_);
  }
  try {
    const devices::SourceSpec spec = devices::parse_source_spec(backend);
    devices::SourceSettings settings;
    settings.layout = layout_;
    settings.sim = sim;
    auto hub = std::make_shared<devices::DeviceHub>(layout_);
    hub->add_source(devices::make_source(spec, settings));
    try {
      fusion_ = std::make_unique<devices::LiveFusion>(hub->layout());
      hub->add_tap(fusion_.get());
    } catch (const std::exception& e) {
      say(std::string("no live fused hand for layout '") + layout_.name + "': " + e.what());
    }
    hub->start();
    hub_ = std::move(hub);
    backend_ = backend;
    sim_config_ = sim;
    started_ns_ = devices::host_now_ns();
    say("started " + backend + " with layout '" + layout_.name + "'");
  } catch (const std::exception& e) {
    say(std::string("cannot start ") + backend + ": " + e.what());
    return e.what();
  }
  return {};
}

void LiveRig::stop() {
  if (lent_) {
    say("the Record tab's session records through the running controllers: they keep running until it is closed");
    return;
  }
  // The trial's worker records from the hub: it ends (keeping what it wrote) before the hub goes.
  if (trial_.running()) {
    trial_.cancel_and_join();
    finish_trial_if_done();
  }
  if (hub_) {
    layout_ = hub_->layout();  // keep the bindings for the next start
    hub_->stop();
    if (fusion_) hub_->remove_tap(fusion_.get());
    for (auto& m : hub_->take_messages()) say(std::move(m));
    hub_.reset();
    fusion_.reset();
    say("stopped " + backend_);
  }
}

double LiveRig::running_seconds() const {
  return hub_ ? static_cast<double>(devices::host_now_ns() - started_ns_) / 1e9 : 0.0;
}

std::string LiveRig::assign(const std::string& serial, const std::string& slot) {
  if (!hub_) return "no backend running";
  // The trial's recorder took the slot map when it started; it stays fixed until the trial ends.
  if (trial_.running()) return "cannot change slots while " + trial_.trial() + " records";
  std::string err = hub_->assign(serial, slot);
  if (err.empty()) layout_ = hub_->layout();
  return err;
}

void LiveRig::poll() {
  trial_.poll();
  for (auto& m : trial_.take_messages()) say(std::move(m));
  finish_trial_if_done();
  if (current_.version() != layout_version_) {
    layout_version_ = current_.version();
    layout_change_pending_ = true;
    if (trial_.running()) say("layout changed to '" + current_.get().name + "': the rig follows when the trial ends");
  }
  if (layout_change_pending_ && !trial_.running() && !lent_) apply_layout_change();
  // Outside a trial the engine is not draining the hub's messages: the rig does.
  if (hub_ && !trial_.running()) {
    for (auto& m : hub_->take_messages()) say(std::move(m));
  }
}

void LiveRig::apply_layout_change() {
  layout_change_pending_ = false;
  Layout next = keep_bindings(current_.get(), layout());
  if (!hub_) {
    layout_ = std::move(next);
    return;
  }
  // The hub realigns with the layout it was built with, and the simulator places its controllers
  // by it: a restart is the one way both follow the new layout.
  const std::string backend = backend_;
  const devices::SimConfig sim = sim_config_;
  stop();
  layout_ = std::move(next);
  if (start(backend, sim).empty()) say("layout changed to '" + layout_.name + "': restarted " + backend);
}

devices::DeviceHub* LiveRig::lend(const std::string& backend, std::string& error) {
  if (lent_) {
    error = "the controllers are already lent to a session";
    return nullptr;
  }
  if (trial_.running()) {
    error = "the Devices tab is recording " + trial_.trial() + "; stop it first";
    return nullptr;
  }
  if (!hub_ || backend_ != backend) {
    error = start(backend, sim_config_);
    if (!error.empty()) return nullptr;
  }
  lent_ = true;
  say("the Record tab's session records through " + backend_);
  return hub_.get();
}

void LiveRig::give_back() {
  if (!lent_) return;
  lent_ = false;
  say("the Record tab's session gave the controllers back");
}

void LiveRig::say(std::string text) {
  ++messages_total_;
  messages_.push_back(std::move(text));
  if (messages_.size() > kMaxMessages) messages_.erase(messages_.begin(), messages_.end() - kMaxMessages);
}

std::string LiveRig::start_trial(const std::filesystem::path& dir, const std::string& trial, double seconds) {
  if (!hub_) return "start a backend first";
  if (lent_) return "the Record tab's session records through these controllers; record there";
  if (trial_.running()) return "already recording " + trial_.trial();
  if (auto why = devices::validate_trial_name(trial); !why.empty()) return why;
  // Never overwrite (the TrialEngine's rule): pressing Record again with the same name records
  // <trial>-2, <trial>-3, … beside the earlier takes.
  std::string name;
  try {
    name = devices::next_free_trial_name(dir, trial);
  } catch (const std::exception& e) {
    return e.what();
  }
  devices::TrialEngineConfig cfg;
  cfg.output_dir = dir;
  cfg.trial = name;
  cfg.seconds = seconds;
  try {
    cfg.backend = devices::parse_source_spec(backend_).backend;
  } catch (const std::exception&) {
    cfg.backend = backend_;
  }
  // Wall-clock time, no simulator truth: the workbench's simulator runs in real time and never
  // ends, so the trial's length is the operator's seconds (sim = null).
  trial_.start(hub_, nullptr, std::move(cfg));
  trial_reported_ = false;
  say("recording " + name + " to " + dir.string() + (name == trial ? std::string() : " (" + trial + " is taken)"));
  return {};
}

void LiveRig::finish_trial_if_done() {
  if (trial_reported_ || !job_finished(trial_.state())) return;
  trial_reported_ = true;
  trial_.poll();
  for (auto& m : trial_.take_messages()) say(std::move(m));
  if (const auto r = trial_.result()) {
    trial_summary_ = summary_of(*r);
  } else {
    trial_summary_ = "trial " + trial_.trial() + " failed: " + trial_.error();
  }
  say(trial_summary_);
}

std::string LiveRig::take_trial_summary() {
  std::string out;
  out.swap(trial_summary_);
  return out;
}

}  // namespace lmc::ui
