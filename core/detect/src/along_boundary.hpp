#pragma once
// Private: the far lines along the field boundary. The far touch line or goal line runs a few
// pixels below the field's edge, parallel to it, one or two pixels wide and blurred into the
// wall's or the boards' foot: its ridge is a few grey levels over a ramp, under the thin-line
// pass's threshold on any one column (ridge_pass.hpp), and its edges are no gradient edges at
// all. Along the boundary the line's row is known up to an offset, so the brightness is averaged
// over runs of columns at each offset below the boundary: the noise falls with the run's length
// while a line at a steady offset keeps its ridge.
//  - Per window of kWindowPx columns (kStepPx apart, so that each column counts twice), the mean
//    brightness at each whole offset from a few px above the boundary to `depth` px below it,
//    each column read at the boundary's row there.
//  - A window's hits: its profile's local maxima whose ridge (how much brighter than the
//    brighter side d px away, the most over d = 1..kAlongBoundaryReach) reaches the threshold
//    and a few times the window's own noise, placed to a fraction of a pixel by a parabola
//    through the maximum and its neighbours.
//  - Hits of neighbouring windows link when the second lies within kLinkPx of where the first
//    predicts it (the same offset, the boundary's slope between them): chains, cut where a
//    straight line through them would stray more than kStraightPx from one (a curved line, two
//    lines meeting at a corner), each piece of at least kMinWindows windows a segment along the
//    line's centre with its colour (the line's against its sides).
// Every buffer is reused: no allocation once warm.
#include <cstdint>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/field_boundary.hpp"
#include "fieldlines/detect/segment.hpp"

#pragma GCC visibility push(hidden)  // private to the library (see elsed/line_model.hpp)

namespace fieldlines {

// A ridge's sides lie up to this far from its centre: lines up to 5 px wide.
inline constexpr int kAlongBoundaryReach = 3;

struct AlongBoundary {
  struct Hit {
    float x = 0, y = 0;  // the window's centre column and the line's row there...
    float offset = 0;    // ...that far below the boundary
    int next = -1;       // the hit of the next window it links to
    bool linked = false;  // some hit of the window before links to it
  };
  std::vector<int> tops;        // per column from the boundary's first, its profile's first row
  std::vector<float> window;    // per offset, the window's mean grey level
  struct Run {  // columns of one block whose profiles start on one row
    int byte, bytes, top, block;  // the first column's byte in a row, the run's bytes, the row, the block
  };
  std::vector<Run> runs;
  std::vector<std::uint32_t> sums;  // per block of columns and offset, the summed B + G + R
  struct Point {
    float x = 0, y = 0;
  };
  std::vector<Hit> hits;       // every window's, left to right
  std::vector<Point> chain;    // one chain's hits in order
  std::vector<int> window_start;  // per window, its first hit (one more: the end)
};

// Into `out` (cleared first), the far lines along `boundary` within `depth` px below it whose
// ridge on the averaged profile reaches `threshold` grey levels, as segments along their centres
// with their colours (the line's against the mean of its sides, along the normal that points
// down, as the thin-line pass's) and their length as saliency. Nothing when `boundary` is empty.
void find_lines_along_boundary(const cv::Mat& bgr8, const FieldBoundary& boundary, int depth, float threshold,
                               AlongBoundary& work, std::vector<Segment>& out);

}  // namespace fieldlines

#pragma GCC visibility pop
