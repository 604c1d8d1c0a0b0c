#pragma once
// Where the canvas's backdrop shows around the image. The image is opaque, so the backdrop is
// filled only beside it: a software renderer (Mesa llvmpipe) pays for every pixel of every
// layer, and a full-canvas fill under a fitted image is about half a million pixels a frame.
#include <array>
#include <cstddef>
#include <span>

#include "gui/model/geometry.hpp"

namespace fieldlines::studio {

// `area` minus `hole` as at most four bands: the full-width rows above and below the hole, then
// the columns left and right of it between them. The bands share the hole's edges exactly, so
// together with it they cover the area once (pixels on an edge go to one side by the
// rasterizer's fill rule). A hole that misses the area, or has no area, leaves the whole area.
class Backdrop {
 public:
  Backdrop(const Rect& area, const Rect& hole);
  // A view of this object's own array: keep the Backdrop alive while it is read.
  std::span<const Rect> bands() const& { return {bands_.data(), count_}; }
  std::span<const Rect> bands() const&& = delete;  // a temporary's would dangle

 private:
  std::array<Rect, 4> bands_{};
  std::size_t count_ = 0;
};

}  // namespace fieldlines::studio
