// `fieldlines train`, `eval` and `sweep` end to end through the built CLI.
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fieldlines/train/splits.hpp"
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
  EXPECT_EQ(p["objective"], "tp-fp:1.5");  // the ours protocol's default
  EXPECT_EQ(p["data"][0], data.string());
  EXPECT_EQ(p["counts"]["segments"], 300);
  for (const char* part : {"train", "test"})
    for (const char* cls : {"marking", "boundary"})
      for (const char* k : {"tp", "fp", "fn", "precision", "recall"}) EXPECT_TRUE(p[part][cls].contains(k)) << part << cls << k;
  EXPECT_GT(p["train"]["marking"]["recall"].get<double>(), 0.9);
  // Same seed, same file content apart from the date.
  // --quiet: nothing at all on stderr on success.
  const fs::path again = dir_ / "thr2.json";
  const CliRun quiet = run("train " + data.string() + " --seed 3 --particles 20 --iterations 20 --quiet -o " + again.string());
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_NE(quiet.out.find("wrote"), std::string::npos);
  EXPECT_EQ(fl::load_thresholds_file(again).thresholds, f.thresholds);
  EXPECT_FALSE(fl::load_thresholds_file(again).provenance.contains("cross_validation"));

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
    // Every seed's figures, whose median is the cell's.
    auto recalls = e["seed_recall"].get<std::vector<double>>();
    ASSERT_EQ(recalls.size(), 3u);
    ASSERT_EQ(e["seed_precision"].size(), 3u);
    std::sort(recalls.begin(), recalls.end());
    EXPECT_DOUBLE_EQ(recalls[1], e["recall"].get<double>());
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

TEST_F(Cli, FoldsCrossValidateIntoTheProvenance) {
  const fs::path data = csv("a.csv", 300), out = dir_ / "cv.json";
  const std::string common = " --seed 4 --particles 20 --iterations 20";
  const CliRun r = run("train " + data.string() + common + " --folds 4 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* text : {"cross-validation: 4 folds by image", "fold 4", "mean", "std", "training marking"})
    EXPECT_NE(r.err.find(text), std::string::npos) << text << " not in\n" << r.err;
  const fl::ThresholdsFile f = fl::load_thresholds_file(out);
  const nlohmann::json& cv = f.provenance["cross_validation"];
  EXPECT_EQ(cv["folds"], 4);
  EXPECT_EQ(cv["split"], "image");
  EXPECT_EQ(cv["seed"], 4);
  EXPECT_FALSE(cv.contains("boundary"));  // only the trained class
  ASSERT_EQ(cv["test_segments"].size(), 4u);
  long tested = 0;
  for (const auto& n : cv["test_segments"]) tested += n.get<long>();
  EXPECT_EQ(tested, 300);  // every row is tested exactly once
  const nlohmann::json& m = cv["marking"];
  for (const char* key : {"precision", "recall"}) {
    ASSERT_EQ(m[key].size(), 4u) << key;
    double sum = 0, ss = 0;
    for (const auto& v : m[key]) {
      EXPECT_TRUE(v.get<double>() >= 0 && v.get<double>() <= 1) << key;
      sum += v.get<double>();
    }
    const double mean = sum / 4;
    for (const auto& v : m[key]) ss += (v.get<double>() - mean) * (v.get<double>() - mean);
    EXPECT_NEAR(m[std::string("mean_") + key].get<double>(), mean, 1e-12) << key;
    EXPECT_NEAR(m[std::string("std_") + key].get<double>(), std::sqrt(ss / 3), 1e-12) << key;
  }
  EXPECT_GT(m["mean_recall"].get<double>(), 0.8);
  EXPECT_EQ(m["pooled"]["tp"].get<long>() + m["pooled"]["fn"].get<long>(), 100);  // all markings, once
  // The final thresholds are trained as without --folds.
  ASSERT_EQ(run("train " + data.string() + common + " --quiet -o " + (dir_ / "plain.json").string()).code, 0);
  EXPECT_EQ(fl::load_thresholds_file(dir_ / "plain.json").thresholds, f.thresholds);

  // Both classes, row split: one entry per class; quiet prints nothing.
  const CliRun both = run("train " + data.string() + common +
                          " --folds 25 --split row --class both --quiet -o " + (dir_ / "both.json").string());
  ASSERT_EQ(both.code, 0) << both.err;
  EXPECT_EQ(both.err, "");
  const nlohmann::json cv2 = fl::load_thresholds_file(dir_ / "both.json").provenance["cross_validation"];
  EXPECT_EQ(cv2["split"], "row");
  for (const char* cls : {"marking", "boundary"}) EXPECT_EQ(cv2[cls]["recall"].size(), 25u) << cls;
}

TEST_F(Cli, BadFoldsFailBeforeWritingAnything) {
  const fs::path data = csv("a.csv", 30), out = dir_ / "t.json";  // 30 rows on 20 images
  const std::pair<const char*, const char*> bad[] = {
      {"--folds 1", "--folds: expected a whole number in [2, 50], got '1'"},
      {"--folds 51", "--folds: expected a whole number in [2, 50], got '51'"},
      {"--folds five", "--folds: expected a whole number"},
      {"--folds 21", "--folds 21: the data has only 20 images"},
      {"--folds 31 --split row", "--folds 31: the data has only 30 labelled rows"},
  };
  for (const auto& [opts, message] : bad) {
    const CliRun r = run("train " + data.string() + " --iterations 5 " + opts + " -o " + out.string());
    EXPECT_EQ(r.code, 2) << opts;
    EXPECT_NE(r.err.find(message), std::string::npos) << opts << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << opts;
  }
}

TEST_F(Cli, AClassWithoutDataIsNotApplicableNotZero) {
  // Only markings and clutter labelled, and thresholds that never predict a boundary.
  std::vector<fl::ReferenceRow> rows = fl::read_reference_csv(csv("a.csv", 30));
  std::erase_if(rows, [](const fl::ReferenceRow& r) { return r.segment.label == fl::Label::Boundary; });
  const fs::path data = dir_ / "no_boundary.csv";
  fl::write_reference_csv(data, rows);
  fl::ThresholdsFile t;
  t.thresholds.boundary.thresholds = {1000.f, 0.f, 100000.f};
  fl::save_thresholds_file(dir_ / "t.json", t);
  const CliRun r = run("eval " + data.string() + " --thresholds " + (dir_ / "t.json").string() + " --json " +
                       (dir_ / "e.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json boundary = nlohmann::json::parse(fl::read_file(dir_ / "e.json"))["total"]["boundary"];
  EXPECT_TRUE(boundary["precision"].is_null()) << boundary;
  EXPECT_TRUE(boundary["recall"].is_null()) << boundary;
  EXPECT_NE(r.out.find("n/a"), std::string::npos) << r.out;
  const nlohmann::json marking = nlohmann::json::parse(fl::read_file(dir_ / "e.json"))["total"]["marking"];
  EXPECT_TRUE(marking["precision"].is_number()) << marking;
}

TEST_F(Cli, AProjectsRecordedSplitIsTheDefaultAndOptionsOverrideIt) {
  // The studio records its test split in the project; `fieldlines train project.json` must test
  // on the same segments, so the provenance and the test part follow the recorded split.
  const fs::path data = csv("a.csv", 300), proj = dir_ / "p.json";
  fl::Project project = fl::project_from_reference_rows(fl::read_reference_csv(data));
  project.split = {fl::SplitMode::ByRow, 0.5, 7};
  project.save(proj);
  const std::string common = " --particles 10 --iterations 10 --quiet -o ";
  ASSERT_EQ(run("train " + proj.string() + common + (dir_ / "t.json").string()).code, 0);
  const nlohmann::json p = fl::load_thresholds_file(dir_ / "t.json").provenance;
  EXPECT_EQ(p["split"], "row");
  EXPECT_DOUBLE_EQ(p["train_fraction"].get<double>(), 0.5);
  EXPECT_EQ(p["seed"], 7);
  EXPECT_EQ(p["counts"]["test_segments"], 150);  // half of the rows, not 30 % of the images
  // The same data as a CSV keeps SplitSpec's defaults (by image, 0.7, seed 1).
  ASSERT_EQ(run("train " + data.string() + common + (dir_ / "c.json").string()).code, 0);
  const nlohmann::json c = fl::load_thresholds_file(dir_ / "c.json").provenance;
  EXPECT_EQ(c["split"], "image");
  EXPECT_EQ(c["seed"], 1);
  EXPECT_EQ(c["counts"]["test_segments"], 90);  // 6 of the 20 images, 15 rows each
  // Options override the recorded split, one by one.
  ASSERT_EQ(run("train " + proj.string() + " --split image --seed 3" + common + (dir_ / "o.json").string()).code, 0);
  const nlohmann::json o = fl::load_thresholds_file(dir_ / "o.json").provenance;
  EXPECT_EQ(o["split"], "image");
  EXPECT_EQ(o["seed"], 3);
  EXPECT_DOUBLE_EQ(o["train_fraction"].get<double>(), 0.5);
  EXPECT_EQ(o["counts"]["test_segments"], 150);  // 10 of the 20 images
  // A recorded seed beyond --seed's range is used whole, as the studio uses it.
  project.split = {fl::SplitMode::ByRow, 0.5, 5'000'000'000ull};
  project.save(proj);
  ASSERT_EQ(run("train " + proj.string() + common + (dir_ / "b.json").string()).code, 0);
  const nlohmann::json b = fl::load_thresholds_file(dir_ / "b.json").provenance;
  EXPECT_EQ(b["seed"].get<std::uint64_t>(), 5'000'000'000ull);
  EXPECT_EQ(b["counts"]["test_segments"], fl::split_train_test(project.labelled(), project.split).test.size());
}
