// The `lmc` entry point: what a user sees before any command runs.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/cli_runner.h"

namespace {

using lmc::test::CliRun;
using lmc::test::run_lmc;

TEST(LmcMain, UnknownCommandIsNamedWithTheList) {
  const CliRun r = run_lmc("frob --json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown command 'frob'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" process"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(LmcMain, NoCommandPrintsTheHelp) {
  const CliRun r = run_lmc("");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("optimize"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lmc <command> --help"), std::string::npos) << r.err;
}

TEST(LmcMain, VersionAndCommandHelp) {
  const CliRun v = run_lmc("--version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.out.rfind("lmc ", 0), 0u) << v.out;
  const CliRun h = run_lmc("visibility --help");
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.out.find("--range-mm"), std::string::npos) << h.out;
}

}  // namespace
