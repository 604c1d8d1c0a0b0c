// The Camera tab's fit from the field's lines: on frames rendered from one fixed camera, the
// background fit recovers its pitch and roll from a start 3 degrees off, and Apply makes it the
// studio's camera; frames without lines report fit_camera's message and leave the camera as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/synth.hpp"
#include "fixtures.hpp"
#include "gui/model/camera_fit_job.hpp"
#include "gui/model/camera_tuning.hpp"
#include "gui/model/studio_controller.hpp"

namespace fs = fieldlines::studio;
using fieldlines::GroundCamera;

namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kPitch = 28, kRoll = -2.5, kHeight = 0.65;

// A project over `n` images written by `image(i)` into `folder`.
template <typename Image>
std::filesystem::path write_images_project(const std::filesystem::path& folder, int n, Image image) {
  fieldlines::Project project;
  for (int i = 0; i < n; ++i) {
    const std::string name = "frame_" + std::to_string(i) + ".png";
    cv::imwrite((folder / name).string(), image(i));
    project.images.push_back({name, {}});
  }
  const auto file = folder / "project.json";
  project.save(file);
  return file;
}

// Kid-size frames from one camera mount: pitch, roll and height fixed, fx 640.
cv::Mat rendered(int index) {
  fieldlines::synth::SynthParams p;
  p.field.scene = fieldlines::synth::Scene::Kid;
  fieldlines::synth::CameraRanges ranges = fieldlines::synth::default_camera_ranges(p.field.scene);
  ranges.pitch_min = ranges.pitch_max = kPitch;
  ranges.height_min = ranges.height_max = kHeight;
  ranges.roll = {kRoll, kRoll};
  ranges.fx_min = ranges.fx_max = 640;
  p.camera = ranges;
  return fieldlines::synth::generate(p, 33, index).bgr;
}

GroundCamera start_camera(double pitch_deg, double roll_deg) {
  return fs::with_pose(fs::typical_camera(640, 480), {pitch_deg, roll_deg, kHeight * 100});
}

struct FitProject {
  FitProject(const char* tag, int n, cv::Mat (*image)(int)) : dir(tag) {
    const auto file = write_images_project(dir.path(), n, image);
    fs::ControllerOptions options;
    options.load_pixels = false;
    controller.emplace(fieldlines::Project::load(file), file, options);
  }
  studio_test::TempDir dir;
  std::optional<fs::StudioController> controller;
};

}  // namespace

TEST(CameraFitJob, RecoversPitchAndRollFromAStartThreeDegreesOffAndApplyAdoptsIt) {
  FitProject p("camera_fit", 8, rendered);
  fs::StudioController& c = *p.controller;
  const GroundCamera start = start_camera(kPitch + 3, kRoll - 3);
  c.set_camera(start);
  ASSERT_TRUE(fs::start_camera_fit(c));
  EXPECT_TRUE(c.camera_fit().running());
  c.camera_fit().wait();
  const auto& outcome = c.camera_fit().outcome();
  ASSERT_TRUE(outcome);
  ASSERT_TRUE(outcome->ok()) << outcome->error();
  const fs::CameraFitResult& r = outcome->value();
  EXPECT_NEAR(r.fit.camera.pitch_rad / kDeg, kPitch, 0.5);
  EXPECT_NEAR(r.fit.camera.roll_rad / kDeg, kRoll, 0.5);
  EXPECT_EQ(r.frames, 8u);
  EXPECT_LT(r.fit.rms_after_deg, r.fit.rms_before_deg);
  std::printf("fit: pitch %.3f (truth %.1f), roll %.3f (truth %.1f), residual %.2f -> %.2f deg, %d lines in %d frames\n",
              r.fit.camera.pitch_rad / kDeg, kPitch, r.fit.camera.roll_rad / kDeg, kRoll, r.fit.rms_before_deg,
              r.fit.rms_after_deg, r.fit.lines_used, r.fit.frames_used);
  const auto summary = fs::fit_summary(r);
  ASSERT_GE(summary.size(), 5u);
  EXPECT_EQ(summary[0].rfind("pitch 31.00 -> ", 0), 0u) << summary[0];
  EXPECT_EQ(summary[1].rfind("roll -5.50 -> ", 0), 0u) << summary[1];
  EXPECT_NE(summary[summary.size() - 3].find("height 0.650 m kept"), std::string::npos) << summary[summary.size() - 3];
  // Until Apply the studio's camera is the start.
  EXPECT_EQ(c.camera()->pitch_rad, start.pitch_rad);
  ASSERT_TRUE(fs::apply_camera_fit(c));
  ASSERT_TRUE(c.camera());
  EXPECT_EQ(c.camera()->pitch_rad, r.fit.camera.pitch_rad);
  EXPECT_EQ(c.camera()->roll_rad, r.fit.camera.roll_rad);
  EXPECT_EQ(c.camera()->fx, r.fit.camera.fx);
  EXPECT_EQ(c.camera()->cx, start.cx);
  EXPECT_FALSE(c.camera_fit().outcome());  // taken: the before -> after lines are gone
  EXPECT_FALSE(fs::apply_camera_fit(c));
}

TEST(CameraFitJob, TheHeightComesFromThePaintedWidthWhenGiven) {
  FitProject p("camera_fit_height", 8, rendered);
  fs::StudioController& c = *p.controller;
  c.set_camera(fs::with_pose(start_camera(kPitch + 2, kRoll + 2), {kPitch + 2, kRoll + 2, 75}));
  fieldlines::CameraFitParams params;
  params.line_width_m = 0.05;
  ASSERT_TRUE(fs::start_camera_fit(c, params));
  c.camera_fit().wait();
  ASSERT_TRUE(c.camera_fit().outcome() && c.camera_fit().outcome()->ok()) << c.camera_fit().status();
  const auto& fit = c.camera_fit().outcome()->value().fit;
  EXPECT_TRUE(fit.height_fitted);
  EXPECT_NEAR(fit.camera.height_m, kHeight, 0.05);
  std::printf("height %.3f m (truth %.2f) from %d stripes\n", fit.camera.height_m, kHeight, fit.widths_used);
  c.camera_fit().discard();
  EXPECT_FALSE(c.camera_fit().outcome());
  EXPECT_NEAR(c.camera()->height_m, 0.75, 1e-12);  // discarded: unchanged
}

TEST(CameraFitJob, FramesWithoutLinesReportTheReasonAndKeepTheCamera) {
  FitProject p("camera_fit_green", 3, [](int) { return cv::Mat(480, 640, CV_8UC3, cv::Scalar(50, 140, 40)); });
  fs::StudioController& c = *p.controller;
  const GroundCamera start = start_camera(30, 0);
  c.set_camera(start);
  ASSERT_TRUE(fs::start_camera_fit(c));
  c.camera_fit().wait();
  const auto& outcome = c.camera_fit().outcome();
  ASSERT_TRUE(outcome);
  ASSERT_FALSE(outcome->ok());
  EXPECT_FALSE(outcome->error().empty());
  EXPECT_EQ(c.camera_fit().status(), "fit failed: " + outcome->error());
  EXPECT_FALSE(fs::apply_camera_fit(c));
  EXPECT_EQ(c.camera()->pitch_rad, start.pitch_rad);
  EXPECT_EQ(c.camera()->roll_rad, start.roll_rad);
  std::printf("green frames: %s\n", outcome->error().c_str());
}

TEST(CameraFitJob, NoCameraNoFit) {
  FitProject p("camera_fit_none", 1, [](int) { return cv::Mat(48, 64, CV_8UC3, cv::Scalar(50, 140, 40)); });
  EXPECT_FALSE(fs::start_camera_fit(*p.controller));
  EXPECT_FALSE(p.controller->camera_fit().running());
  GroundCamera bad = start_camera(30, 0);
  bad.fx = -1;
  EXPECT_THROW(p.controller->set_camera(bad), fieldlines::Error);
  EXPECT_FALSE(p.controller->camera());
}
