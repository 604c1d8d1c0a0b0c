#pragma once
// What the status bar says, as text: the counters (image, labels, review, zoom, frame time) and
// the notes after them (the last action's message, detection, saving, calibration's guidance).
// The panel fits them into one line (ellipsize.hpp) and shows everything on hover, so nothing
// runs off the window's edge and nothing is lost.
#include <string>
#include <vector>

#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

enum class Severity { Info, Warning, Error };

struct StatusNote {
  std::string text;
  Severity severity = Severity::Info;
};

// "image 3/20  |  5/40 labelled  |  120 to review  |  zoom 100%  |  frame 12.0 ms  |  images/a.png"
std::string status_counters(const StudioController& controller, double zoom, double frame_ms);

// Most urgent first (errors, then warnings, then the rest), so a cut line keeps what matters.
// The detection progress while it runs is the panel's (a bar), not a note.
std::vector<StatusNote> status_notes(const StudioController& controller, const std::string& message);

}  // namespace fieldlines::studio
