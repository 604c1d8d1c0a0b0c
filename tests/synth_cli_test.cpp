// The synth, autolabel and eval --gt commands, run as the user runs them.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "shared_data.hpp"

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int code;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

CliRun run(const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = fieldlines::test::cli_path().string() + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

class SynthCli : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test: ctest may run them in parallel.
    dir_ = fs::temp_directory_path() /
           (std::string("fieldlines_synth_cli_") + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SynthCli, WritesImagesMasksAndTruthDeterministically) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(run("synth --scene kid --condition dim,shadows --n 2 --seed 4 --quiet -o " + a.string(), dir_).code, 0);
  ASSERT_EQ(run("synth --scene kid --condition dim,shadows --n 2 --seed 4 --quiet -o " + b.string(), dir_).code, 0);
  for (const char* stem : {"kid_4_0000", "kid_4_0001"}) {
    const std::string png = std::string(stem) + ".png", json = std::string(stem) + ".json";
    ASSERT_TRUE(fs::exists(a / png));
    EXPECT_TRUE(fs::exists(a / "masks" / png));
    EXPECT_TRUE(fs::exists(a / "truth" / json));
    EXPECT_EQ(slurp(a / png), slurp(b / png)) << stem;
    EXPECT_EQ(slurp(a / "truth" / json), slurp(b / "truth" / json));
  }
  EXPECT_NE(slurp(a / "truth" / "kid_4_0001.json").find("\"condition\":\"shadows\""), std::string::npos);
}

TEST_F(SynthCli, BadOptionsAreUsageErrors) {
  const std::string o = " -o " + (dir_ / "x").string();
  EXPECT_EQ(run("synth --scene futsal --n 1 --seed 1" + o, dir_).code, 2);
  EXPECT_NE(run("synth --scene futsal --n 1 --seed 1" + o, dir_).err.find("futsal"), std::string::npos);
  EXPECT_EQ(run("synth --scene ssl --seed 1" + o, dir_).code, 2);
  EXPECT_EQ(run("synth --scene ssl --n 1 --seed 1 --line-width 1" + o, dir_).code, 2);
  EXPECT_EQ(run("synth --scene ssl --n 1 --seed 1 --condition foggy" + o, dir_).code, 2);
  EXPECT_EQ(run("synth --scene ssl --n 1 --seed 1", dir_).code, 2);
  EXPECT_EQ(run("synth --help", dir_).code, 0);
}

TEST_F(SynthCli, CameraRangesFromTheCommandLine) {
  const fs::path set = dir_ / "high";
  const CliRun r = run("synth --scene ssl --height 0.5:0.5 --pitch 25:25 --roll 0 --n 2 --seed 3 --quiet -o " +
                           set.string(), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* stem : {"ssl_3_0000", "ssl_3_0001"}) {
    const auto truth = nlohmann::json::parse(slurp(set / "truth" / (std::string(stem) + ".json")));
    EXPECT_NEAR(truth["camera"]["position"][2].get<double>(), 0.5, 1e-9) << stem;
    EXPECT_NEAR(truth["camera"]["pitch_deg"].get<double>(), 25, 1e-9) << stem;
    EXPECT_NEAR(truth["camera"]["roll_deg"].get<double>(), 0, 1e-9) << stem;
  }
  const std::string o = " --n 1 --seed 1 -o " + (dir_ / "x").string();
  const CliRun backwards = run("synth --scene ssl --height 0.9:0.3" + o, dir_);
  EXPECT_EQ(backwards.code, 2);
  EXPECT_NE(backwards.err.find("--height: LO must not exceed HI"), std::string::npos) << backwards.err;
  EXPECT_EQ(run("synth --scene ssl --pitch 10" + o, dir_).code, 2);   // not LO:HI
  EXPECT_EQ(run("synth --scene ssl --roll 90" + o, dir_).code, 2);    // out of range
  EXPECT_FALSE(fs::exists(dir_ / "x" / "ssl_1_0000.png"));
}

TEST_F(SynthCli, DemoIsMadeOnceAndItsPathPrinted) {
  const fs::path demo = dir_ / "demo";
  const CliRun first = run("synth --demo -o " + demo.string(), dir_);
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_EQ(first.out, (demo / "project.json").string() + "\n");
  EXPECT_TRUE(fs::exists(demo / "images" / "ssl_2024_0029.png"));
  const auto stamp = fs::last_write_time(demo / "project.json");
  EXPECT_EQ(run("synth --demo -o " + demo.string(), dir_).code, 0);
  EXPECT_EQ(fs::last_write_time(demo / "project.json"), stamp);
}

TEST_F(SynthCli, AutolabelAndEvalAgainstTruth) {
  const fs::path set = dir_ / "set";
  ASSERT_EQ(run("synth --scene ssl --n 3 --seed 7 --quiet -o " + set.string(), dir_).code, 0);
  const CliRun label = run("autolabel " + set.string() + " --csv " + (dir_ / "rows.csv").string(), dir_);
  ASSERT_EQ(label.code, 0) << label.err;
  EXPECT_TRUE(fs::exists(set / "project.json"));
  const std::string csv = slurp(dir_ / "rows.csv");
  EXPECT_EQ(csv.rfind("img_path,", 0), 0u);
  EXPECT_NE(csv.find(",False,True,False"), std::string::npos);  // some marking rows
  const CliRun eval = run("eval --gt " + set.string() + " --json " + (dir_ / "score.json").string(), dir_);
  ASSERT_EQ(eval.code, 0) << eval.err;
  EXPECT_NE(eval.out.find("ssl          artificial       3"), std::string::npos) << eval.out;
  EXPECT_TRUE(fs::exists(dir_ / "score.json"));
  // A folder without ground truth is a fatal error naming the folder.
  fs::create_directories(dir_ / "empty");
  const CliRun bad = run("eval --gt " + (dir_ / "empty").string(), dir_);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("no image with ground truth"), std::string::npos) << bad.err;
}

// eval --per-image: each frame's own row under its group's, and its own scores in the JSON,
// which add up to the group's.
TEST_F(SynthCli, EvalPerImageGivesEachFramesRowAndTheyAddUpToItsGroup) {
  const fs::path set = dir_ / "set";
  ASSERT_EQ(run("synth --scene ssl --n 3 --seed 7 --quiet -o " + set.string(), dir_).code, 0);
  const CliRun eval = run("eval --gt " + set.string() + " --per-image --json " + (dir_ / "s.json").string(), dir_);
  ASSERT_EQ(eval.code, 0) << eval.err;
  for (const char* name : {"  ssl_7_0000.png", "  ssl_7_0001.png", "  ssl_7_0002.png"})
    EXPECT_NE(eval.out.find(name), std::string::npos) << eval.out;
  const auto group = nlohmann::json::parse(slurp(dir_ / "s.json"))["groups"][0];
  ASSERT_EQ(group["per_image"].size(), 3u);
  double visible = 0, covered = 0;
  long predicted = 0;
  for (const auto& image : group["per_image"]) {
    EXPECT_EQ(image["images"], 1);
    visible += image["marking"]["visible_px"].get<double>(), covered += image["marking"]["covered_px"].get<double>();
    predicted += image["marking"]["predicted"].get<long>();
  }
  EXPECT_GT(visible, 0);
  EXPECT_NEAR(visible, group["marking"]["visible_px"].get<double>(), 1e-6);
  EXPECT_NEAR(covered, group["marking"]["covered_px"].get<double>(), 1e-6);
  EXPECT_EQ(predicted, group["marking"]["predicted"].get<long>());
  // Without the flag, neither the rows nor the JSON's images.
  const CliRun plain = run("eval --gt " + set.string() + " --json " + (dir_ / "p.json").string(), dir_);
  EXPECT_EQ(plain.out.find("ssl_7_0000.png"), std::string::npos) << plain.out;
  EXPECT_FALSE(nlohmann::json::parse(slurp(dir_ / "p.json"))["groups"][0].contains("per_image"));
}

// eval --hand's second table: the detected field boundary against the drawn one, per column the
// drawing spans; a frame without field counts its height on each of them.
TEST_F(SynthCli, EvalHandScoresTheFieldBoundaryAgainstTheDrawnOne) {
  const fs::path data = dir_ / "data", truth = dir_ / "truth";
  fs::create_directories(data);
  fs::create_directories(truth);
  cv::Mat field(120, 200, CV_8UC3, cv::Scalar(60, 60, 60));            // a grey wall...
  field.rowRange(40, 120).setTo(cv::Scalar(40, 140, 40));             // ...above turf from row 40
  cv::line(field, {10, 80}, {190, 80}, cv::Scalar(255, 255, 255), 4);  // and a painted line
  ASSERT_TRUE(cv::imwrite((data / "field.png").string(), field));
  ASSERT_TRUE(cv::imwrite((data / "wall.png").string(), cv::Mat(120, 200, CV_8UC3, cv::Scalar(60, 60, 60))));
  const auto write_truth = [&](const std::string& image, const nlohmann::json& boundary) {
    const nlohmann::json j = {
        {"schema", "fieldlines-hand-truth"}, {"version", 1}, {"image", image}, {"width", 200}, {"height", 120},
        {"annotated_by", "test"},
        {"features", {{{"label", "marking"}, {"name", "line"}, {"points", {{10, 80, 4}, {190, 80, 4}}}},
                      {{"label", "field_boundary"}, {"name", "boundary"}, {"points", boundary}}}}};
    std::ofstream(truth / (fs::path(image).stem().string() + ".json")) << j.dump();
  };
  write_truth("field.png", {{0, 39.5, 0}, {199, 39.5, 0}});  // all 200 columns
  write_truth("wall.png", {{0, 50, 0}, {99, 50, 0}});        // 100 columns, and no field to find
  const CliRun eval =
      run("eval --hand " + truth.string() + " --data " + data.string() + " --json " + (dir_ / "s.json").string(), dir_);
  ASSERT_EQ(eval.code, 0) << eval.err;
  EXPECT_NE(eval.out.find("median px"), std::string::npos) << eval.out;
  const auto score = nlohmann::json::parse(slurp(dir_ / "s.json"))["total"]["hand_field_boundary"];
  EXPECT_EQ(score["columns"], 300);
  EXPECT_EQ(score["within_2pct_height"], 200) << eval.out;
  EXPECT_LE(score["median_error_px"].get<double>(), 2.4) << eval.out;
  // The stripes' centre lines against the drawn centres: 180 px drawn per frame; the built-in
  // thresholds keep the stripes off, so none found.
  EXPECT_NE(eval.out.find("centre R"), std::string::npos) << eval.out;
  const auto centre = nlohmann::json::parse(slurp(dir_ / "s.json"))["total"]["centre_lines"];
  EXPECT_NEAR(centre["truth_px"].get<double>(), 360, 1e-3);
  EXPECT_EQ(centre["detected_px"].get<double>(), 0);
}

// eval --gt --truth-camera gives the detector each frame's camera: on Kid frames of a held-out
// seed the circle on the turf finds more circles than the image fits alone; the options'
// misuse stops the run with the reason.
TEST_F(SynthCli, EvalWithTheTruthCameraFindsMoreCircles) {
  const fs::path set = dir_ / "kid";
  ASSERT_EQ(run("synth --scene kid --condition all --n 40 --seed 4242 --quiet -o " + set.string(), dir_).code, 0);
  const auto circles = [&](const std::string& options) {
    const fs::path out = dir_ / "score.json";
    const CliRun eval = run("eval --gt " + set.string() + " --features " + options + " --json " + out.string(), dir_);
    EXPECT_EQ(eval.code, 0) << eval.err;
    return nlohmann::json::parse(slurp(out))["total"]["circle"]["found"].get<int>();
  };
  const int alone = circles(""), exact = circles("--truth-camera"), off = circles("--truth-camera --camera-error 1,0.05");
  EXPECT_GT(exact, alone);
  EXPECT_GE(off, alone);
  for (const char* bad : {"--camera-error 1,0.05", "--truth-camera --camera-error 1", "--truth-camera --camera-error 40,0",
                                 "--truth-camera --camera-error 1,0.05x"}) {
    const CliRun r = run("eval --gt " + set.string() + " " + std::string(bad), dir_);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--camera-error"), std::string::npos) << bad << ": " << r.err;
  }
}

}  // namespace
