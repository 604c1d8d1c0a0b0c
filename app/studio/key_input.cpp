#include "app/studio/key_input.hpp"

#include <algorithm>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ImGuiContext: which widget is active, and whether it is a text field

#include "gui/model/shortcut_actions.hpp"

namespace fieldlines::app {

namespace {
bool is_modifier(int key) { return key >= GLFW_KEY_LEFT_SHIFT && key <= GLFW_KEY_RIGHT_SUPER; }
}  // namespace

// The table's key codes are GLFW's, so key presses pass through unchanged.
static_assert(static_cast<int>(studio::Key::M) == GLFW_KEY_M && static_cast<int>(studio::Key::Z) == GLFW_KEY_Z);
static_assert(static_cast<int>(studio::Key::B) == GLFW_KEY_B && static_cast<int>(studio::Key::Y) == GLFW_KEY_Y);
static_assert(static_cast<int>(studio::Key::Left) == GLFW_KEY_LEFT && static_cast<int>(studio::Key::Right) == GLFW_KEY_RIGHT);
static_assert(static_cast<int>(studio::Key::F1) == GLFW_KEY_F1 && static_cast<int>(studio::Key::F7) == GLFW_KEY_F7);
static_assert(static_cast<int>(studio::Key::Enter) == GLFW_KEY_ENTER && static_cast<int>(studio::Key::Tab) == GLFW_KEY_TAB);
static_assert(static_cast<int>(studio::Key::P) == GLFW_KEY_P && static_cast<int>(studio::Key::Space) == GLFW_KEY_SPACE);
static_assert(static_cast<int>(studio::Key::G) == GLFW_KEY_G && static_cast<int>(studio::Key::I) == GLFW_KEY_I);
static_assert(static_cast<int>(studio::Key::O) == GLFW_KEY_O && static_cast<int>(studio::Key::S) == GLFW_KEY_S);
static_assert(static_cast<int>(studio::Key::Up) == GLFW_KEY_UP && static_cast<int>(studio::Key::Down) == GLFW_KEY_DOWN);
static_assert(static_cast<int>(studio::Key::PageUp) == GLFW_KEY_PAGE_UP &&
              static_cast<int>(studio::Key::PageDown) == GLFW_KEY_PAGE_DOWN);

void run_shortcuts(std::span<const KeyPress> keys, studio::StudioController& controller, studio::UiState& ui) {
  if (ImGui::GetIO().WantTextInput) return;
  for (const KeyPress& k : keys) {
    const studio::Chord pressed{static_cast<studio::Key>(k.key), (k.mods & GLFW_MOD_CONTROL) != 0,
                                (k.mods & GLFW_MOD_SHIFT) != 0};
    if (const studio::Shortcut* shortcut = studio::find_shortcut(pressed, k.repeat)) {
      studio::run_shortcut(*shortcut, controller, ui);
    }
  }
}

void route_tab_key() {
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  // The active widget at the end of the last frame (exact, unlike io.WantTextInput, which lags a
  // frame). A slider being typed into (Ctrl+click) is a text field with the slider's id.
  const bool typing = g.ActiveId != 0 && g.InputTextState.ID == g.ActiveId;
  ImGui::GetIO().KeyMap[ImGuiKey_Tab] = typing ? GLFW_KEY_TAB : -1;  // -1: unmapped, never pressed
}

MissedKeyReplay::MissedKeyReplay(std::span<const KeyPress> keys) {
  ImGuiIO& io = ImGui::GetIO();
  ctrl_ = io.KeyCtrl, shift_ = io.KeyShift, alt_ = io.KeyAlt, super_ = io.KeySuper, mods_ = io.KeyMods;
  const int last = static_cast<int>(IM_ARRAYSIZE(io.KeysDown));
  for (const KeyPress& k : keys) {
    // Duration > 0: held since an earlier frame, ImGui has this press. A modifier's own press
    // carries the modifiers from before it; the key pressed with it tells them.
    if (k.repeat || k.key < 0 || k.key >= last || is_modifier(k.key) || io.KeysDownDuration[k.key] > 0) continue;
    if (io.KeysDownDuration[k.key] < 0 && std::find(replayed_.begin(), replayed_.end(), k.key) == replayed_.end()) {
      // Pressed and released before this frame: ImGui never saw it down.
      replayed_.push_back(k.key);
      io.KeysDown[k.key] = true;
      io.KeysDownDuration[k.key] = 0;  // "pressed this frame" to IsKeyPressed
    }
    // Seen down or replayed, the modifiers may be up already (Ctrl released right after A):
    // the ones it was pressed with count, as they do for the studio's own shortcuts.
    io.KeyCtrl = (k.mods & GLFW_MOD_CONTROL) != 0;
    io.KeyShift = (k.mods & GLFW_MOD_SHIFT) != 0;
    io.KeyAlt = (k.mods & GLFW_MOD_ALT) != 0;
    io.KeySuper = (k.mods & GLFW_MOD_SUPER) != 0;
    io.KeyMods = (io.KeyCtrl ? ImGuiKeyModFlags_Ctrl : 0) | (io.KeyShift ? ImGuiKeyModFlags_Shift : 0) |
                 (io.KeyAlt ? ImGuiKeyModFlags_Alt : 0) | (io.KeySuper ? ImGuiKeyModFlags_Super : 0);
  }
}

MissedKeyReplay::~MissedKeyReplay() {
  ImGuiIO& io = ImGui::GetIO();
  // No events are processed during a frame, so the replayed keys are still up as GLFW knows it.
  for (const int key : replayed_) {
    io.KeysDown[key] = false;
    io.KeysDownDuration[key] = -1;
  }
  io.KeyCtrl = ctrl_, io.KeyShift = shift_, io.KeyAlt = alt_, io.KeySuper = super_, io.KeyMods = mods_;
}

}  // namespace fieldlines::app
