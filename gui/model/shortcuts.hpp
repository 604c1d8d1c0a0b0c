#pragma once
// The studio's one table of inputs: every keyboard shortcut (key, action, description) and the
// mouse inputs of the image view. The key handling looks keys up here, the in-app help draws
// this table, and a test checks that the README's and docs/studio.md's tables list exactly
// these rows, so none of them can drift.
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "gui/model/camera_nudge.hpp"
#include "gui/model/feature_layers.hpp"

namespace fieldlines::studio {

// Key codes are GLFW's (glfw3.h: printable keys are their upper-case ASCII), so the window
// passes its codes through unchanged; app/studio/key_input.cpp checks them against glfw3.h.
enum class Key : int {
  None = 0,  // a mouse input: handled by the image view, listed for the help
  B = 'B', C = 'C', E = 'E', F = 'F', G = 'G', I = 'I', M = 'M', N = 'N', O = 'O', P = 'P', Q = 'Q', S = 'S', T = 'T',
  Y = 'Y', Z = 'Z',
  Space = ' ',
  Enter = 257, Tab = 258, Right = 262, Left = 263, Down = 264, Up = 265, PageUp = 266, PageDown = 267,
  F1 = 290, F2, F3, F4, F5, F6, F7,
};

struct Chord {
  Key key = Key::None;
  bool ctrl = false, shift = false;
  bool operator==(const Chord&) const = default;
};

enum class Action {
  LabelMarking, LabelBoundary, LabelNone, LabelClear,  // the hovered segment
  NextUnderCursor,  // hover the next of the overlapping segments under the cursor
  Fit, PreviousImage, NextImage, NextImageWithErrors,
  Propose, AcceptProposals, FocusUncertain,  // the review loop
  ToggleFeatureLayer,  // one of the field feature layers (feature_layers.hpp) on or off
  NudgeCamera,  // the Camera tab's camera one step (camera_nudge.hpp)
  Undo, Redo, ToggleTraining, ShowTab, Quit,
  Pointer,  // a mouse input (no key)
};

struct Shortcut {
  Chord chord;
  Action action;
  std::string_view description;
  std::string_view pointer = {};  // the mouse input's name, for Action::Pointer
  int tab = -1;                   // for ShowTab: 0 Images .. 5 Export
  bool repeats = false;           // acts on auto-repeat while held (navigation and nudges)
  FeatureLayer layer = FeatureLayer::Count;  // for ToggleFeatureLayer
  CameraNudge nudge = {};                    // for NudgeCamera
};

// Every input, in the order the help and the docs list them.
std::span<const Shortcut> shortcuts();

// The shortcut a key press triggers, if any. Shift only matters where a chord names it (so
// Shift+M still labels marking, Ctrl+Shift+Z is redo); repeats of other keys are ignored.
const Shortcut* find_shortcut(Chord pressed, bool repeat = false);

// How the help and the docs write the input: "M", "Ctrl+Shift+Z", "Left", "F1", "left click".
std::string input_name(const Shortcut& shortcut);
// The first key of `action` (e.g. "Ctrl+Z" for Undo), for button captions; empty when none.
std::string key_for(Action action);

}  // namespace fieldlines::studio
