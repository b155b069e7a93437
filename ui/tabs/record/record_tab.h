#pragma once
// The Record tab (record_tab.cpp says what it does): the composition root of the session model,
// the set-up form and the panels, and the keys and buttons mapped to the model's actions.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/model/record/record_setup_form.h"
#include "ui/model/record/record_state.h"
#include "ui/tabs/record/record_setup_panel.h"
#include "ui/tabs/record/record_trial_list_panel.h"
#include "ui/tabs/record/record_trial_panel.h"
#include "ui/tabs/record/subject_screen_controls_panel.h"
#include "ui/tabs/tab.h"

namespace lmc::ui {

class WorkbenchContext;
struct SubjectScreenLink;

std::unique_ptr<Tab> make_record_tab(StatusSink& status, WorkbenchContext& context);

class RecordTab final : public Tab {
 public:
  RecordTab(StatusSink& status, WorkbenchContext& context);

  void update(bool shown) override;
  void draw() override;
  std::string recording_now() const override;
  void stop_recording() override { model_->stop_trial(); }

  // ---- what a script may drive (--capture) --------------------------------------------------
  // The session and its actions (create, open, pre-flight, trial, redo, close).
  RecordState& model() { return *model_; }
  // The set-up form as the operator fills it in.
  RecordSetupForm& form() { return form_; }
  // Lists the sessions folder again (the form's "resume" list).
  void refresh_sessions();
  // Why the last create or open failed, under the set-up form ("" = none).
  void show_setup_error(std::string why) { error_ = std::move(why); }

 private:
  void draw_setup();
  void subject_clash_question();
  void create(bool same_subject_confirmed = false);
  void open();
  bool draw_header();
  void subject_screen_key();
  void act(TrialPanelAction a);
  std::string act_on_trial(TrialPanelAction a);
  std::optional<std::string> act_on_verdict(TrialPanelAction a);
  std::string trial_name(int i) const;
  void keys();

  StatusSink& status_;
  WorkbenchContext& context_;
  std::shared_ptr<RecordState> model_;  // the panels share it
  RecordSetupForm form_;
  std::vector<SessionListing> sessions_;  // for "resume": the sessions folder's contents
  SubjectScreenLink& subject_;
  RecordSetupPanel setup_panel_;
  RecordTrialListPanel trial_list_panel_;
  RecordTrialPanel trial_panel_;
  SubjectScreenControlsPanel subject_controls_;
  std::string error_;
  std::vector<SessionListing> subject_clash_;  // sessions of the id being created: the question is open
  bool open_at_start_ = false;
};

}  // namespace lmc::ui
