// Bad-input matrix, outputs: every command's output path unwritable (a path under a regular
// file, or under /proc: tests run as root, so permissions prove nothing) and a full disk
// (simulated with a file-size limit). The command must exit 2 naming the path, and a file that
// was there before must be left exactly as it was.
#include <filesystem>

#include "bad_input_support.hpp"

namespace fs = std::filesystem;
using fieldlines::test::BadInputTest;
using fieldlines::test::CliRun;
using fieldlines::test::read_text;

namespace {

class BadOutputs : public BadInputTest {
 protected:
  void SetUp() override {
    BadInputTest::SetUp();
    blocker_ = bytes("plain_file", "a regular file, not a folder");
  }
  // A path whose parent is a regular file: no write can succeed there.
  fs::path under_file(const std::string& name) const { return blocker_ / name; }

  // The command-line arguments of every command with one output, the output path filled in.
  std::vector<std::string> command(const std::string& name, const fs::path& out) {
    if (name == "detect") return {"detect", "--quiet", "--json", out.string(), image_a(), image_b()};
    if (name == "detect-csv") return {"detect", "--quiet", "--csv", out.string(), image_a(), image_b()};
    if (name == "bench") return {"bench", "--quiet", "--repeat", "1", "--json", out.string(), image_a()};
    if (name == "train") return {"train", csv("d.csv").string(), "--quiet", "--iterations", "5", "-o", out.string()};
    if (name == "eval")
      return {"eval", csv("d.csv").string(), "--thresholds", thresholds("t.json").string(), "--json", out.string()};
    if (name == "sweep")
      return {"sweep", csv("d.csv").string(), csv("e.csv").string(), csv("f.csv").string(), "--quiet", "--seeds", "1",
              "--iterations", "5", "--json", out.string()};
    if (name == "autolabel") return {"autolabel", set(), "--quiet", "-o", out.string()};
    if (name == "autolabel-csv") return {"autolabel", set(), "--quiet", "-o", path("p.json").string(), "--csv", out.string()};
    if (name == "eval-gt") return {"eval", "--gt", set(), "--json", out.string()};
    if (name == "calibrate") return {"calibrate", image_a(), "--quiet", "-o", out.string()};
    if (name == "calibrate-json")
      return {"calibrate", image_a(), "--quiet", "-o", path("c.json").string(), "--json", out.string()};
    ADD_FAILURE() << name;
    return {};
  }
  std::string image_a() { return fs::exists(path("a.png")) ? path("a.png").string() : field_image("a.png").string(); }
  std::string image_b() {
    return fs::exists(path("b.png")) ? path("b.png").string() : image("b.png", fieldlines::test::synthetic_field(320, 240, 7)).string();
  }
  std::string set() { return fs::exists(path("set")) ? path("set").string() : synth_set("set").string(); }

  void expect_unwritable(const std::string& name, const std::vector<std::string>& parts) {
    const fs::path out = under_file("out.json");
    const CliRun r = run(command(name, out));
    std::vector<std::string> all = parts;
    all.push_back(out.string());
    EXPECT_CLI_FAILS(r, 2, all);
    EXPECT_EQ(read_text(blocker_), "a regular file, not a folder");
  }

  // Runs `name` with no room on the disk over an existing output file: exit 2 naming the file,
  // the old bytes untouched, no temporary file left behind.
  void expect_full_disk_keeps_old(const std::string& name, const std::string& old_contents) {
    const fs::path out = bytes("old_output", old_contents);
    const std::vector<std::string> args = command(name, out);  // makes the inputs first
    const auto before = list();
    const CliRun r = run_with_file_limit(args, 0);
    EXPECT_CLI_FAILS(r, 2, "cannot save '" + out.string() + "'", "File too large");
    EXPECT_EQ(read_text(out), old_contents);
    EXPECT_EQ(list(), before);
  }
  std::vector<std::string> list() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().filename().string().rfind("cli_", 0) != 0) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  fs::path blocker_;
};

// ---- unwritable output folder ---------------------------------------------------------------

TEST_F(BadOutputs, DetectJsonUnderAFile) { expect_unwritable("detect", {"--json", "does not exist"}); }
TEST_F(BadOutputs, DetectCsvUnderAFile) { expect_unwritable("detect-csv", {"--csv", "does not exist"}); }
TEST_F(BadOutputs, DetectDrawUnderAFile) {
  const CliRun r = run({"detect", "--quiet", "--draw", under_file("overlays").string(), image_a()});
  EXPECT_CLI_FAILS(r, 2, "--draw " + under_file("overlays").string(), "cannot create the folder");
}
TEST_F(BadOutputs, BenchJsonUnderAFile) { expect_unwritable("bench", {"--json", "does not exist"}); }
TEST_F(BadOutputs, TrainOutputUnderAFile) { expect_unwritable("train", {"-o", "does not exist"}); }
TEST_F(BadOutputs, EvalJsonUnderAFile) { expect_unwritable("eval", {"--json", "does not exist"}); }
TEST_F(BadOutputs, SweepJsonUnderAFile) { expect_unwritable("sweep", {"--json", "does not exist"}); }
// Checked before the labelling, not when saving at the end.
TEST_F(BadOutputs, AutolabelProjectUnderAFile) { expect_unwritable("autolabel", {"-o", "does not exist"}); }
TEST_F(BadOutputs, AutolabelCsvUnderAFile) { expect_unwritable("autolabel-csv", {"--csv", "does not exist"}); }
TEST_F(BadOutputs, EvalGroundTruthJsonUnderAFile) { expect_unwritable("eval-gt", {"--json", "does not exist"}); }
TEST_F(BadOutputs, CalibrateOutputUnderAFile) { expect_unwritable("calibrate", {"-o", "does not exist"}); }
TEST_F(BadOutputs, CalibrateJsonUnderAFile) { expect_unwritable("calibrate-json", {"--json", "does not exist"}); }
TEST_F(BadOutputs, SynthFolderUnderAFile) {
  const CliRun r = run({"synth", "--scene", "ssl", "--n", "1", "--seed", "1", "--quiet", "-o", under_file("set").string()});
  EXPECT_CLI_FAILS(r, 2, under_file("set").string());
}
TEST_F(BadOutputs, TrainOutputUnderProc) {
  const CliRun r = run(command("train", "/proc/fieldlines_thresholds.json"));
  EXPECT_CLI_FAILS(r, 2, "cannot save '/proc/fieldlines_thresholds.json'");
}

TEST_F(BadOutputs, TrainRefusesToReplaceAFileThatIsNotThresholds) {
  // `train labels.json -o labels.json` must not turn hours of labels into a thresholds file.
  const fs::path labels = project("labels.json");
  const std::string before = read_text(labels);
  const CliRun r = run({"train", labels.string(), "--quiet", "--iterations", "5", "-o", labels.string()});
  EXPECT_CLI_FAILS(r, 2, "refusing to overwrite -o " + labels.string(), "not a fieldlines thresholds file");
  EXPECT_EQ(read_text(labels), before);
  // A thresholds file, even one from an older run, is replaced as asked.
  const fs::path old = thresholds("old.json");
  const CliRun ok = run({"train", labels.string(), "--quiet", "--iterations", "5", "-o", old.string()});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(read_text(old), read_text(thresholds("defaults.json")));
}

TEST_F(BadOutputs, EvalAndSweepRefuseToWriteOverTheirInputs) {
  const fs::path data = csv("d.csv");
  const fs::path t = thresholds("t.json");
  const std::string data_before = read_text(data), t_before = read_text(t);
  for (const fs::path& victim : {data, t}) {
    const CliRun r = run({"eval", data.string(), "--thresholds", t.string(), "--json", victim.string()});
    EXPECT_CLI_FAILS(r, 2, "--json " + victim.string(), "is also an input file");
  }
  const CliRun r = run({"sweep", data.string(), "--quiet", "--seeds", "1", "--fractions", "0.5", "--iterations", "5",
                        "--json", (dir_ / "." / "d.csv").string()});
  EXPECT_CLI_FAILS(r, 2, "is also an input file");
  EXPECT_EQ(read_text(data), data_before);
  EXPECT_EQ(read_text(t), t_before);
}

// ---- full disk ------------------------------------------------------------------------------

TEST_F(BadOutputs, DetectJsonFullDiskKeepsTheOldFile) { expect_full_disk_keeps_old("detect", "{\"old\": true}\n"); }
TEST_F(BadOutputs, DetectCsvFullDiskKeepsTheOldFile) { expect_full_disk_keeps_old("detect-csv", "old csv\n"); }
TEST_F(BadOutputs, DetectDrawFullDiskReportsEveryOverlay) {
  // Overlays are per image: each failed write is that image's failure (exit 1), and an old
  // overlay of the same name is kept.
  const std::string a = image_a(), b = image_b();
  const fs::path old = bytes("ov/a.png", "old overlay");
  const CliRun r = run_with_file_limit({"detect", "--quiet", "--draw", path("ov").string(), a, b}, 0);
  EXPECT_CLI_FAILS(r, 1, "a.png: cannot save '" + old.string() + "': File too large", "b.png: cannot save",
                   "2 of 2 inputs failed");
  EXPECT_EQ(read_text(old), "old overlay");
}
TEST_F(BadOutputs, BenchJsonFullDiskKeepsTheOldFile) { expect_full_disk_keeps_old("bench", "{\"old\": 1}\n"); }
TEST_F(BadOutputs, TrainFullDiskKeepsTheOldThresholds) {
  expect_full_disk_keeps_old("train", read_text(thresholds("previous.json")));
}
TEST_F(BadOutputs, EvalJsonFullDiskKeepsTheOldFile) { expect_full_disk_keeps_old("eval", "{\"old\": 2}\n"); }
TEST_F(BadOutputs, SweepJsonFullDiskKeepsTheOldFile) { expect_full_disk_keeps_old("sweep", "[]\n"); }
TEST_F(BadOutputs, AutolabelFullDiskKeepsTheOldProject) {
  expect_full_disk_keeps_old("autolabel", read_text(project("previous.json", 9)));
}
TEST_F(BadOutputs, AutolabelCsvFullDiskKeepsTheOldCsv) {
  // The project is written first and fails first; the old CSV must survive either way.
  const fs::path out = bytes("old.csv", "old csv\n");
  const CliRun r = run_with_file_limit(command("autolabel-csv", out), 0);
  EXPECT_CLI_FAILS(r, 2, "cannot save", "File too large");
  EXPECT_EQ(read_text(out), "old csv\n");
}
TEST_F(BadOutputs, SynthFullDiskKeepsTheOldImageAndSaysSo) {
  const fs::path old = bytes("set/ssl_1_0000.png", "old image bytes");
  const CliRun r = run_with_file_limit({"synth", "--scene", "ssl", "--n", "1", "--seed", "1", "--quiet", "-o",
                                        path("set").string()}, 0);
  EXPECT_CLI_FAILS(r, 2, "cannot save '" + old.string() + "'", "File too large");
  EXPECT_EQ(read_text(old), "old image bytes");
}

}  // namespace
