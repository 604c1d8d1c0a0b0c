#include "gui/model/status_line.hpp"

#include <algorithm>
#include <cstdio>

namespace fieldlines::studio {

std::string status_counters(const StudioController& c, double zoom, double frame_ms) {
  std::size_t labelled = 0;
  for (const Segment& s : c.segments()) labelled += s.label != Label::Unlabelled;
  char line[160];
  std::snprintf(line, sizeof line, "image %zu/%zu  |  %zu/%zu labelled  |  %zu to review  |  zoom %.0f%%  |  frame %.1f ms",
                c.image_count() ? c.current() + 1 : 0, c.image_count(), labelled, c.segments().size(), c.to_review(),
                zoom * 100, frame_ms);
  // The path last: where the line is cut, the counts stay and the path's end goes (hover shows it).
  return std::string(line) + "  |  " + (c.image_count() ? c.project().images[c.current()].path : std::string("-"));
}

std::vector<StatusNote> status_notes(const StudioController& c, const std::string& message) {
  std::vector<StatusNote> notes;
  if (!c.save_error().empty()) notes.push_back({"autosave failed: " + c.save_error(), Severity::Error});
  if (!c.guidance().empty()) notes.push_back({c.guidance(), Severity::Warning});
  if (!message.empty()) notes.push_back({message, Severity::Info});
  if (!c.detection().running()) {
    if (const std::string detection = c.detection_report().summary(); !detection.empty())
      notes.push_back({detection, c.detection_report().failed.empty() ? Severity::Info : Severity::Warning});
  }
  if (c.save_error().empty() && c.save_count() > 0) notes.push_back({"saved", Severity::Info});
  std::stable_sort(notes.begin(), notes.end(), [](const StatusNote& a, const StatusNote& b) { return a.severity > b.severity; });
  return notes;
}

}  // namespace fieldlines::studio
