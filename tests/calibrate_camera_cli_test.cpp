// `fieldlines calibrate-camera` end to end through the built CLI on rendered frames of one fixed
// camera (`fieldlines synth --roll LO:HI --fx LO:HI`), and bad input refused with exit 2, a
// message and no camera file.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"

namespace fl = fieldlines;
namespace fs = std::filesystem;
using fl::test::read_text;
using fl::test::run_cli;

namespace {

class CalibrateCamera : public fl::test::TempDirTest {
 protected:
  // `n` frames of a Kid-size field from one camera mount, set `seed`.
  fs::path frames(const std::string& name, double pitch, double roll, double height, int n, int seed) {
    const fs::path dir = dir_ / name;
    const auto fixed = [](double v) { return std::to_string(v) + ":" + std::to_string(v); };
    const auto r = run_cli({"synth", "--scene", "kid", "--height", fixed(height), "--pitch", fixed(pitch), "--roll",
                            fixed(roll), "--fx", "640:640", "--n", std::to_string(n), "--seed", std::to_string(seed),
                            "--quiet", "-o", dir.string()},
                           dir_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir;
  }
  fs::path camera_file(const std::string& name, double pitch, double roll, double height) {
    const nlohmann::json j{{"format", "fieldlines-camera"}, {"version", 1},     {"fx", 640},
                           {"fy", 640},                     {"cx", 319.5},      {"cy", 239.5},
                           {"pitch_deg", pitch},            {"roll_deg", roll}, {"height_m", height}};
    return write_bytes(name, j.dump());
  }
  // Exit code 2, `message` on stderr, no camera file.
  void refused(const std::vector<std::string>& args, const std::string& message) {
    const fs::path out = dir_ / "refused.json";
    std::vector<std::string> all{"calibrate-camera"};
    all.insert(all.end(), args.begin(), args.end());
    all.insert(all.end(), {"-o", out.string(), "--quiet"});
    const auto r = run_cli(all, dir_);
    EXPECT_EQ(r.exit_code, 2) << message << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << message;
  }
};

TEST_F(CalibrateCamera, SynthRendersOneFixedMount) {
  const fs::path set = frames("mount", 25, 2, 0.6, 2, 31);
  for (const auto& entry : fs::directory_iterator(set / "truth")) {
    const auto camera = nlohmann::json::parse(read_text(entry.path()))["camera"];
    EXPECT_DOUBLE_EQ(camera["roll_deg"].get<double>(), 2);
    EXPECT_DOUBLE_EQ(camera["pitch_deg"].get<double>(), 25);
    EXPECT_DOUBLE_EQ(camera["fx"].get<double>(), 640);
    EXPECT_DOUBLE_EQ(camera["position"][2].get<double>(), 0.6);
  }
  const auto backwards = run_cli({"synth", "--scene", "kid", "--roll", "3:-3", "--n", "1", "--seed", "1", "-o", (dir_ / "x").string()}, dir_);
  EXPECT_EQ(backwards.exit_code, 2);
  EXPECT_NE(backwards.err.find("--roll"), std::string::npos) << backwards.err;
  EXPECT_EQ(run_cli({"synth", "--scene", "kid", "--fx", "10:20", "--n", "1", "--seed", "1", "-o", (dir_ / "x").string()}, dir_).exit_code, 2);
}

TEST_F(CalibrateCamera, RecoversThePoseAndTheHeightOfRenderedFrames) {
  const fs::path set = frames("kid", 28, -2.5, 0.65, 8, 33);
  const fs::path start = camera_file("start.json", 32, 1.5, 0.75);
  const fs::path out = dir_ / "camera.json", report = dir_ / "fit.json";
  const auto r = run_cli({"calibrate-camera", set.string(), "--camera", start.string(), "-o", out.string(),
                          "--line-width", "0.05", "--json", report.string()},
                         dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto camera = nlohmann::json::parse(read_text(out));
  EXPECT_EQ(camera["format"], "fieldlines-camera");
  EXPECT_NEAR(camera["pitch_deg"].get<double>(), 28, 0.3) << r.out;
  EXPECT_NEAR(camera["roll_deg"].get<double>(), -2.5, 0.3) << r.out;
  EXPECT_NEAR(camera["height_m"].get<double>(), 0.65, 0.03) << r.out;
  EXPECT_NEAR(camera["fx"].get<double>(), 640, 6.4) << "the focal length fitted within 1 %";
  EXPECT_EQ(camera["cx"].get<double>(), 319.5);
  for (const char* says : {"frames: ", "pitch 32.00 -> ", "roll 1.50 -> ", "residual ", "height 0.750 -> "})
    EXPECT_NE(r.out.find(says), std::string::npos) << says << "\n" << r.out;
  const auto fit = nlohmann::json::parse(read_text(report));
  EXPECT_EQ(fit["frames"], 8);
  EXPECT_GT(fit["lines_used"].get<int>(), 10);
  EXPECT_LT(fit["rms_after_deg"].get<double>(), fit["rms_before_deg"].get<double>());
  EXPECT_TRUE(fit["height"]["fitted"].get<bool>());

  // Without the line width the start's height is kept, and the report says so.
  const auto kept = run_cli({"calibrate-camera", set.string(), "--camera", start.string(), "-o", out.string()}, dir_);
  ASSERT_EQ(kept.exit_code, 0) << kept.err;
  EXPECT_NEAR(nlohmann::json::parse(read_text(out))["height_m"].get<double>(), 0.75, 1e-9);
  EXPECT_NE(kept.out.find("kept"), std::string::npos) << kept.out;
}

TEST_F(CalibrateCamera, ACorruptImageIsReportedAndTheOthersFitted) {
  const fs::path set = frames("kid", 22, 1, 0.5, 6, 35);
  write_bytes("kid/broken.png", "not an image");
  const fs::path out = dir_ / "camera.json";
  const auto r = run_cli({"calibrate-camera", set.string(), "--camera", camera_file("s.json", 25, 0, 0.5).string(),
                          "-o", out.string(), "--quiet"},
                         dir_);
  EXPECT_EQ(r.exit_code, 1) << r.err;  // some inputs failed, the batch went on
  EXPECT_NE(r.err.find("broken.png"), std::string::npos) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(read_text(out))["pitch_deg"].get<double>(), 22, 0.3);
}

TEST_F(CalibrateCamera, BadInputIsRefusedWithoutACameraFile) {
  const fs::path set = frames("kid", 25, 0, 0.6, 3, 37);
  const fs::path start = camera_file("start.json", 27, 1, 0.6);
  refused({set.string(), "--camera", (dir_ / "missing.json").string()}, "missing.json");
  refused({set.string(), "--camera", write_bytes("bad.json", "{\"format\": ").string()}, "bad.json");
  refused({set.string()}, "missing --camera");
  refused({set.string(), "--camera", camera_file("up.json", -60, 0, 0.6).string()}, "sees no ground");
  refused({set.string(), "--camera", start.string(), "--line-width", "nan"}, "--line-width");
  refused({set.string(), "--camera", start.string(), "--line-width", "2"}, "--line-width");
  // Green frames: no line at all.
  const fs::path green = dir_ / "green";
  for (int i = 0; i < 2; ++i) write_image("green/g" + std::to_string(i) + ".png", cv::Mat(480, 640, CV_8UC3, cv::Scalar(50, 140, 40)));
  refused({green.string(), "--camera", start.string()}, "no lines");
  // Only unreadable frames.
  write_bytes("corrupt/a.png", "garbage");
  refused({(dir_ / "corrupt").string(), "--camera", start.string()}, "a.png");
  // Frames of two mounts far apart.
  const fs::path mixed = frames("mixed", 15, 8, 0.6, 4, 39);
  for (const auto& entry : fs::directory_iterator(frames("other", 42, -8, 0.6, 4, 41)))
    if (entry.is_regular_file()) fs::copy_file(entry.path(), mixed / ("other_" + entry.path().filename().string()));
  refused({mixed.string(), "--camera", camera_file("mid.json", 28, 0, 0.6).string()}, "contradict");
  // An -o path in a folder that does not exist: refused before any work.
  const auto r = run_cli({"calibrate-camera", set.string(), "--camera", start.string(), "-o", (dir_ / "no/such/c.json").string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no/such"), std::string::npos) << r.err;
}

}  // namespace

namespace {

// --place: where each frame's camera stands, from the centre circle and the halfway line, is the
// truth's (in the half asked for: the field is symmetric, so a truth in the other half is
// compared mirrored).
TEST_F(CalibrateCamera, PlaceFromTheCentreCircleIsTheTruths) {
  const fs::path set = frames("placed", 25, 2, 0.6, 12, 5);
  const fs::path report = dir_ / "placed.json";
  const auto r = run_cli({"calibrate-camera", set.string(), "--camera", camera_file("start.json", 22, 0, 0.5).string(),
                          "-o", (dir_ / "camera.json").string(), "--line-width", "0.05", "--place", "--json",
                          report.string(), "--quiet"},
                         dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int placed = 0;
  const nlohmann::json fitted = nlohmann::json::parse(read_text(report));
  for (const auto& frame : fitted.at("per_frame")) {
    if (frame.at("place").is_null()) continue;
    ++placed;
    const std::string image = frame["image"];
    const auto truth = nlohmann::json::parse(read_text(set / "truth" / (fs::path(image).stem().string() + ".json")))["camera"];
    double x = truth["position"][0], y = truth["position"][1], yaw = truth["yaw_deg"];
    if (x > 0) x = -x, y = -y, yaw += 180;
    EXPECT_NEAR(frame["place"]["x_m"].get<double>(), x, 0.1) << image;
    EXPECT_NEAR(frame["place"]["y_m"].get<double>(), y, 0.1) << image;
    EXPECT_NEAR(std::remainder(frame["place"]["yaw_deg"].get<double>() - yaw, 360.0), 0, 1.0) << image;
  }
  EXPECT_GE(placed, 2) << "the frames must show the centre circle and the halfway line";
  const auto without = run_cli({"calibrate-camera", set.string(), "--camera", (dir_ / "start.json").string(), "-o",
                                (dir_ / "c2.json").string(), "--positive-half"},
                               dir_);
  EXPECT_EQ(without.exit_code, 2);
  EXPECT_NE(without.err.find("--positive-half goes with --place"), std::string::npos) << without.err;
}

}  // namespace
