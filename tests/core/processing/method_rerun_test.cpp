// A method comparison fuses each trial twice but resamples and ray-traces it once
// (process_trial_with_method): the second method's result must be exactly what processing the
// trial from scratch with that method gives, every output file byte for byte.
#include <gtest/gtest.h>

#include "core/processing/trial_pipeline.h"
#include "core/processing/trial_summary.h"
#include "core/results/trial_outputs.h"
#include "tests/support/shared_real_trial.h"

namespace lmc {
namespace {

void expect_same_outputs(const TrialAnalysis& a, const TrialAnalysis& b) {
  const auto fa = trial_output_files(a, trial_summary_json(a)), fb = trial_output_files(b, trial_summary_json(b));
  ASSERT_EQ(fa.size(), fb.size());
  for (size_t i = 0; i < fa.size(); ++i) {
    EXPECT_EQ(fa[i].name, fb[i].name);
    EXPECT_TRUE(fa[i].contents == fb[i].contents) << fa[i].name << " differs";
  }
}

TEST(MethodRerun, TheOtherMethodFromAProcessedTrialIsThatMethodFromScratch) {
  const auto files = test::shared_real_trial_files();
  LMC_REQUIRE_REFERENCE_FILE(files.lmc);
  LMC_REQUIRE_REFERENCE_FILE(files.trc);
  const test::SharedRealTrial trial = test::load_shared_real_trial();
  ProcessOptions def, ref;
  def.method = FusionMethod::kDefault;
  ref.method = FusionMethod::kReference;
  const TrialAnalysis by_default = process_trial("Naiv_Static101", trial.recording, trial.layout, &trial.vicon, def);
  const TrialAnalysis by_reference = process_trial("Naiv_Static101", trial.recording, trial.layout, &trial.vicon, ref);
  ASSERT_TRUE(by_default.has_vicon);

  const TrialAnalysis reference_again = process_trial_with_method(by_default, "Naiv_Static101", ref);
  EXPECT_EQ(reference_again.method, FusionMethod::kReference);
  expect_same_outputs(reference_again, by_reference);
  const TrialAnalysis default_again = process_trial_with_method(by_reference, "Naiv_Static101", def);
  EXPECT_EQ(default_again.method, FusionMethod::kDefault);
  expect_same_outputs(default_again, by_default);
  // The two methods do differ on this trial, so the equality above is not that of two copies.
  EXPECT_NE(format_fused_points(by_default), format_fused_points(by_reference));
}

TEST(MethodRerun, RefusesALengthCorrectionWithTheReferenceMethod) {
  TrialAnalysis done;
  ProcessOptions ref;
  ref.method = FusionMethod::kReference;
  ref.length_correction = LengthCorrection{};
  try {
    (void)process_trial_with_method(done, "Naiv_Static101", ref);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("a length correction applies to the default fusion only"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace lmc
