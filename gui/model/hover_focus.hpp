#pragma once
// The hovered segment when a key chose it. Tab brings the least certain segment into view and
// hovers it, so M/B/N label it; the view moved under a pointer resting on the image, so whatever
// now lies under that pointer must not take the hover back. The chosen segment stays hovered
// until the pointer itself moves (or a button is pressed) over another segment, the image
// changes, or the segment is gone; otherwise the pointer's pick (HoverCycle) is the hovered one.
#include <cstddef>
#include <optional>

namespace fieldlines::studio {

class HoverFocus {
 public:
  // A key chose `segment` of image `image`: hovered from the next update on.
  void hold(std::size_t image, std::size_t segment);
  // Back to the pointer's pick (Space turns to the segments under the cursor).
  void release() { held_.reset(); }

  // Once per frame: `pointer` = the segment the pointer picks on image `image` (none when it is
  // over no segment or off the canvas), `pointer_acted` = the pointer moved or a button was
  // pressed over the canvas this frame. Returns the hovered segment.
  std::optional<std::size_t> update(std::size_t image, std::size_t segment_count, std::optional<std::size_t> pointer,
                                    bool pointer_acted);

  std::optional<std::size_t> held() const { return held_; }

 private:
  std::optional<std::size_t> held_;
  std::size_t image_ = 0;
};

}  // namespace fieldlines::studio
