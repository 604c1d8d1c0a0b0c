// The real panels drawn by ImGui without a window (a context, a font atlas, no backend): at
// 1280x800 and larger, with long texts in the status bar, on every tab, nothing is laid out past
// its window's right edge (ImGui would clip it: text cut off) and no window or tooltip lies
// outside the display; the Camera tab also with and without a camera and a fit's result, from
// 1280x720. The layout is ImGui's own, so this is what the window shows.
#include <gtest/gtest.h>

#include <imgui.h>
#include <imgui_internal.h>

#include <string>
#include <vector>

#include "fixtures.hpp"
#include "gui/model/camera_tuning.hpp"
#include "gui/model/leave_one_out.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/ui_state.hpp"
#include "gui/panels/studio_window.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;

namespace {

class HeadlessImGui {
 public:
  explicit HeadlessImGui(ImVec2 display) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = display;
    io.DeltaTime = 1.f / 60;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas: what a backend does first
  }
  ~HeadlessImGui() { ImGui::DestroyContext(); }
  HeadlessImGui(const HeadlessImGui&) = delete;
  HeadlessImGui& operator=(const HeadlessImGui&) = delete;

  void frame(fs::StudioController& controller, fs::UiState& ui, ImVec2 mouse = {-FLT_MAX, -FLT_MAX}) {
    ImGui::GetIO().MousePos = mouse;
    ImGui::NewFrame();
    fieldlines::gui::draw_studio(controller, ui, {});
    ImGui::Render();
  }
};

// Every window drawn last frame whose contents (as laid out) run past its right edge, and every
// window outside the display, by name.
std::vector<std::string> overflows(ImVec2 display) {
  std::vector<std::string> out;
  for (ImGuiWindow* w : GImGui->Windows) {
    if (!w->WasActive || w->Hidden) continue;
    const std::string name = w->Name;
    if (w->Pos.x < -0.5f || w->Pos.y < -0.5f || w->Pos.x + w->Size.x > display.x + 0.5f ||
        w->Pos.y + w->Size.y > display.y + 0.5f)
      out.push_back(name + " outside the display");
    if (w->ScrollbarX) continue;  // a window that scrolls sideways shows the rest on demand
    const float right = w->InnerRect.Max.x - w->WindowPadding.x + 0.5f;
    const float ideal = w->Pos.x + w->WindowPadding.x + w->ContentSizeIdeal.x - w->Scroll.x;
    if (ideal > right + 1) out.push_back(name + " laid out to x " + std::to_string(ideal) + " past " + std::to_string(right));
  }
  return out;
}

struct LayoutProject {
  LayoutProject() : dir("layout") {
    fs::ControllerOptions options;
    options.load_pixels = false;
    // 36 segments: fewer than calibration needs (50), so it refuses and says why.
    const auto file = studio_test::write_project(dir.path(), 3, 12);
    controller.emplace(fieldlines::Project::load(file), file, options);
  }
  studio_test::TempDir dir;
  std::optional<fs::StudioController> controller;
};

TEST(StudioPanelsLayout, NothingRunsPastTheWindowsEdgeOnAnyTabWithALongStatusLine) {
  for (const ImVec2 display : {ImVec2{1280, 800}, ImVec2{1600, 1000}, ImVec2{1920, 1080}}) {
    LayoutProject p;
    fs::StudioController& c = *p.controller;
    HeadlessImGui imgui(display);
    fs::UiState ui;
    ui.status_message = "proposed 1234 labels (marking label-free, boundary disabled); ";
    ui.status_message.append(300, 'x');
    ui.status_message += " and a message far longer than any status bar at this size";
    // Labels in every image (a test split of one image: "not enough to judge" lines) and
    // proposals on too few segments for calibration (its long guidance in two places).
    for (std::size_t img = 0; img < c.image_count(); ++img) {
      c.select_image(img);
      const std::size_t some[] = {0, 1, 2};
      ASSERT_TRUE(c.label(some, Label::Marking));
    }
    c.propose();
    ASSERT_FALSE(c.guidance().empty());
    ASSERT_FALSE(fs::not_enough_to_judge(c.test_image_count()).empty());
    for (int panel = 0; panel < static_cast<int>(fs::Panel::Count); ++panel) {
      ui.show(static_cast<fs::Panel>(panel));
      for (int f = 0; f < 5; ++f) imgui.frame(c, ui);  // a tab shows a frame after it is asked for; a table settles in one
      const std::vector<std::string> bad = overflows(display);
      EXPECT_TRUE(bad.empty()) << display.x << "x" << display.y << " tab " << fs::panel_name(static_cast<fs::Panel>(panel))
                               << ": " << ::testing::PrintToString(bad);
    }
  }
}

TEST(StudioPanelsLayout, TheStatusLinesFullTextShowsOnHoverInsideTheDisplay) {
  const ImVec2 display{1280, 800};
  LayoutProject p;
  HeadlessImGui imgui(display);
  fs::UiState ui;
  ui.status_message.assign(400, 'y');
  ui.status_message += " the end";
  // The status bar is the last line; hover its right end, where the notes are cut.
  for (int f = 0; f < 4; ++f) imgui.frame(*p.controller, ui, {display.x - 60, display.y - 20});
  bool tooltip = false;
  for (ImGuiWindow* w : GImGui->Windows) tooltip |= w->WasActive && (w->Flags & ImGuiWindowFlags_Tooltip);
  EXPECT_TRUE(tooltip);
  const std::vector<std::string> bad = overflows(display);
  EXPECT_TRUE(bad.empty()) << ::testing::PrintToString(bad);
}

TEST(StudioPanelsLayout, TooltipsNearTheRightEdgeStayInsideTheDisplay) {
  const ImVec2 display{1280, 800};
  LayoutProject p;
  HeadlessImGui imgui(display);
  fs::UiState ui;
  int tooltips = 0;
  for (int panel = 0; panel < static_cast<int>(fs::Panel::Count); ++panel) {
    ui.show(static_cast<fs::Panel>(panel));
    for (int f = 0; f < 3; ++f) imgui.frame(*p.controller, ui);
    // Down the side panel's right part, where its help markers, sliders and checkboxes end.
    for (float x : {display.x - 30, display.x - 150}) {
      for (float y = 40; y < display.y - 30; y += 18) {
        for (int f = 0; f < 2; ++f) imgui.frame(*p.controller, ui, {x, y});
        for (ImGuiWindow* w : GImGui->Windows) tooltips += w->WasActive && (w->Flags & ImGuiWindowFlags_Tooltip);
        const std::vector<std::string> bad = overflows(display);
        EXPECT_TRUE(bad.empty()) << fs::panel_name(static_cast<fs::Panel>(panel)) << " at " << x << "," << y << ": "
                                 << ::testing::PrintToString(bad);
      }
    }
  }
  EXPECT_GT(tooltips, 0);  // some were shown, so the check saw them
}

// The Camera tab in the states a person meets: no camera, one, a fit's error, one for another
// image size; from 1280x720 up.
struct CameraProject {
  CameraProject() : dir("camera_layout") {
    const auto file = studio_test::write_project(dir.path(), 3, 12, 640, 480);
    controller.emplace(fieldlines::Project::load(file), file, fs::ControllerOptions{});
  }
  studio_test::TempDir dir;
  std::optional<fs::StudioController> controller;
};

void expect_fits(HeadlessImGui& imgui, fs::StudioController& c, fs::UiState& ui, ImVec2 display, const char* state) {
  for (int f = 0; f < 4; ++f) imgui.frame(c, ui);
  ASSERT_EQ(ui.shown_panel, fs::Panel::Camera) << state;
  const std::vector<std::string> bad = overflows(display);
  EXPECT_TRUE(bad.empty()) << display.x << "x" << display.y << " " << state << ": " << ::testing::PrintToString(bad);
}

TEST(StudioCameraPanelLayout, FitsFrom1280x720WithAndWithoutACameraAndAFitsResult) {
  for (const ImVec2 display : {ImVec2{1280, 720}, ImVec2{1280, 800}, ImVec2{1920, 1080}}) {
    CameraProject p;
    fs::StudioController& c = *p.controller;
    HeadlessImGui imgui(display);
    fs::UiState ui;
    ui.show(fs::Panel::Camera);
    expect_fits(imgui, c, ui, display, "no camera");
    c.set_camera(fs::typical_camera(640, 480));
    expect_fits(imgui, c, ui, display, "typical camera");
    // Grid pictures have no painted lines: the fit fails with fit_camera's long message.
    ASSERT_TRUE(fs::start_camera_fit(c));
    c.camera_fit().wait();
    ASSERT_TRUE(c.camera_fit().outcome() && !c.camera_fit().outcome()->ok());
    expect_fits(imgui, c, ui, display, "failed fit");
    // A camera for another image size: the note under the intrinsics.
    c.set_camera(fs::typical_camera(1920, 1080));
    expect_fits(imgui, c, ui, display, "camera for another size");
  }
}

TEST(StudioCameraPanelLayout, TooltipsNearTheRightEdgeStayInsideTheDisplay) {
  const ImVec2 display{1280, 720};
  CameraProject p;
  fs::StudioController& c = *p.controller;
  c.set_camera(fs::typical_camera(640, 480));
  HeadlessImGui imgui(display);
  fs::UiState ui;
  ui.show(fs::Panel::Camera);
  int tooltips = 0;
  for (float x : {display.x - 30, display.x - 150}) {
    for (float y = 40; y < display.y - 30; y += 18) {
      for (int f = 0; f < 2; ++f) imgui.frame(c, ui, {x, y});
      for (ImGuiWindow* w : GImGui->Windows) tooltips += w->WasActive && (w->Flags & ImGuiWindowFlags_Tooltip);
      const std::vector<std::string> bad = overflows(display);
      EXPECT_TRUE(bad.empty()) << x << "," << y << ": " << ::testing::PrintToString(bad);
    }
  }
  EXPECT_GT(tooltips, 0);  // the help markers were reached
}

}  // namespace
