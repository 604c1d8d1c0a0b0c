#include "gui/model/shortcuts.hpp"

#include <array>

namespace fieldlines::studio {

namespace {

constexpr Chord key(Key k) { return {k, false, false}; }
constexpr Chord ctrl(Key k, bool shift = false) { return {k, true, shift}; }
// A key that moves the Camera tab's camera one step (camera_nudge.hpp); held, it repeats.
constexpr Shortcut nudge(Chord chord, std::string_view description, CameraAxis axis, int direction) {
  return {chord, Action::NudgeCamera, description, {}, -1, true, FeatureLayer::Count, {axis, direction}};
}

constexpr std::array kShortcuts{
    Shortcut{key(Key::M), Action::LabelMarking, "label the hovered segment marking"},
    Shortcut{key(Key::B), Action::LabelBoundary, "label the hovered segment boundary"},
    Shortcut{key(Key::N), Action::LabelNone, "label the hovered segment none"},
    Shortcut{key(Key::C), Action::LabelClear, "clear the hovered segment's label"},
    Shortcut{key(Key::Space), Action::NextUnderCursor, "hover the next segment under the cursor (overlapping edges; the tooltip says 1 of 2)"},
    Shortcut{{}, Action::Pointer, "label the hovered segment with the brush (Label tab; marking by default)", "left click"},
    Shortcut{{}, Action::Pointer, "label the hovered segment none", "right click"},
    Shortcut{{}, Action::Pointer, "label every segment the rectangle touches with the brush", "left drag"},
    Shortcut{{}, Action::Pointer, "pan", "right or middle drag"},
    Shortcut{{}, Action::Pointer, "zoom at the cursor", "wheel"},
    Shortcut{key(Key::F), Action::Fit, "fit the image to the window"},
    Shortcut{key(Key::Left), Action::PreviousImage, "previous image", {}, -1, true},
    Shortcut{key(Key::Right), Action::NextImage, "next image", {}, -1, true},
    Shortcut{key(Key::E), Action::NextImageWithErrors, "next image where the thresholds disagree with a label"},
    Shortcut{key(Key::P), Action::Propose, "propose a label for every unlabelled segment (label-free, then trained on your labels)"},
    Shortcut{key(Key::Enter), Action::AcceptProposals, "accept this image's proposals (one undo step) and go to the next image to review"},
    Shortcut{key(Key::Tab), Action::FocusUncertain, "show the project's least certain unlabelled segment"},
    Shortcut{key(Key::G), Action::ToggleFeatureLayer, "show / hide the field boundary (where the green ends)", {}, -1, false, FeatureLayer::FieldBoundary},
    Shortcut{key(Key::I), Action::ToggleFeatureLayer, "show / hide the line intersections (L, T, X)", {}, -1, false, FeatureLayer::Intersections},
    Shortcut{key(Key::O), Action::ToggleFeatureLayer, "show / hide the centre circle", {}, -1, false, FeatureLayer::CentreCircle},
    Shortcut{key(Key::S), Action::ToggleFeatureLayer, "show / hide the stripes' centre lines and widths", {}, -1, false, FeatureLayer::Stripes},
    nudge(key(Key::Up), "Camera tab: tilt the camera up a step (pitch -0.05 degree)", CameraAxis::Pitch, -1),
    nudge(key(Key::Down), "Camera tab: tilt the camera down a step (pitch +0.05 degree)", CameraAxis::Pitch, 1),
    nudge(ctrl(Key::Left), "Camera tab: roll the camera anticlockwise a step (-0.05 degree)", CameraAxis::Roll, -1),
    nudge(ctrl(Key::Right), "Camera tab: roll the camera clockwise a step (+0.05 degree)", CameraAxis::Roll, 1),
    nudge(key(Key::PageUp), "Camera tab: raise the camera a step (+0.5 cm)", CameraAxis::Height, 1),
    nudge(key(Key::PageDown), "Camera tab: lower the camera a step (-0.5 cm)", CameraAxis::Height, -1),
    Shortcut{ctrl(Key::Z), Action::Undo, "undo (one step per user action)"},
    Shortcut{ctrl(Key::Z, true), Action::Redo, "redo"},
    Shortcut{ctrl(Key::Y), Action::Redo, "redo"},
    Shortcut{ctrl(Key::T), Action::ToggleTraining, "start / stop training"},
    Shortcut{key(Key::F1), Action::ShowTab, "Images tab", {}, 0},
    Shortcut{key(Key::F2), Action::ShowTab, "Label tab", {}, 1},
    Shortcut{key(Key::F3), Action::ShowTab, "Thresholds tab", {}, 2},
    Shortcut{key(Key::F4), Action::ShowTab, "Train tab", {}, 3},
    Shortcut{key(Key::F5), Action::ShowTab, "Metrics tab", {}, 4},
    Shortcut{key(Key::F6), Action::ShowTab, "Export tab", {}, 5},
    Shortcut{key(Key::F7), Action::ShowTab, "Camera tab", {}, 6},
    Shortcut{ctrl(Key::Q), Action::Quit, "quit"},
};

std::string key_name(Key k) {
  switch (k) {
    case Key::None: return {};
    case Key::Left: return "Left";
    case Key::Right: return "Right";
    case Key::Up: return "Up";
    case Key::Down: return "Down";
    case Key::PageUp: return "Page Up";
    case Key::PageDown: return "Page Down";
    case Key::Enter: return "Enter";
    case Key::Tab: return "Tab";
    case Key::Space: return "Space";
    default: break;
  }
  const int code = static_cast<int>(k);
  if (code >= static_cast<int>(Key::F1)) {
    // Appended, not "F" + ...: GCC 12 warns falsely (-Wrestrict) on that concatenation.
    std::string name = "F";
    name += std::to_string(code - static_cast<int>(Key::F1) + 1);
    return name;
  }
  return std::string(1, static_cast<char>(code));
}

}  // namespace

std::span<const Shortcut> shortcuts() { return kShortcuts; }

const Shortcut* find_shortcut(Chord pressed, bool repeat) {
  if (pressed.key == Key::None) return nullptr;
  const Shortcut* match = nullptr;
  for (const Shortcut& s : kShortcuts) {
    if (s.chord.key != pressed.key || s.chord.ctrl != pressed.ctrl) continue;
    if (s.chord.shift == pressed.shift) {  // exact: wins over a match ignoring Shift
      match = &s;
      break;
    }
    if (!s.chord.shift && !match) match = &s;  // Shift held, but this chord does not name it
  }
  if (match && repeat && !match->repeats) return nullptr;
  return match;
}

std::string input_name(const Shortcut& s) {
  if (s.chord.key == Key::None) return std::string(s.pointer);
  return std::string(s.chord.ctrl ? "Ctrl+" : "") + (s.chord.shift ? "Shift+" : "") + key_name(s.chord.key);
}

std::string key_for(Action action) {
  for (const Shortcut& s : kShortcuts) {
    if (s.action == action && s.chord.key != Key::None) return input_name(s);
  }
  return {};
}

}  // namespace fieldlines::studio
