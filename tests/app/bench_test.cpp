// Runs the built `lmc bench` (lmc::test::cli_path()) on a tiny workload: checks the report, not speed.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/visibility/visibility_kernel.h"
#include "tests/support/cli_runner.h"
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
  ASSERT_EQ(j["cases"].size(), 3u);
  EXPECT_EQ(j["cases"][0]["name"], "paper-initial");
  EXPECT_EQ(j["cases"][2]["name"], "random");
  EXPECT_EQ(j["cases"][2]["layouts"], 30);
  for (const auto& c : j["cases"]) {
    EXPECT_GT(c["single_thread_evals_per_s"].get<double>(), 0.0);
    EXPECT_GT(c["all_threads_evals_per_s"].get<double>(), 0.0);
  }
  EXPECT_EQ(j["search"]["particles"], 3);
  EXPECT_GT(j["search"]["seconds"].get<double>(), 0.0);
  EXPECT_EQ(j["kernel_build"], lmc::kernel_build_name(lmc::KernelBuild::kBest));
}

// LMC_KERNEL picks the kernel's build (a lab whose CPU runs AVX-512 slowly can keep AVX2); a value
// it does not know is said, and the fastest build runs.
TEST(LmcBench, LmcKernelPicksTheBuildAndABadValueIsSaid) {
  const auto dir = lmc::test::scratch_dir("cli_bench_kernel");
  const std::string args = "bench --frames 20 --min-seconds 0.01 --no-search --json";
  const CliRun base = run_lmc(args, dir / "baseline", "export LMC_KERNEL=baseline &&");
  ASSERT_EQ(base.exit_code, 0) << base.err;
  EXPECT_EQ(nlohmann::json::parse(base.out)["kernel_build"], "baseline");
  const CliRun avx2 = run_lmc(args, dir / "avx2", "export LMC_KERNEL=avx2 &&");
  ASSERT_EQ(avx2.exit_code, 0) << avx2.err;
  EXPECT_EQ(nlohmann::json::parse(avx2.out)["kernel_build"], lmc::kernel_build_name(lmc::KernelBuild::kAvx2));
  const CliRun bad = run_lmc(args, dir / "bad", "export LMC_KERNEL=sse9 &&");
  ASSERT_EQ(bad.exit_code, 0) << bad.err;
  EXPECT_NE(bad.err.find("LMC_KERNEL=sse9 is not avx512, avx2 or baseline"), std::string::npos) << bad.err;
  EXPECT_EQ(nlohmann::json::parse(bad.out)["kernel_build"], lmc::kernel_build_name(lmc::KernelBuild::kBest));
}

}  // namespace
