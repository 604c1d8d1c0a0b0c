#pragma once
// The keyboard between GLFW, ImGui and the studio's shortcuts (the window's side of
// gui/model/shortcut_actions.hpp).
//
// ImGui 1.86's GLFW backend tells widgets about keys only through io.KeysDown and io.KeyCtrl etc.,
// the state at the start of a frame. A key pressed and released between two frames never reaches
// a text field, and a key still down whose Ctrl was already released reads as a plain key: a
// quick Ctrl+A tap while the studio idles in glfwWaitEvents (the frame after the wake-up is a
// slow one) did not select all in the export path, 3 times in 5 under Xvfb (logged: the A never
// seen down, or seen with Ctrl already up). Typed characters come through ImGui's character queue and were never lost; the
// studio's shortcuts come from its own KeyPress events, which have every press with the
// modifiers it was pressed with. This gives ImGui those presses for the frame they arrived in.
// Not fixed: two chords within one frame (Ctrl+A and then Shift+~ 10 ms later, as a script types)
// still share one set of modifiers, the last press's; ImGui 1.87's input queue would split them.
#include <span>
#include <vector>

#include "gui/model/studio_controller.hpp"
#include "gui/model/ui_state.hpp"

namespace fieldlines::app {

// A key press as GLFW reported it. Shortcuts are taken from these events rather than from ImGui's
// key-down state, because a press and release arriving between two frames would otherwise be lost.
struct KeyPress {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;  // GLFW_MOD_* bits
  bool repeat = false;
};

// After ImGui::NewFrame: runs the shortcuts of gui/model/shortcuts.hpp's table for these key
// presses (none while a text field has focus).
void run_shortcuts(std::span<const KeyPress> keys, studio::StudioController& controller, studio::UiState& ui);

// Before ImGui::NewFrame. ImGui 1.86 moves its keyboard focus on Tab in whatever window was
// clicked last, with no widget active too: into the side panel's first field, and a slider
// reached that way turns into a text box, which switches every shortcut off until Escape. So
// ImGui sees Tab only while a text field is being typed in (Tab then moves to the next field);
// otherwise Tab is the studio's shortcut alone.
void route_tab_key();

class MissedKeyReplay {
 public:
  // After ImGui::NewFrame, before any widget: every non-repeat press in `keys` reads as pressed
  // this frame (also when ImGui missed it), with the modifiers it was pressed with.
  explicit MissedKeyReplay(std::span<const KeyPress> keys);
  // Before ImGui::Render: ImGui's key state as the backend left it.
  ~MissedKeyReplay();
  MissedKeyReplay(const MissedKeyReplay&) = delete;
  MissedKeyReplay& operator=(const MissedKeyReplay&) = delete;

 private:
  std::vector<int> replayed_;
  bool ctrl_ = false, shift_ = false, alt_ = false, super_ = false;
  int mods_ = 0;
};

}  // namespace fieldlines::app
