#include "gui/model/canvas_backdrop.hpp"

#include <algorithm>

namespace fieldlines::studio {

Backdrop::Backdrop(const Rect& area_in, const Rect& hole_in) {
  const Rect area = area_in.normalised();
  const Rect h = hole_in.normalised();
  // The hole clipped to the area.
  const Rect hole{{std::max(h.min.x, area.min.x), std::max(h.min.y, area.min.y)},
                  {std::min(h.max.x, area.max.x), std::min(h.max.y, area.max.y)}};
  const auto add = [&](Rect r) {
    if (r.width() > 0 && r.height() > 0) bands_[count_++] = r;
  };
  if (!(hole.width() > 0 && hole.height() > 0)) {  // also NaN: draw the whole backdrop
    add(area);
    return;
  }
  add({area.min, {area.max.x, hole.min.y}});
  add({{area.min.x, hole.max.y}, area.max});
  add({{area.min.x, hole.min.y}, {hole.min.x, hole.max.y}});
  add({{hole.max.x, hole.min.y}, {area.max.x, hole.max.y}});
}

}  // namespace fieldlines::studio
