#pragma once
// What the studio's window shows besides the project: the canvas, which tab, the Images tab's
// filter, the Train, Export and Camera tabs' forms, the status line. Window-free, so tests reach it;
// gui/panels draws it, gui/model/shortcut_actions.hpp and the panels change it.
#include <string>
#include <vector>

#include "gui/model/camera_form.hpp"
#include "gui/model/camera_tuning.hpp"
#include "gui/model/canvas_state.hpp"
#include "gui/model/export_form.hpp"
#include "gui/model/frame_stats.hpp"
#include "gui/model/train_form.hpp"

namespace fieldlines::studio {

enum class Panel { Images, Label, Thresholds, Train, Metrics, Export, Camera, Count };
const char* panel_name(Panel panel);

struct UiState {
  CanvasState image_view;
  Panel requested_panel = Panel::Label;  // selected on the next frame (F1..F7 or startup)
  bool panel_request_pending = true;
  Panel shown_panel = Panel::Label;
  int image_filter = 0;  // 0 all, 1 not fully labelled, 2 with errors, 3 test split
  int image_order = 0;   // Images tab: 0 file order, 1 least certain first (review order)
  TrainForm training;
  ExportForm export_form;
  CameraForm camera_form;
  CameraViewBuffers camera_view;
  std::vector<std::string> recent_projects;
  std::string open_request;    // a project the user asked to open (the main loop swaps sessions)
  std::string status_message;  // shown in the status bar
  const FrameStats* frame_stats = nullptr;
  bool quit_requested = false;

  void show(Panel panel) {
    requested_panel = panel;
    panel_request_pending = true;
  }
};

}  // namespace fieldlines::studio
