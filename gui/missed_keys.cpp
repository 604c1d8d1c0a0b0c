#include "gui/missed_keys.hpp"

#include <algorithm>

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace fieldlines::gui {

MissedKeyReplay::MissedKeyReplay(std::span<const KeyPress> keys) {
  ImGuiIO& io = ImGui::GetIO();
  ctrl_ = io.KeyCtrl, shift_ = io.KeyShift, alt_ = io.KeyAlt, super_ = io.KeySuper, mods_ = io.KeyMods;
  const int last = static_cast<int>(IM_ARRAYSIZE(io.KeysDown));
  for (const KeyPress& k : keys) {
    // Down at NewFrame (duration >= 0): ImGui saw this press itself.
    if (k.repeat || k.key < 0 || k.key >= last || io.KeysDownDuration[k.key] >= 0) continue;
    if (std::find(replayed_.begin(), replayed_.end(), k.key) != replayed_.end()) continue;
    replayed_.push_back(k.key);
    io.KeysDown[k.key] = true;
    io.KeysDownDuration[k.key] = 0;  // "pressed this frame" to IsKeyPressed
    // The modifiers may have been released within the same frame too (Ctrl up right after A).
    io.KeyCtrl = (k.mods & GLFW_MOD_CONTROL) != 0;
    io.KeyShift = (k.mods & GLFW_MOD_SHIFT) != 0;
    io.KeyAlt = (k.mods & GLFW_MOD_ALT) != 0;
    io.KeySuper = (k.mods & GLFW_MOD_SUPER) != 0;
    io.KeyMods = (io.KeyCtrl ? ImGuiKeyModFlags_Ctrl : 0) | (io.KeyShift ? ImGuiKeyModFlags_Shift : 0) |
                 (io.KeyAlt ? ImGuiKeyModFlags_Alt : 0) | (io.KeySuper ? ImGuiKeyModFlags_Super : 0);
  }
}

MissedKeyReplay::~MissedKeyReplay() {
  if (replayed_.empty()) return;
  ImGuiIO& io = ImGui::GetIO();
  // No events are processed during a frame, so these keys are still up as far as GLFW knows.
  for (const int key : replayed_) {
    io.KeysDown[key] = false;
    io.KeysDownDuration[key] = -1;
  }
  io.KeyCtrl = ctrl_, io.KeyShift = shift_, io.KeyAlt = alt_, io.KeySuper = super_, io.KeyMods = mods_;
}

}  // namespace fieldlines::gui
