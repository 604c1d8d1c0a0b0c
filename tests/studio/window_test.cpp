// The real studio window under Xvfb (Mesa llvmpipe), driven with xdotool like a user: hover and
// click segments, press keys, check the project file on disk, capture the screen, SIGKILL the
// process mid-session and reopen. Also takes the panel screenshots: into the build folder, or
// into $FIELDLINES_SCREENSHOT_DIR when set (scripts/screenshots.sh refreshes docs/screenshots).
#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fieldlines/synth/demo.hpp"
#include "fixtures.hpp"
#include "gui/model/overlay_style.hpp"
#include "x_session.hpp"

namespace fs = std::filesystem;
using fieldlines::Label;
using namespace std::chrono_literals;

namespace {

using studio_test::rows_of_colour;
using studio_test::run;
using studio_test::wait_for;

// Two 640x480 images with 12 known segments each.
class StudioWindow : public studio_test::StudioUnderX {
 protected:
  void SetUp() override {
    StudioUnderX::SetUp();
    use_project(2, 12);
  }
};

// Count of pixels within `tol` of an RGB colour along segment i's drawn line.
int colour_hits(const cv::Mat& shot, const std::pair<int, int>& mid, fieldlines::studio::Rgba c, int tol = 40) {
  int hits = 0;
  for (int dx = -30; dx <= 30; ++dx) {
    for (int dy = -3; dy <= 3; ++dy) {
      const int px = mid.first + dx, py = mid.second + dy;
      if (px < 0 || py < 0 || px >= shot.cols || py >= shot.rows) continue;
      const cv::Vec3b p = shot.at<cv::Vec3b>(py, px);  // BGR
      if (std::abs(p[2] - c.r) <= tol && std::abs(p[1] - c.g) <= tol && std::abs(p[0] - c.b) <= tol) ++hits;
    }
  }
  return hits;
}

}  // namespace

TEST_F(StudioWindow, LabelByMouseAndKeysUndoRedoAndSurviveSigkill) {
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();

  // Segment 0: hover + key M. Segment 1: left click (brush = marking). Segment 2: key B.
  // Segment 3: right click = none. Segment 4: key N, then undone with Ctrl+Z and redone.
  hover(0);
  act_and_wait_for_save("key m");
  hover(1);
  act_and_wait_for_save("click 1");
  hover(2);
  act_and_wait_for_save("key b");
  hover(3);
  act_and_wait_for_save("click 3");
  hover(4);
  act_and_wait_for_save("key n");
  act_and_wait_for_save("key ctrl+z");
  {
    const auto p = fieldlines::Project::load(project_);
    EXPECT_EQ(p.images[0].segments[4].label, Label::Unlabelled);  // undone, on disk
    EXPECT_EQ(p.images[0].segments[3].label, Label::None);
  }
  act_and_wait_for_save("key ctrl+shift+z");

  const auto p = fieldlines::Project::load(project_);
  const auto& s = p.images[0].segments;
  EXPECT_EQ(s[0].label, Label::Marking);
  EXPECT_EQ(s[1].label, Label::Marking);
  EXPECT_EQ(s[2].label, Label::Boundary);
  EXPECT_EQ(s[3].label, Label::None);
  EXPECT_EQ(s[4].label, Label::None);
  for (std::size_t i = 5; i < s.size(); ++i) EXPECT_EQ(s[i].label, Label::Unlabelled) << i;


  // Wheel up over segment 10 zooms at the cursor: the same segment stays under the pointer.
  {
    const float fitted = state()["scale"].get<float>();
    hover(10);
    const auto before = on_screen(10);
    ASSERT_EQ(run(x("click 4")), 0);
    ASSERT_TRUE(wait_for([&] { return state()["scale"].get<float>() > fitted * 1.1f; }, 10s));
    EXPECT_NEAR(state()["scale"].get<float>(), fitted * 1.2f, fitted * 0.01f);
    const auto after = on_screen(10);
    EXPECT_NEAR(after.first, before.first, 1);
    EXPECT_NEAR(after.second, before.second, 1);
    EXPECT_EQ(state()["hovered"], 10);
    ASSERT_EQ(run(x("key f")), 0);  // fit again
    ASSERT_TRUE(wait_for([&] { return std::abs(state()["scale"].get<float>() - fitted) < 1e-4f; }, 10s));
  }

  // Drag a rectangle across the row of segments 8 and 9: both get the brush label (marking).
  {
    const auto a = on_screen(8), b = on_screen(9);
    ASSERT_EQ(run(x("mousemove " + std::to_string(a.first - 40) + " " + std::to_string(a.second - 10))), 0);
    std::this_thread::sleep_for(150ms);
    ASSERT_EQ(run(x("mousedown 1")), 0);
    std::this_thread::sleep_for(150ms);
    ASSERT_EQ(run(x("mousemove " + std::to_string((a.first + b.first) / 2) + " " + std::to_string(a.second))), 0);
    std::this_thread::sleep_for(150ms);
    act_and_wait_for_save("mousemove " + std::to_string(b.first + 40) + " " + std::to_string(b.second + 10) +
                          " mouseup 1");
    const auto r = fieldlines::Project::load(project_);
    EXPECT_EQ(r.images[0].segments[8].label, Label::Marking);
    EXPECT_EQ(r.images[0].segments[9].label, Label::Marking);
    EXPECT_EQ(r.images[0].segments[10].label, Label::Unlabelled);
    EXPECT_EQ(r.images[0].segments[7].label, Label::Unlabelled);
  }

  // The screen shows the image (green field) and each label's overlay colour on its segment.
  ASSERT_EQ(run(x("mousemove 5 5")), 0);  // away from the segments: no highlight, no tooltip
  ASSERT_TRUE(wait_for([&] { return state()["hovered"] == -1; }, 10s));
  std::this_thread::sleep_for(300ms);
  const cv::Mat shot = cv::imread(screenshot("labelled").string());
  ASSERT_FALSE(shot.empty());
  ASSERT_EQ(shot.cols, kWidth);
  const auto field_at = on_screen(6);  // a point between rows of segments: the field's green
  const cv::Vec3b field = shot.at<cv::Vec3b>(field_at.second + 20, field_at.first);
  EXPECT_NEAR(field[1], 140, 12);  // G of the fixture's (40, 140, 40) field
  EXPECT_NEAR(field[0], 40, 12);
  using fieldlines::studio::label_colour;
  EXPECT_GT(colour_hits(shot, on_screen(0), label_colour(Label::Marking)), 40);
  EXPECT_GT(colour_hits(shot, on_screen(2), label_colour(Label::Boundary)), 40);
  EXPECT_GT(colour_hits(shot, on_screen(3), label_colour(Label::None)), 40);
  EXPECT_GT(colour_hits(shot, on_screen(7), label_colour(Label::Unlabelled)), 20);
  EXPECT_EQ(colour_hits(shot, on_screen(7), label_colour(Label::Marking)), 0);
  // Unlabelled segments stand out on the turf and on the white line under them: across each,
  // the pixel that looks most unlike the turf is >= 90 Delta-E from it and from white (cyan,
  // the colour of earlier versions, reached 65 and 49), with the dark outline beside it.
  for (const std::size_t i : {7u, 10u, 11u}) {
    const auto [mx, my] = on_screen(i);
    const std::array<int, 3> turf{field[2], field[1], field[0]};
    double best = 0, best_vs_white = 0, darkest = 100;
    for (int dy = -6; dy <= 6; ++dy) {
      const cv::Vec3b p = shot.at<cv::Vec3b>(my + dy, mx);
      const std::array<int, 3> px{p[2], p[1], p[0]};
      const double d = studio_test::delta_e76(px, turf);
      if (d > best) best = d, best_vs_white = studio_test::delta_e76(px, {255, 255, 255});
      darkest = std::min(darkest, studio_test::lightness(px));
    }
    EXPECT_GE(best, 90.0) << "segment " << i;
    EXPECT_GE(best_vs_white, 90.0) << "segment " << i;
    EXPECT_LT(darkest, 20.0) << "segment " << i << ": no dark outline";
  }

  // Next image with the arrow key, label there, then SIGKILL right after the save.
  ASSERT_EQ(run(x("key Right")), 0);
  ASSERT_TRUE(wait_for([&] { return state()["image"] == 1; }, 10s));
  hover(5);
  act_and_wait_for_save("key b");
  studio->kill(SIGKILL);
  studio->wait();

  const auto killed = fieldlines::Project::load(project_);  // valid JSON project, nothing lost
  EXPECT_EQ(killed.images[1].segments[5].label, Label::Boundary);
  EXPECT_EQ(killed.images[0].segments[0].label, Label::Marking);
  // No temporary file of the project's save is left. (The test's state file is rewritten as the
  // view changes: the kill may land in one of its writes, which leaves that file's temporary.)
  const std::string project_temp = fieldlines::temporary_prefix(project_);
  for (const auto& entry : fs::directory_iterator(project_.parent_path())) {
    EXPECT_FALSE(entry.path().filename().string().starts_with(project_temp)) << "temporary file left: " << entry.path();
  }

  // Reopen: the studio starts on the same file, and the labels are still there after quitting.
  auto again = start_studio();
  ASSERT_TRUE(again->running()) << log();
  hover(6);
  act_and_wait_for_save("key m");
  ASSERT_EQ(run(x("key ctrl+q")), 0);
  ASSERT_TRUE(wait_for([&] { return !again->running(); }, 15s));
  EXPECT_EQ(again->exit_code(), 0);
  const auto reopened = fieldlines::Project::load(project_);
  EXPECT_EQ(reopened.images[1].segments[5].label, Label::Boundary);
  EXPECT_EQ(reopened.images[0].segments[6].label, Label::Marking);
}

// Export path as a user types it: click the field, Ctrl+A (from idle, where ImGui 1.86 lost the
// tap), "~/x/robot.json"; the folder is not there, so Enter writes nothing and the first button
// offers to create it; the file lands in $HOME/x, nothing named "~" anywhere.
TEST_F(StudioWindow, ExportPathExpandsTildeAndCreatesTheFolderWhenAsked) {
  const fs::path home = dir() / "home";
  fs::create_directories(home);
  const char* old_home = std::getenv("HOME");
  const std::string saved_home = old_home ? old_home : "";
  setenv("HOME", home.c_str(), 1);  // the studio inherits the test's environment
  auto studio = start_studio();
  if (old_home) setenv("HOME", saved_home.c_str(), 1);
  else unsetenv("HOME");
  ASSERT_TRUE(studio->running()) << log();

  ASSERT_EQ(run(x("mousemove " + std::to_string(kWidth - 60) + " 780")), 0);
  ASSERT_EQ(run(x("key F6")), 0);
  ASSERT_TRUE(wait_for([&] { return state()["panel"] == "Export"; }, 10s));
  std::this_thread::sleep_for(400ms);
  const std::array<int, 3> field_bg{29, 47, 73}, button_bg{36, 70, 110};  // ImGui's dark style
  const std::vector<int> fields = rows_of_colour(screenshot("export-before"), field_bg);
  ASSERT_FALSE(fields.empty()) << "no path field on the Export tab";
  ASSERT_EQ(run(x("mousemove 1000 " + std::to_string(fields.front()) + " click 1")), 0);
  ASSERT_EQ(run(x("mousemove " + std::to_string(kWidth - 60) + " 780")), 0);
  // Five rounds, each from idle: a lost select-all in any of them leaves the default path in
  // the field around the typed text, and the file is not written where expected.
  for (int round = 0; round < 5; ++round) {
    std::this_thread::sleep_for(1s);
    ASSERT_EQ(run(x("key ctrl+a")), 0);
    std::this_thread::sleep_for(150ms);  // a person's pause before typing on
    ASSERT_EQ(run(x("type '~/x/robot.json'")), 0);
  }
  ASSERT_EQ(run(x("key Return")), 0);
  std::this_thread::sleep_for(600ms);
  EXPECT_FALSE(fs::exists(home / "x")) << "Enter created a folder without being asked";

  const std::vector<int> buttons = rows_of_colour(screenshot("export-missing-folder"), button_bg);
  ASSERT_FALSE(buttons.empty()) << "no buttons on the Export tab";
  ASSERT_EQ(run(x("mousemove 900 " + std::to_string(buttons.front()) + " click 1")), 0);  // "Create folder and export"
  const fs::path written = home / "x" / "robot.json";
  ASSERT_TRUE(wait_for([&] { return fs::exists(written); }, 10s)) << "nothing written to " << written << "\n" << log();
  // The robot's file, with the project's thresholds.
  EXPECT_EQ(fieldlines::load_thresholds_file(written).thresholds, fieldlines::Project::load(project_).thresholds);
  for (const fs::path& folder : {dir(), project_.parent_path(), home}) {
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
      EXPECT_EQ(entry.path().filename().string().find('~'), std::string::npos) << entry.path();
    }
  }
  screenshot("export-written");
  ASSERT_EQ(run(x("key ctrl+q")), 0);
  EXPECT_EQ(studio->wait(), 0) << log();
}

TEST_F(StudioWindow, PanelScreenshotsOnTheDemoProject) {
  // The built-in demo (synthetic SSL frames, detected, the first ones labelled from the ground
  // truth), generated into the test's folder: what a new user sees first.
  fieldlines::DemoParams demo;
  demo.folder = dir() / "demo";
  demo.images_per_condition = 2;
  demo.labelled_images = 6;
  project_ = fieldlines::ensure_demo(demo);
  segments_ = fieldlines::Project::load(project_).images[0].segments;
  ASSERT_GE(segments_.size(), 4u);
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();

  const char* override_dir = std::getenv("FIELDLINES_SCREENSHOT_DIR");
  const fs::path docs = override_dir && *override_dir ? fs::path(override_dir) : studio_test::default_screenshot_dir();
  fs::create_directories(docs);
  const char* panels[] = {"Images", "Label", "Thresholds", "Train", "Metrics", "Export"};
  for (int i = 0; i < 6; ++i) {
    // Only the Label screenshot shows a hovered segment with its tooltip; elsewhere the pointer
    // rests on the status bar so nothing covers the plots.
    if (i == 1) {
      hover(segments_.size() / 2);
    } else {
      ASSERT_EQ(run(x("mousemove " + std::to_string(kWidth - 60) + " 780")), 0);
      ASSERT_TRUE(wait_for([&] { return state()["hovered"] == -1; }, 10s));
    }
    if (i == 3) {
      // Train: review three images first (P, Enter x3) so auto-train draws its learning curve,
      // then start a PSO run with Ctrl+T and capture once it has finished.
      ASSERT_EQ(run(x("key p")), 0);
      for (int enter = 0; enter < 3; ++enter) {
        const auto before = state()["to_review"];
        ASSERT_EQ(run(x("key Return")), 0);
        ASSERT_TRUE(wait_for([&] { return state()["to_review"] != before || enter == 0; }, 10s));
      }
      ASSERT_TRUE(wait_for([&] { return state()["auto_training"] == false; }, 30s));
      ASSERT_EQ(run(x("key ctrl+t")), 0);
      ASSERT_TRUE(wait_for([&] { return state()["trained"] == true; }, 120s));
    } else {
      ASSERT_EQ(run(x("key F" + std::to_string(i + 1))), 0);
    }
    ASSERT_TRUE(wait_for([&] { return state()["panel"] == panels[i]; }, 10s)) << panels[i];
    std::this_thread::sleep_for(400ms);
    const fs::path shot = screenshot(panels[i]);
    const cv::Mat image = cv::imread(shot.string());
    ASSERT_EQ(image.cols, kWidth);
    if (i == 3) {
      // The best-score curve is drawn (ImGui's grey plot line under the progress bar), and the
      // learning curve above it in the class colours (marking magenta).
      int curve = 0, learning = 0;
      for (int y = 30; y < 700; ++y) {
        for (int px = 880; px < 1270; ++px) {
          const cv::Vec3b p = image.at<cv::Vec3b>(y, px);  // BGR
          curve += y > 150 && std::abs(p[0] - 156) < 30 && std::abs(p[1] - 156) < 30 && std::abs(p[2] - 156) < 30;
          learning += std::abs(p[2] - 255) < 40 && std::abs(p[1] - 40) < 40 && std::abs(p[0] - 200) < 40;
        }
      }
      EXPECT_GT(curve, 100) << "no best-score curve in the Train panel";
      EXPECT_GT(learning, 20) << "no learning curve in the Train panel";
    }
    std::string name = panels[i];
    name[0] = static_cast<char>(std::tolower(name[0]));
    fs::copy_file(shot, docs / ("studio-" + name + ".png"), fs::copy_options::overwrite_existing);
  }
}
