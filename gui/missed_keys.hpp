#pragma once
// ImGui 1.86's GLFW backend tells widgets about keys only through io.KeysDown, the state at the
// start of a frame, so a key pressed and released between two frames never reaches a text field:
// a quick Ctrl+A while the studio idles in glfwWaitEvents (the first frame after the wake-up is
// the slow one), or any tap during a slow frame. Measured under Xvfb: 3 of 5 Ctrl+A taps from
// idle were lost in the export path field. Typed characters come through ImGui's character queue
// and were never lost; the studio's shortcuts come from its own KeyPress events. This puts the
// presses ImGui missed into its key state for the one frame they arrived in.
#include <span>
#include <vector>

#include "gui/studio_ui.hpp"

namespace fieldlines::gui {

class MissedKeyReplay {
 public:
  // After ImGui::NewFrame, before any widget: every non-repeat press in `keys` that ImGui does
  // not see down reads as pressed this frame, with the modifiers it was pressed with.
  explicit MissedKeyReplay(std::span<const KeyPress> keys);
  // Before ImGui::Render: ImGui's key state as the backend left it (those keys are up).
  ~MissedKeyReplay();
  MissedKeyReplay(const MissedKeyReplay&) = delete;
  MissedKeyReplay& operator=(const MissedKeyReplay&) = delete;

 private:
  std::vector<int> replayed_;
  bool ctrl_ = false, shift_ = false, alt_ = false, super_ = false;
  int mods_ = 0;
};

}  // namespace fieldlines::gui
