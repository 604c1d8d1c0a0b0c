// Every command answers --help on stdout with usage and examples, and --version works.
#include <gtest/gtest.h>

#include "cli_test_support.hpp"

namespace fieldlines::test {
namespace {

class CliHelp : public TempDirTest {};

TEST_F(CliHelp, EveryCommandHasHelpWithExamples) {
  for (const char* command : {"detect", "bench", "train", "eval", "sweep", "synth", "autolabel", "convert"}) {
    const CliRun r = run_cli({command, "--help"}, dir_);
    EXPECT_EQ(r.exit_code, 0) << command << ": " << r.err;
    EXPECT_NE(r.out.find("usage: fieldlines " + std::string(command)), std::string::npos) << command;
    EXPECT_NE(r.out.find("examples:"), std::string::npos) << command << " --help has no examples";
  }
}

TEST_F(CliHelp, EvalGroundTruthHasItsOwnHelp) {
  const CliRun r = run_cli({"eval", "--gt", "--help"}, dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("examples:"), std::string::npos) << r.out;
}

TEST_F(CliHelp, TopLevelHelpVersionAndUnknownCommand) {
  CliRun r = run_cli({"--help"}, dir_);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("examples:"), std::string::npos);
  r = run_cli({"--version"}, dir_);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("fieldlines ", 0), 0u) << r.out;
  r = run_cli({"frobnicate"}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown command 'frobnicate'"), std::string::npos);
  r = run_cli({}, dir_);
  EXPECT_EQ(r.exit_code, 2);
}

}  // namespace
}  // namespace fieldlines::test
