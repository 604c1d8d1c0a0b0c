#pragma once
// One function per tab of the studio's side bar; each draws state and calls the controller.
#include <string>

#include <imgui.h>

#include "gui/model/overlay_style.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/ui_state.hpp"

namespace fieldlines::gui {

using studio::Panel;
using studio::UiState;

void draw_images_panel(studio::StudioController& controller, UiState& ui);
void draw_label_panel(studio::StudioController& controller, UiState& ui);
void draw_thresholds_panel(studio::StudioController& controller, UiState& ui);
void draw_train_panel(studio::StudioController& controller, UiState& ui);
// Auto-train, proposals and the learning curve: the top of the Train tab.
void draw_auto_train(studio::StudioController& controller);
void draw_metrics_panel(studio::StudioController& controller, UiState& ui);
void draw_export_panel(studio::StudioController& controller, UiState& ui);
// The Camera tab (camera_panel.cpp), and the ground grid it puts over the canvas (between
// `canvas_min` and `canvas_max`, screen px) while the tab is open.
void draw_camera_panel(studio::StudioController& controller, UiState& ui);
void draw_camera_overlay(const studio::StudioController& controller, UiState& ui, ImVec2 canvas_min,
                         ImVec2 canvas_max);

// A "(?)" whose tooltip, `text`, opens above it: help that never covers what follows it.
void help_marker(const char* text);

// Text in `colour` that wraps at the panel's edge (long paths, summaries) instead of running off.
void wrapped_text(const ImVec4& colour, const std::string& text);
// The same in the style's dimmed text colour, for hints.
void wrapped_hint(const std::string& text);

// The class's on/off checkbox (Thresholds and Export tabs), with calibration's reason under it
// when calibration turned it off. Returns whether the class is on.
bool class_switch(studio::StudioController& controller, Label cls);

// The colour legend of the current overlay mode (also drawn on the Label panel).
void draw_legend(studio::OverlayMode mode);

// The in-app help: every row of gui/model/shortcuts.hpp's table.
void draw_shortcut_help();

}  // namespace fieldlines::gui
