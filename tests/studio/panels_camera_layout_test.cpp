// The Camera tab drawn by ImGui without a window, as panels_layout_test.cpp draws the other tabs
// (its headless context and overflow check, here for the tab that is not a Panel): at 1280x720
// and larger, with no camera, with one, with a fit's result and with its error, nothing is laid
// out past the side panel's right edge and no window or tooltip leaves the display.
#include <gtest/gtest.h>

#include <imgui.h>
#include <imgui_internal.h>

#include <string>
#include <vector>

#include "fixtures.hpp"
#include "gui/model/camera_tuning.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/ui_state.hpp"
#include "gui/panels/studio_window.hpp"

namespace fs = fieldlines::studio;

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
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
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

// Whether the side panel's Camera tab is the one shown.
bool camera_tab_shown(const fs::UiState& ui) { return ui.shown_panel == fs::Panel::Camera; }

std::vector<std::string> overflows(ImVec2 display) {
  std::vector<std::string> out;
  for (ImGuiWindow* w : GImGui->Windows) {
    if (!w->WasActive || w->Hidden) continue;
    const std::string name = w->Name;
    if (w->Pos.x < -0.5f || w->Pos.y < -0.5f || w->Pos.x + w->Size.x > display.x + 0.5f ||
        w->Pos.y + w->Size.y > display.y + 0.5f)
      out.push_back(name + " outside the display");
    if (w->ScrollbarX) continue;
    const float right = w->InnerRect.Max.x - w->WindowPadding.x + 0.5f;
    const float ideal = w->Pos.x + w->WindowPadding.x + w->ContentSizeIdeal.x - w->Scroll.x;
    if (ideal > right + 1) out.push_back(name + " laid out to x " + std::to_string(ideal) + " past " + std::to_string(right));
  }
  return out;
}

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
  ASSERT_TRUE(camera_tab_shown(ui)) << state;
  const std::vector<std::string> bad = overflows(display);
  EXPECT_TRUE(bad.empty()) << display.x << "x" << display.y << " " << state << ": " << ::testing::PrintToString(bad);
}

}  // namespace

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
