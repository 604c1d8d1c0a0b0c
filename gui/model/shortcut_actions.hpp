#pragma once
// What each shortcut of gui/model/shortcuts.hpp's table does to the studio: window-free, so a
// test presses keys without a window. The window turns its key events into chords
// (app/studio/key_input.hpp) and calls this for each one it finds in the table.
#include "gui/model/shortcuts.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/ui_state.hpp"

namespace fieldlines::studio {

void run_shortcut(const Shortcut& shortcut, StudioController& controller, UiState& ui);

}  // namespace fieldlines::studio
