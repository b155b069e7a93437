// Runs the built `lmc bench` (lmc::test::cli_path()) on a tiny workload: checks the report, not speed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/visibility/visibility_kernel.h"
#include "tests/support/cli_runner.h"
#include "tests/support/quick_session.h"
#include "tests/support/reference_data.h"

namespace {

using lmc::test::CliRun;
using lmc::test::read_text_file;
using lmc::test::run_lmc;

}  // namespace

namespace {

TEST(LmcBench, JsonHasTheDocumentedKeys) {
  const auto dir = lmc::test::scratch_dir("cli_bench");
  const CliRun r = run_lmc("bench --frames 50 --min-seconds 0.01 --particles 3 --iterations 1 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 50);
  EXPECT_GE(j["threads"].get<int>(), 1);
  ASSERT_EQ(j["cases"].size(), 6u);
  EXPECT_EQ(j["cases"][0]["name"], "paper-initial");
  EXPECT_EQ(j["cases"][2]["name"], "random");
  EXPECT_EQ(j["cases"][2]["layouts"], 30);
  EXPECT_EQ(j["cases"][3]["name"], "random-lmc");
  EXPECT_EQ(j["cases"][4]["name"], "random-lmc2");
  EXPECT_EQ(j["cases"][5]["name"], "random-mixed");
  // The mixed rigs against the uniform rigs of their two models, in adjacent rounds.
  const auto& mixed = j["mixed_rig"];
  EXPECT_EQ(mixed["frames"], 50);
  EXPECT_GE(mixed["rounds"].get<int>(), 15);
  for (const char* k : {"lmc_seconds", "lmc2_seconds", "mixed_seconds", "mixed_swapped_seconds", "ratio"}) {
    EXPECT_GT(mixed[k].get<double>(), 0.0) << k;
  }
  for (const auto& c : j["cases"]) {
    EXPECT_GT(c["single_thread_evals_per_s"].get<double>(), 0.0);
    EXPECT_GT(c["all_threads_evals_per_s"].get<double>(), 0.0);
  }
  EXPECT_EQ(j["search"]["particles"], 3);
  EXPECT_GT(j["search"]["seconds"].get<double>(), 0.0);
  // The three timed searches: the study's as the authors ran it, then both metrics on the table,
  // whose ratio is what the robust terms cost a search.
  ASSERT_EQ(j["searches"].size(), 3u);
  EXPECT_EQ(j["searches"][0]["name"], "study-box");
  EXPECT_EQ(j["searches"][0]["bounds"], "x=-1000:1000,z=-1000:1000,rx=-90:90,ry=-180:180");
  EXPECT_EQ(j["searches"][0]["seconds"], j["search"]["seconds"]);
  EXPECT_EQ(j["searches"][1]["name"], "study-table");
  EXPECT_EQ(j["searches"][1]["metric"], "study");
  EXPECT_EQ(j["searches"][2]["name"], "robust-table");
  EXPECT_EQ(j["searches"][2]["metric"], "robust");
  EXPECT_EQ(j["searches"][2]["bounds"], "x=-360:360,z=-360:360,rx=-90:90,ry=-180:180");
  EXPECT_GT(j["searches"][2]["best_cost"].get<double>(), 0.0);
  EXPECT_NEAR(j["robust_terms_cost"].get<double>(),
              j["searches"][2]["seconds"].get<double>() / j["searches"][1]["seconds"].get<double>() - 1.0, 1e-12);
  EXPECT_EQ(j["kernel_build"], lmc::kernel_build_name(lmc::KernelBuild::kBest));
  // The terms' cost per evaluation, from alternated runs on the same table layouts.
  const auto& terms = j["terms_per_evaluation"];
  EXPECT_EQ(terms["layouts"], 30);
  EXPECT_EQ(terms["bounds"], "x=-360:360,z=-360:360,rx=-90:90,ry=-180:180");
  EXPECT_EQ(terms["frames"], 50);
  EXPECT_GE(terms["pairs"].get<int>(), 15);
  EXPECT_GT(terms["study_seconds"].get<double>(), 0.0);
  EXPECT_GT(terms["robust_seconds"].get<double>(), 0.0);
  EXPECT_GT(terms["cost"].get<double>(), -1.0);  // a median of time ratios: any positive ratio
}

// --searches picks which searches run; a name it does not know is refused, naming it.
TEST(LmcBench, SearchesPicksTheTimedSearches) {
  const auto dir = lmc::test::scratch_dir("cli_bench_searches");
  const CliRun r =
      run_lmc("bench --frames 20 --min-seconds 0.01 --particles 2 --iterations 1 --searches robust-table --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["searches"].size(), 1u);
  EXPECT_EQ(j["searches"][0]["name"], "robust-table");
  EXPECT_FALSE(j.contains("search"));  // the study's search did not run
  EXPECT_FALSE(j.contains("robust_terms_cost"));
  const CliRun bad = run_lmc("bench --frames 20 --no-search --searches study-desk", dir / "bad");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("study-desk"), std::string::npos) << bad.err;
}

// LMC_KERNEL picks the kernel's build (a lab whose CPU runs AVX-512 slowly can keep AVX2); a value
// it does not know is said, and the fastest build runs.
TEST(LmcBench, LmcKernelPicksTheBuildAndABadValueIsSaid) {
  const auto dir = lmc::test::scratch_dir("cli_bench_kernel");
  const std::string args = "bench --frames 20 --min-seconds 0.01 --no-search --json";
  const CliRun base = run_lmc(args, dir / "baseline", lmc::test::env_prefix("LMC_KERNEL", "baseline"));
  ASSERT_EQ(base.exit_code, 0) << base.err;
  EXPECT_EQ(nlohmann::json::parse(base.out)["kernel_build"], "baseline");
  const CliRun avx2 = run_lmc(args, dir / "avx2", lmc::test::env_prefix("LMC_KERNEL", "avx2"));
  ASSERT_EQ(avx2.exit_code, 0) << avx2.err;
  EXPECT_EQ(nlohmann::json::parse(avx2.out)["kernel_build"], lmc::kernel_build_name(lmc::KernelBuild::kAvx2));
  const CliRun bad = run_lmc(args, dir / "bad", lmc::test::env_prefix("LMC_KERNEL", "sse9"));
  ASSERT_EQ(bad.exit_code, 0) << bad.err;
  EXPECT_NE(bad.err.find("LMC_KERNEL=sse9 is not avx512, avx2 or baseline"), std::string::npos) << bad.err;
  EXPECT_EQ(nlohmann::json::parse(bad.out)["kernel_build"], lmc::kernel_build_name(lmc::KernelBuild::kBest));
}

TEST(LmcBench, ProcessingTimesASubjectAsLmcProcessDoes) {
  const auto dir = lmc::test::scratch_dir("cli_bench_processing");
  ASSERT_EQ(lmc::test::record_quick_session(dir / "S01", dir / "logs", "S01", 2), "");
  const CliRun r = run_lmc("bench --processing " + (dir / "S01").string() + " --runs 2 --json", dir / "bench");
  ASSERT_EQ(r.exit_code, 0) << r.all();
  const auto j = nlohmann::json::parse(r.out)["processing"];
  EXPECT_GT(j["trials"].get<int>(), 0);
  EXPECT_EQ(j["runs"], 2);
  for (const char* method : {"default", "both"}) {
    const auto& m = j[method];
    ASSERT_EQ(m["wall_seconds"].size(), 2u) << method;
    ASSERT_EQ(m["cpu_seconds"].size(), 2u) << method;
    EXPECT_GT(m["median_wall_s"].get<double>(), 0.0) << method;
    EXPECT_GT(m["median_cpu_s"].get<double>(), 0.0) << method;
  }
  // A folder without trials is refused, naming it.
  std::filesystem::create_directories(dir / "empty");
  const CliRun none = run_lmc("bench --processing " + (dir / "empty").string() + " --runs 1", dir / "bench-empty");
  EXPECT_NE(none.exit_code, 0);
  EXPECT_NE(none.all().find("empty"), std::string::npos) << none.all();
}

}  // namespace
