// Camera tab: the robot's camera nudged by hand (pitch, roll, height), the ground grid it puts
// over the frame, the top view of the frame's features on the turf, the fit from the field's
// lines (background), and the camera file saved and loaded. The geometry, the fit and the form
// are gui/model's (camera_tuning.hpp, camera_fit_job.hpp, camera_form.hpp); this draws them.
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "fieldlines/detect/ground_features.hpp"
#include "gui/model/camera_fit_job.hpp"
#include "gui/model/camera_form.hpp"
#include "gui/model/camera_tuning.hpp"
#include "gui/panels/image_view.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {

const ImVec4 kErrorColour{1, 0.4f, 0.4f, 1};
const ImVec4 kWarningColour{1, 0.7f, 0.3f, 1};

ImVec2 im(studio::Vec2 v) { return {v.x, v.y}; }
ImU32 colour(studio::Rgba c) { return IM_COL32(c.r, c.g, c.b, c.a); }

// -/+ buttons of one step (Ctrl: the fast step); true when the value changed.
bool nudge(const char* label, double& value, double step, double fast, const char* format) {
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  return ImGui::InputDouble(label, &value, step, fast, format);
}

void draw_pose(studio::StudioController& controller, const GroundCamera& camera) {
  studio::CameraPose pose = studio::pose_of(camera);
  bool changed = nudge("pitch (deg)", pose.pitch_deg, studio::kAngleStepDeg, studio::kAngleFastStepDeg, "%.2f");
  changed |= nudge("roll (deg)", pose.roll_deg, studio::kAngleStepDeg, studio::kAngleFastStepDeg, "%.2f");
  changed |= nudge("height (cm)", pose.height_cm, studio::kHeightStepCm, studio::kHeightFastStepCm, "%.1f");
  ImGui::SameLine();
  help_marker("-/+ nudge by one step (0.05 degree, 0.5 cm), with Ctrl by 1 degree or 5 cm;\n"
              "or type a value. Keys, held to repeat: Up / Down pitch, Ctrl+Left / Ctrl+Right roll,\n"
              "Page Up / Page Down height. The grid over the frame and the top view follow at once.\n"
              "Pitch: the optical axis below the horizontal; roll: clockwise on screen.");
  if (changed) controller.set_camera(studio::with_pose(camera, pose));  // clamped: always valid
  char intrinsics[128];
  std::snprintf(intrinsics, sizeof intrinsics, "fx %.1f  fy %.1f  cx %.1f  cy %.1f (px)", camera.fx, camera.fy,
                camera.cx, camera.cy);
  wrapped_hint(intrinsics);
  const std::string note = studio::intrinsics_note(camera, controller.image().cols, controller.image().rows);
  if (!note.empty()) wrapped_text(kWarningColour, note);
}

void draw_top_view(const studio::StudioController& controller, const GroundCamera& camera, studio::CameraForm& form,
                   studio::CameraViewBuffers& buffers) {
  ImGui::TextUnformatted("Top view (metres, the camera's foot at the bottom)");
  ImGui::SameLine();
  help_marker("The current frame's features on the turf through this camera: stripes' centre lines,\n"
              "junctions, the centre circle, the field boundary; the blue lines are the image's edges.\n"
              "With the right pitch and roll the field's lines come out parallel or square and the\n"
              "circle round. Features come from this image's last detection in the studio.");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  ImGui::SliderFloat("range (m)", &form.top_view_range_m, 2, 20, "%.0f");
  const ImVec2 size{ImGui::GetContentRegionAvail().x, 200};
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  const studio::TopView view({{at.x, at.y}, {at.x + size.x, at.y + size.y}}, form.top_view_range_m);
  studio::TopViewDrawing& drawing = buffers.top_view;
  project_features(controller.field_features(), camera, {}, buffers.ground);
  studio::build_top_view(buffers.ground, camera, controller.image().cols, controller.image().rows, view, drawing);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(at, {at.x + size.x, at.y + size.y}, true);
  draw->AddRectFilled(at, {at.x + size.x, at.y + size.y}, IM_COL32(20, 45, 25, 255));
  for (const studio::TopViewLine& l : drawing.lines) draw->AddLine(im(l.a), im(l.b), colour(l.colour), l.thickness);
  for (const studio::TopViewCircle& c : drawing.circles)
    draw->AddCircle(im(c.centre), c.radius, colour(c.colour), 0, c.thickness);
  for (const studio::TopViewLetter& t : drawing.letters) {
    const char text[2] = {t.letter, 0};
    draw->AddText({t.at.x, t.at.y - ImGui::GetFontSize()}, colour(t.colour), text);
  }
  draw->PopClipRect();
  if (controller.field_features().markings.empty() && controller.field_features().field_boundary.points.empty())
    wrapped_hint("no features for this image yet: detect it (button above or the Images tab)");
}

void draw_fit(studio::StudioController& controller, studio::CameraForm& form) {
  ImGui::TextUnformatted("Fit from the lines");
  ImGui::SameLine();
  help_marker("Detects every image of the project (the stripes stage on) and fits the pitch and roll\n"
              "that make their lines parallel or square on the turf, from the camera above (within\n"
              "8 degrees): as `fieldlines calibrate-camera`. The images must come from one standing\n"
              "camera (same pitch, roll and height), at least 3 with 2 lines or more.\n"
              "A painted line width (e.g. 5 cm for SPL and Humanoid) fits the height too.");
  studio::CameraFitJob& job = controller.camera_fit();
  ImGui::BeginDisabled(job.running() || !controller.camera() || controller.image_count() == 0);
  if (ImGui::Button("Fit from the lines")) studio::start_camera_fit(controller, form.fit_params());
  ImGui::EndDisabled();
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.3f);
  ImGui::InputFloat("painted line width (cm)", &form.line_width_cm, 0, 0, "%.1f");
  if (form.line_width_cm < 0) form.line_width_cm = 0;
  ImGui::SameLine();
  help_marker("The painted lines' width (SPL and Humanoid 5 cm, MSL 12.5 cm, SSL 1 cm): the fit\n"
              "takes the height from the stripes' widths on the turf. 0: the height is kept.");
  if (job.running()) {
    const studio::CameraFitProgress& p = job.progress();
    ImGui::ProgressBar(p.total ? static_cast<float>(p.done) / static_cast<float>(p.total) : 0.f, {-1, 0},
                       job.status().c_str());
    if (ImGui::Button("Cancel fit")) job.cancel();
    return;
  }
  const auto& outcome = job.outcome();
  if (!outcome) return;
  if (!outcome->ok()) {
    wrapped_text(kErrorColour, job.status());
    if (ImGui::Button("Dismiss")) job.discard();
    return;
  }
  for (const std::string& line : studio::fit_summary(outcome->value())) wrapped_text(ImGui::GetStyleColorVec4(ImGuiCol_Text), line);
  if (ImGui::Button("Apply")) form.apply_fit(controller);
  ImGui::SameLine();
  if (ImGui::Button("Discard")) job.discard();
}

void draw_file(studio::StudioController& controller, studio::CameraForm& form) {
  ImGui::TextUnformatted("Camera file");
  ImGui::SameLine();
  help_marker("The camera file `fieldlines detect --camera` and the studio's --camera read\n"
              "(intrinsics, pitch, roll, height). ~ is your home folder; a relative path starts in\n"
              "the project's folder. Save writes it atomically; Load makes it the studio's camera.");
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##camera_path", &form.path());
  if (ImGui::IsItemEdited()) form.resolve();
  if (!form.target().ok()) wrapped_text(kErrorColour, form.target().error);
  else wrapped_hint("-> " + form.target().path.string());
  ImGui::BeginDisabled(!form.target().ok());
  ImGui::BeginDisabled(!controller.camera());
  if (ImGui::Button("Save camera")) form.save(controller);
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Load camera")) form.load(controller);
  ImGui::EndDisabled();
  if (!form.message().empty())
    wrapped_text(form.failed() ? kErrorColour : ImGui::GetStyleColorVec4(ImGuiCol_Text), form.message());
}

}  // namespace

void draw_camera_panel(studio::StudioController& controller, UiState& ui) {
  studio::CameraForm& form = ui.camera_form;
  form.update(controller);
  const std::optional<GroundCamera>& camera = controller.camera();
  if (!camera) {
    wrapped_hint("No camera: give one with --camera FILE, load a camera file below, or start from a typical "
                 "camera for this image's size (fx = the width, the principal point at the centre, pitch 30 "
                 "degrees, roll 0, 0.6 m up) and nudge it or fit it from the lines.");
    ImGui::BeginDisabled(controller.image().empty());
    if (ImGui::Button("Start from a typical camera")) form.start_typical(controller);
    ImGui::EndDisabled();
  } else {
    draw_pose(controller, *camera);
    ImGui::Checkbox("ground grid over the frame", &form.show_grid);
    ImGui::SameLine();
    help_marker("Lines every 0.5 m on the turf (whole metres brighter, straight ahead too) out to 8 m,\n"
                "and the horizon (dashed): where this camera takes the turf to be.");
    ImGui::BeginDisabled(controller.detection().running());
    if (ImGui::Button("Re-detect the images with this camera")) controller.detect_all(false);
    ImGui::EndDisabled();
    ImGui::SameLine();
    help_marker("Detection fits the centre circle on the turf with the camera it was started with;\n"
                "after a nudge or a fit, re-detect so the features use the new one.");
    ImGui::Separator();
    draw_top_view(controller, *camera, form, ui.camera_view);
  }
  ImGui::Separator();
  draw_fit(controller, form);
  ImGui::Separator();
  draw_file(controller, form);
}

void draw_camera_overlay(const studio::StudioController& controller, UiState& ui, ImVec2 canvas_min,
                         ImVec2 canvas_max) {
  const studio::CameraForm& form = ui.camera_form;
  // While the tab is open (the tab bar, drawn before, says which one is).
  if (ui.shown_panel != studio::Panel::Camera || !form.show_grid || !controller.camera()) return;
  const studio::ViewTransform& view = ui.image_view.view;
  studio::GroundGrid& grid = ui.camera_view.grid;
  studio::build_ground_grid(*controller.camera(), controller.image().cols, controller.image().rows, form.grid, grid);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(canvas_min, canvas_max, true);
  for (const studio::GridLine& l : grid.lines) {
    const studio::ScreenSegment s = studio::to_screen(l, view);
    draw->AddLine(im(s.a), im(s.b), l.major ? IM_COL32(255, 255, 255, 170) : IM_COL32(255, 255, 255, 80),
                  l.major ? 1.5f : 1.0f);
  }
  if (grid.horizon) {
    const studio::ScreenSegment s = studio::to_screen(*grid.horizon, view);
    draw_styled_line(draw, im(s.a), im(s.b), {{120, 170, 255, 255}, studio::Stroke::Dashed, 1.5f});
  }
  draw->PopClipRect();
}

}  // namespace fieldlines::gui
