#pragma once
// The studio's whole window: the image canvas on the left, tabbed panels on the right, a status
// bar, and the keyboard shortcuts. Draws controller state and forwards user actions to it.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fieldlines/train/protocols.hpp"
#include "fieldlines/train/training.hpp"
#include "gui/model/folder_listing.hpp"
#include "gui/model/frame_stats.hpp"
#include "gui/image_view.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/video_frames.hpp"

namespace fieldlines::gui {

// A key press as GLFW reported it. Shortcuts are taken from these events rather than from ImGui's
// key-down state, because a press and release arriving between two frames would otherwise be lost.
struct KeyPress {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;  // GLFW_MOD_* bits
  bool repeat = false;
};

enum class Panel { Images, Label, Thresholds, Train, Metrics, Export, Count };
const char* panel_name(Panel panel);

struct UiState {
  ImageViewState image_view;
  Panel requested_panel = Panel::Label;  // selected on the next frame (F1..F6 or startup)
  bool panel_request_pending = true;
  Panel shown_panel = Panel::Label;
  int image_filter = 0;  // 0 all, 1 not fully labelled, 2 with errors, 3 test split
  int image_order = 0;   // Images tab: 0 file order, 1 least certain first (review order)
  TrainParams train_params = protocol_spec(Protocol::Ours).train;  // as `fieldlines train` by default
  int scatter_x = 0, scatter_y = 1;  // threshold dimensions of the particle scatter
  // Train tab: what Apply did ("applied: marking P .. R .. on the test split"), shown while the
  // applied thresholds are still the current ones.
  std::string applied_message;
  std::optional<Thresholds> applied_thresholds;
  std::string export_path;          // as typed; set to the project's default when it opens
  std::string export_path_project;  // the project file that default was made for
  std::string export_message;
  bool export_failed = false;       // export_message is an error
  std::string export_preview;
  studio::FolderListing export_folders;  // the folder browser's listing, reread once a second
  std::vector<std::string> recent_projects;
  std::string open_request;    // a project the user asked to open (the main loop swaps sessions)
  std::string status_message;  // shown in the status bar
  const studio::FrameStats* frame_stats = nullptr;
  bool quit_requested = false;
};

// Draws one frame of the UI (between ImGui::NewFrame and ImGui::Render).
void draw_studio(studio::StudioController& controller, UiState& ui, std::span<const KeyPress> keys = {});

// Draws the frame shown while a video's frames are extracted, before any project is open: the
// progress and a Cancel button (which asks to quit, as closing the window does).
void draw_video_import(const studio::VideoImport& import, UiState& ui);

// Runs the shortcuts of gui/model/shortcuts.hpp's table for these key presses (none while a text
// field has focus).
void handle_shortcuts(studio::StudioController& controller, UiState& ui, std::span<const KeyPress> keys);
// The in-app help: every row of the same table.
void draw_shortcut_help();

}  // namespace fieldlines::gui
