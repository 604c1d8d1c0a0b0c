// Every command answers -h and --help on stdout with usage and examples, and --version works.
// The help texts that list detector parameters and protocol values print them from their one
// definition (kDetectorParamSpecs, protocol_spec).
#include <cstdio>

#include <gtest/gtest.h>

#include "cli_test_support.hpp"
#include "fieldlines/detect/detector_params.hpp"
#include "fieldlines/train/protocols.hpp"

namespace fieldlines::test {
namespace {

class CliHelp : public TempDirTest {};

// " text ": found as a whole column of a help line.
std::string word(std::string_view text) {
  std::string w(1, ' ');
  w.append(text);
  w.push_back(' ');
  return w;
}

TEST_F(CliHelp, EveryCommandHasHelpWithExamples) {
  for (const char* command : {"detect", "bench", "calibrate", "train", "eval", "sweep", "synth", "autolabel", "convert"}) {
    for (const char* flag : {"--help", "-h"}) {
      const CliRun r = run_cli({command, flag}, dir_);
      EXPECT_EQ(r.exit_code, 0) << command << " " << flag << ": " << r.err;
      EXPECT_NE(r.out.find("usage: fieldlines " + std::string(command)), std::string::npos) << command << " " << flag;
      EXPECT_NE(r.out.find("examples:"), std::string::npos) << command << " " << flag << " has no examples";
    }
  }
}

TEST_F(CliHelp, HelpWinsWhereverItStands) {
  // After other options, and where a value option would otherwise take it as its value.
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"detect", "--quiet", "--help"}, {"train", "-o", "--help"}, {"autolabel", "--csv", "-h"}}) {
    const CliRun r = run_cli(args, dir_);
    EXPECT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
    EXPECT_NE(r.out.find("usage: fieldlines " + args[0]), std::string::npos) << args[0];
  }
}

TEST_F(CliHelp, DetectHelpListsEveryDetectorParameterWithDefaultAndRange) {
  const CliRun r = run_cli({"detect", "--help"}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t section = r.out.find("detector parameters");
  ASSERT_NE(section, std::string::npos) << r.out;
  int listed = 0;
  for (const ParamSpec& s : kDetectorParamSpecs) {
    if (!s.in_files) continue;  // not a key of a thresholds file
    // "  <name>  <default>  <range>  <unit>  <meaning>" on one line.
    const std::size_t at = r.out.find("\n  " + std::string(s.name) + " ", section);
    ASSERT_NE(at, std::string::npos) << s.name << " missing from detect --help";
    const std::string line = r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
    EXPECT_NE(line.find(word(param_default_text(s))), std::string::npos) << line;
    if (!s.range.empty()) {
      EXPECT_NE(line.find(s.range.to_string()), std::string::npos) << line;
    }
    if (!s.unit.empty()) {
      EXPECT_NE(line.find(word(s.unit)), std::string::npos) << line;
    }
    EXPECT_NE(line.find(std::string(s.help.substr(0, 20))), std::string::npos) << line;
    ++listed;
  }
  EXPECT_GE(listed, 12);
}

TEST_F(CliHelp, TrainingHelpShowsEachProtocolsValues) {
  const ProtocolSpec ours = protocol_spec(Protocol::Ours), paper = protocol_spec(Protocol::Paper);
  const auto pair = [](double o, double p) {
    char text[64];
    std::snprintf(text, sizeof text, "(ours %g, paper %g)", o, p);
    return std::string(text);
  };
  for (const char* command : {"train", "sweep"}) {
    const CliRun r = run_cli({command, "--help"}, dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("PSO iterations " + pair(ours.train.pso.iterations, paper.train.pso.iterations)),
              std::string::npos) << r.out;
    EXPECT_NE(r.out.find("PSO inertia " + pair(ours.train.pso.inertia, paper.train.pso.inertia)), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("ours " + ours.train.objective.name()), std::string::npos) << r.out;
    // Each protocol's summary, wrapped over lines: compared with line breaks and indents as one space.
    std::string flat;
    for (const char c : r.out)
      if (!((c == ' ' || c == '\n') && !flat.empty() && flat.back() == ' ')) flat += c == '\n' ? ' ' : c;
    for (const Protocol p : {Protocol::Ours, Protocol::Paper})
      EXPECT_NE(flat.find(std::string(to_string(p)) + ": " + protocol_summary(p)), std::string::npos) << r.out;
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
