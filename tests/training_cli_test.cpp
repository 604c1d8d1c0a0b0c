// `fieldlines train`, `eval` and `sweep` end to end through the built CLI.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fieldlines/atomic_file.hpp"
#include "fieldlines/dataset.hpp"
#include "fieldlines/reference_csv.hpp"
#include "fieldlines/thresholds_file.hpp"
#include "shared_data.hpp"

namespace fl = fieldlines;
namespace fs = std::filesystem;

namespace {

struct CliRun {
  int code;
  std::string out, err;
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fl_train_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliRun run(const std::string& args) {
    const std::string cmd = fl::test::cli_path().string() + " " + args + " >" + (dir_ / "out").string() + " 2>" +
                            (dir_ / "err").string();
    const int status = std::system(cmd.c_str());
    return {WEXITSTATUS(status), fl::read_file(dir_ / "out"), fl::read_file(dir_ / "err")};
  }

  // A labelled CSV of `n` segments over 20 images: markings, boundaries and clutter.
  fs::path csv(const std::string& name, int n) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<fl::ReferenceRow> rows;
    for (int i = 0; i < n; ++i) {
      fl::ReferenceRow r;
      r.image = "img" + std::to_string(i % 20) + ".png";
      fl::Segment& s = r.segment;
      s.x1 = 100, s.y1 = 5;
      s.saliency = 30 + 200 * u(rng);
      const int kind = i % 3;
      const float m = 20 + 100 * u(rng);
      if (kind == 0) s.grad_y = {m, 0.8f * m, m}, s.label = fl::Label::Marking;
      if (kind == 1) s.grad_y = {5, m, 5}, s.label = fl::Label::Boundary;
      if (kind == 2) s.grad_y = {m * (u(rng) - .5f), m * (u(rng) - .5f), m}, s.label = fl::Label::None;
      rows.push_back(r);
    }
    const fs::path p = dir_ / name;
    fl::write_reference_csv(p, rows);
    return p;
  }
  fs::path dir_;
};

}  // namespace

TEST_F(Cli, TrainWritesAValidThresholdsFileThatEvalReads) {
  const fs::path data = csv("a.csv", 300), out = dir_ / "thr.json";
  const CliRun r = run("train " + data.string() + " --seed 3 --particles 20 --iterations 20 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("training marking"), std::string::npos);  // progress on stderr
  const fl::ThresholdsFile f = fl::load_thresholds_file(out);
  const nlohmann::json& p = f.provenance;
  EXPECT_EQ(p["seed"], 3);
  EXPECT_EQ(p["objective"], "tp-fp");
  EXPECT_EQ(p["data"][0], data.string());
  EXPECT_EQ(p["counts"]["segments"], 300);
  for (const char* part : {"train", "test"})
    for (const char* cls : {"marking", "boundary"})
      for (const char* k : {"tp", "fp", "fn", "precision", "recall"}) EXPECT_TRUE(p[part][cls].contains(k)) << part << cls << k;
  EXPECT_GT(p["train"]["marking"]["recall"].get<double>(), 0.9);
  // Same seed, same file content apart from the date.
  const fs::path again = dir_ / "thr2.json";
  ASSERT_EQ(run("train " + data.string() + " --seed 3 --particles 20 --iterations 20 -o " + again.string()).code, 0);
  EXPECT_EQ(fl::load_thresholds_file(again).thresholds, f.thresholds);

  const CliRun e = run("eval " + data.string() + " --thresholds " + out.string() + " --per-image --json " +
                    (dir_ / "eval.json").string());
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_NE(e.out.find("img7.png"), std::string::npos);
  const auto j = nlohmann::json::parse(fl::read_file(dir_ / "eval.json"));
  EXPECT_EQ(j["files"][0]["images"].size(), 20u);
  const long tp = j["total"]["marking"]["tp"], fn = j["total"]["marking"]["fn"];
  EXPECT_EQ(tp + fn, 100);
}

TEST_F(Cli, ClearErrorsForBadInput) {
  const fs::path data = csv("a.csv", 30);
  CliRun r = run("train " + data.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("-o"), std::string::npos);
  std::ofstream(dir_ / "bad.csv") << fl::read_file(data) << "x.png,1,2,3,4,5,6,7,8,9,10,NaN,True,False,False\n";
  r = run("train " + (dir_ / "bad.csv").string() + " -o " + (dir_ / "t.json").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad.csv:32"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "t.json"));
  r = run("train " + data.string() + " --objective accuracy -o " + (dir_ / "t.json").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("objective"), std::string::npos);
  r = run("eval " + data.string() + " --thresholds " + data.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("a.csv"), std::string::npos);
  r = run("sweep " + data.string() + " --fractions 0.5,1.5");
  EXPECT_EQ(r.code, 2);
}

TEST_F(Cli, SweepPrintsTheTableAndWritesJson) {
  const fs::path a = csv("a.csv", 200), b = csv("b.csv", 150);
  const CliRun r = run("sweep " + a.string() + " " + b.string() +
                    " --fractions 0.2,0.5 --seeds 3 --protocol paper --json " + (dir_ / "s.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("precision"), std::string::npos);
  EXPECT_NE(r.out.find("50%"), std::string::npos);
  const auto j = nlohmann::json::parse(fl::read_file(dir_ / "s.json"));
  ASSERT_EQ(j.size(), 4u);
  for (const auto& e : j) {
    EXPECT_TRUE(e["precision"].get<double>() >= 0 && e["precision"].get<double>() <= 1);
    EXPECT_TRUE(e["fraction"] == 0.2 || e["fraction"] == 0.5);
  }
}

TEST_F(Cli, ProjectFilesAreDataToo) {
  // A project made from the CSV trains to the same thresholds as the CSV itself.
  const fs::path data = csv("a.csv", 120), proj = dir_ / "p.json";
  fl::project_from_reference_rows(fl::read_reference_csv(data)).save(proj);
  const std::string common = " --seed 2 --particles 10 --iterations 10 --train-fraction 1 -o ";
  ASSERT_EQ(run("train " + data.string() + common + (dir_ / "t1.json").string()).code, 0);
  const CliRun r = run("train " + proj.string() + common + (dir_ / "t2.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(fl::load_thresholds_file(dir_ / "t1.json").thresholds, fl::load_thresholds_file(dir_ / "t2.json").thresholds);
  EXPECT_TRUE(fl::load_thresholds_file(dir_ / "t2.json").provenance["test"].is_null());
}
