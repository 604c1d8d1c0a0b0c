#pragma once
// Private: the thin-line pass's first stage. A painted line one to a few pixels wide gives two
// gradient edges of opposite sign that the Sobel of the smoothed image blurs into each other, and
// far, faint ones fall below the gradient threshold: the line itself, brighter than the pixels on
// both sides of it, is the stronger signal. This fills GradientMaps with that ridge instead of a
// gradient, so that ELSED's anchors, drawing and line fit run on it unchanged and draw segments
// along the lines' centres:
//  - the input is the frame's smoothed grey, as the gradient pass smoothed it for its own
//    Sobel (GradientMaps::smooth): no second pass over the colour frame;
//  - across x (and likewise across y), a pixel's ridge is how much brighter it is than the
//    darker of the two pixels d px to either side, the most over d = 1..reach (a line up to
//    2 reach - 1 px wide fits between them), never below zero;
//  - dx and dy carry the ridge across x and across y in the Sobel's units (a ridge of c grey
//    levels reads 4c, as a step of c does), dy's sign set by which diagonal the line runs along
//    (the ridge across one diagonal against the other), so that the orientation validation
//    measures is the line's normal;
//  - mag is |dx| + |dy|, zero below the threshold and within `reach` of the frame's border;
//    the state holds the edge direction where kept (vertical elsewhere), every pixel Free.
//    Only blocks of columns with a kept pixel are written: the maps stay cleared from one frame
//    to the next but for those (the writes of a dense map cost more than finding the ridge).
// The maps cover the frame's first `rows` rows (the far rows, where lines are thin), in the
// frame's coordinates.
#include <cstdint>
#include <vector>

#include "elsed_types.hpp"

#pragma GCC visibility push(hidden)  // private to the library (see line_model.hpp)

namespace fieldlines::elsed {

class RidgePass {
 public:
  static constexpr int kMaxReach = 8;  // DetectorParams::thin_reach's range
  RidgePass();
  // `frame`: a gradient pass's maps with the smoothed grey kept (GradientPass::set_keep_smoothed);
  // without it no pixel has a ridge. Sizes `maps` (by capacity) and fills all of it.
  void run(const GradientMaps& frame, int rows, int reach, int threshold, GradientMaps& maps);

 private:
  bool use_avx2_;  // the CPU has AVX2: ridge_rows_avx2's kernel first
  std::vector<std::uint32_t> blocks_;  // the blocks the last run() wrote (ridge_rows_avx2.hpp), to clear
  std::size_t block_count_ = 0;
};

}  // namespace fieldlines::elsed

#pragma GCC visibility pop
