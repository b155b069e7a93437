// `lmc figures --length-correction FOLDER=FILE` applies a subject's finger-length correction to
// that folder's trials as the Review tab does (core/review/folder_length_corrections.h): finger
// lengths change and joint angles do not, the figures' sidecars name the file, and what cannot be
// used (a folder that is not an input, the reference fusion) is an error saying what to fix.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_runner.h"
#include "tests/support/quick_session.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace figures_length_correction_test {  // named: test files share unity batches

namespace fs = std::filesystem;
using test::CliRun;
using test::run_lmc;
using test::shell_quote;

TEST(LmcFigures, AppliesAFoldersLengthCorrectionAsTheReviewTabDoes) {
  const fs::path dir = test::scratch_dir("lmc_figures_length_correction");
  const fs::path s01 = dir / "S01";
  ASSERT_EQ(test::record_quick_session(s01, dir / "l", "S01", 3), "");
  const fs::path lengths = dir / "S01-lengths.json";
  CliRun r = run_lmc("length-correction fit " + shell_quote(s01.string()) +
                         " --trial Naiv_Static101 --subject S01 -o " + shell_quote(lengths.string()),
                     dir / "l");
  ASSERT_EQ(r.exit_code, 0) << r.all();

  const std::string cache = test::env_prefix("LMC_CACHE_DIR", (dir / "cache").string());
  const std::string base = "figures " + shell_quote(s01.string()) + " -o ";
  r = run_lmc(base + shell_quote((dir / "plain").string()), dir / "l", cache);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  const std::string correction = " --length-correction " + shell_quote(s01.string() + "=" + lengths.string());
  r = run_lmc(base + shell_quote((dir / "corrected").string()) + correction, dir / "l", cache);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  // Corrected results are processed, never the plain ones from the cache.
  EXPECT_NE(r.out.find("figures of 2 trial(s) (0 from the cache, 0 failed)"), std::string::npos) << r.out;

  const auto text = [&](const char* run, const char* file) { return test::read_text_file(dir / run / file); };
  EXPECT_NE(text("plain", "study-finger-length.csv"), text("corrected", "study-finger-length.csv"));
  EXPECT_NE(text("plain", "agreement.csv"), text("corrected", "agreement.csv"));
  EXPECT_EQ(text("plain", "study-joint-angles.csv"), text("corrected", "study-joint-angles.csv"));
  const std::string sidecar = text("corrected", "visibility-map.json");
  EXPECT_NE(sidecar.find("\"length_correction_files\""), std::string::npos) << sidecar;
  // As JSON writes it (a Windows path's backslashes doubled).
  EXPECT_NE(sidecar.find(nlohmann::json(lengths.string()).dump()), std::string::npos) << sidecar;
  EXPECT_EQ(text("plain", "visibility-map.json").find("length_correction_files"), std::string::npos);

  r = run_lmc(base + shell_quote((dir / "x").string()) + " --length-correction " +
                  shell_quote((dir / "S02").string() + "=" + lengths.string()),
              dir / "l", cache);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("expected FOLDER=FILE with FOLDER one of the inputs"), std::string::npos) << r.all();
  r = run_lmc(base + shell_quote((dir / "x").string()) + " --method reference" + correction, dir / "l", cache);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--length-correction applies to the default fusion only"), std::string::npos) << r.all();
  fs::remove_all(dir);
}

}  // namespace figures_length_correction_test
}  // namespace lmc
