#pragma once
// The studio's whole window: the image canvas on the left, tabbed panels on the right, a status
// bar. Draws controller and UI state and forwards user actions to them.
#include "gui/model/studio_controller.hpp"
#include "gui/model/ui_state.hpp"
#include "gui/model/video_frames.hpp"
#include "gui/panels/image_view.hpp"

namespace fieldlines::gui {

// Draws one frame of the UI (between ImGui::NewFrame and ImGui::Render); `texture` holds
// ui.image_view's picture (CanvasState::picture_to_upload).
void draw_studio(studio::StudioController& controller, studio::UiState& ui, const CanvasTexture& texture);

// The colour to clear the frame to under draw_studio, given what was cleared to before. The
// studio window paints no background of its own: a full-window layer a software renderer fills
// every frame (about 10 ms of one core's time under llvmpipe at 1280x800). The clear shows the
// style's translucent window background as it looked over `behind` instead.
ImVec4 studio_backdrop(ImVec4 behind);

// Draws the frame shown while a video's frames are extracted, before any project is open: the
// progress and a Cancel button (which asks to quit, as closing the window does).
void draw_video_import(const studio::VideoImport& import, studio::UiState& ui);

}  // namespace fieldlines::gui
