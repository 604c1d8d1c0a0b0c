// The Camera tab in the real window: the studio opened on rendered frames with --camera, the
// tab draws the ground grid over the frame, the pitch's + button moves it, Save writes the
// nudged camera, Fit from the lines shows its outcome; nothing crashes and the studio quits cleanly.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/camera_file.hpp"
#include "fieldlines/synth/synth.hpp"
#include "x_session.hpp"

using namespace std::chrono_literals;
using studio_test::run;
using studio_test::wait_for;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180;

class StudioCameraWindow : public studio_test::StudioUnderX {
 protected:
  void SetUp() override {
    StudioUnderX::SetUp();
    // A folder of frames from one camera mount (Kid size, pitch 28, roll -2.5, 0.65 m up).
    frames_ = dir() / "frames";
    std::filesystem::create_directories(frames_);
    fieldlines::synth::SynthParams p;
    p.field.scene = fieldlines::synth::Scene::Kid;
    auto ranges = fieldlines::synth::default_camera_ranges(p.field.scene);
    ranges.pitch_min = ranges.pitch_max = 28;
    ranges.height_min = ranges.height_max = 0.65;
    ranges.roll = {-2.5, -2.5};
    ranges.fx_min = ranges.fx_max = 640;
    p.camera = ranges;
    for (int i = 0; i < 3; ++i)
      cv::imwrite((frames_ / ("frame_" + std::to_string(i) + ".png")).string(), fieldlines::synth::generate(p, 41, i).bgr);
    camera_file_ = dir() / "start.json";
    fieldlines::GroundCamera start{640, 640, 319.5, 239.5, 31 * kDeg, 0.5 * kDeg, 0.65};
    fieldlines::write_file_atomically(camera_file_, fieldlines::to_json(start).dump(2));
    project_ = frames_;
  }
  // start_studio() with --camera.
  std::unique_ptr<studio_test::Child> start_with_camera() {
    std::filesystem::remove(state_);
    auto child = std::make_unique<studio_test::Child>(
        std::vector<std::string>{studio_test::studio_path().string(), project_.string(), "--camera",
                                 camera_file_.string(), "--window-size",
                                 std::to_string(kWidth) + "x" + std::to_string(kHeight), "--state-file", state_.string()},
        std::vector<std::string>{"DISPLAY=" + display_.name, "XDG_CONFIG_HOME=" + (dir() / "config").string(),
                                 "XDG_DATA_HOME=" + (dir() / "data").string(), "LIBGL_ALWAYS_SOFTWARE=1"},
        dir() / "studio.log");
    EXPECT_TRUE(wait_for([&] { return !state().is_null(); }, 30s)) << log();
    return child;
  }
  // A click ImGui sees whole: the pointer rests on the button for a few frames first and after
  // (a move, press and release within one frame would land wherever the pointer ends up).
  void click(int px, int py) {
    ASSERT_EQ(run(x("mousemove " + std::to_string(px) + " " + std::to_string(py))), 0);
    std::this_thread::sleep_for(150ms);
    ASSERT_EQ(run(x("click 1")), 0);
    std::this_thread::sleep_for(150ms);
  }
  // Pixels of the canvas (left of the side panel) that differ between two screenshots.
  static int canvas_change(const std::filesystem::path& a, const std::filesystem::path& b) {
    const cv::Mat x = cv::imread(a.string()), y = cv::imread(b.string());
    if (x.empty() || x.size() != y.size()) return -1;
    const cv::Rect canvas(0, 0, 860, 760);
    cv::Mat diff;
    cv::absdiff(x(canvas), y(canvas), diff);
    cv::cvtColor(diff, diff, cv::COLOR_BGR2GRAY);
    return cv::countNonZero(diff > 30);
  }
  std::filesystem::path frames_, camera_file_;
};

}  // namespace

TEST_F(StudioCameraWindow, TheCameraTabDrawsTheGridNudgesItAndSavesTheCamera) {
  auto studio = start_with_camera();
  ASSERT_TRUE(studio->running()) << log();
  ASSERT_TRUE(wait_for([&] { return state()["features"]["stripes"].get<int>() > 0 && !state()["detecting"].get<bool>(); }, 30s))
      << state().dump();
  ASSERT_EQ(run(x("mousemove 5 790")), 0);  // off the canvas: no hover halo
  std::this_thread::sleep_for(300ms);
  const auto before = screenshot("camera_before");
  // The Camera tab by its key (the screen positions below are the tab's layout at 1280x800).
  ASSERT_EQ(run(x("key F7")), 0);
  ASSERT_EQ(run(x("mousemove 5 790")), 0);
  std::this_thread::sleep_for(500ms);
  const auto grid = screenshot("camera_grid");
  EXPECT_GT(canvas_change(before, grid), 500) << "the tab drew no grid over the frame";

  // The pitch's + button four times: 31 -> 31.2 degrees, and the grid moves.
  for (int i = 0; i < 4; ++i) click(1084, 38);
  ASSERT_EQ(run(x("mousemove 5 790")), 0);
  std::this_thread::sleep_for(500ms);
  const auto nudged = screenshot("camera_nudged");
  EXPECT_GT(canvas_change(grid, nudged), 200) << "the grid did not move";

  // The nudge keys: Page Up twice (1 cm higher), Ctrl+Right once (0.05 degree of roll).
  ASSERT_EQ(run(x("key Page_Up Page_Up ctrl+Right")), 0);
  std::this_thread::sleep_for(300ms);

  // Save camera: the nudged camera beside the folder of frames.
  const std::filesystem::path saved = dir() / "frames-camera.json";
  click(916, 572);
  ASSERT_TRUE(wait_for([&] { return std::filesystem::exists(saved); }, 10s)) << "no camera file written";
  const fieldlines::GroundCamera camera = fieldlines::load_camera_file(saved);
  EXPECT_NEAR(camera.pitch_rad / kDeg, 31.2, 1e-6);
  EXPECT_NEAR(camera.roll_rad / kDeg, 0.55, 1e-6);
  EXPECT_NEAR(camera.height_m, 0.66, 1e-9);

  // Fit from the lines runs in the background and shows its result or its reason; the window
  // keeps drawing meanwhile and after.
  click(940, 440);
  ASSERT_EQ(run(x("mousemove 5 790")), 0);
  std::this_thread::sleep_for(3s);
  const auto fitted = screenshot("camera_fitted");
  EXPECT_TRUE(studio->running()) << log();
  // docs/studio.md's picture of the tab, when scripts/screenshots.sh asks for it.
  if (const char* docs = std::getenv("FIELDLINES_SCREENSHOT_DIR"); docs && *docs)
    std::filesystem::copy_file(fitted, std::filesystem::path(docs) / "studio-camera.png",
                               std::filesystem::copy_options::overwrite_existing);
  const cv::Mat panel_before = cv::imread(nudged.string()), panel_after = cv::imread(fitted.string());
  ASSERT_EQ(panel_before.size(), panel_after.size());
  const cv::Rect side(870, 450, 410, 100);  // between the Fit button and the camera file
  EXPECT_GT(cv::norm(panel_before(side), panel_after(side), cv::NORM_L1), 0) << "the fit showed nothing";

  ASSERT_EQ(run(x("key ctrl+q")), 0);
  ASSERT_TRUE(wait_for([&] { return !studio->running(); }, 15s));
  EXPECT_EQ(studio->exit_code(), 0) << log();
}
