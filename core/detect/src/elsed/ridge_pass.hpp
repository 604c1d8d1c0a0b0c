#pragma once
// Private: the thin-line pass's first stage. A painted line one to a few pixels wide gives two
// gradient edges of opposite sign that the Sobel of the smoothed image blurs into each other, and
// far, faint ones fall below the gradient threshold: the line itself, brighter than the pixels on
// both sides of it, is the stronger signal. Ridge maps (GradientMaps) hold that ridge instead of
// a gradient, so that ELSED's anchors, drawing and line fit run on them unchanged and draw
// segments along the lines' centres:
//  - the input is the frame's smoothed grey, as the gradient pass smooths it for its own Sobel:
//    the pass computes each ridge row while the rows it reads are in its ring (gradient_pass.hpp),
//    with no second pass over the frame;
//  - across x (and likewise across y), a pixel's ridge is how much brighter it is than the
//    brighter of the two pixels d px to either side, the most over d = 1..reach (a line up to
//    2 reach - 1 px wide fits between them), never below zero;
//  - dx and dy carry the ridge across x and across y in the Sobel's units (a ridge of c grey
//    levels reads 4c, as a step of c does), dy's sign set by which diagonal the line runs along
//    (the ridge across one diagonal against the other), so that the orientation validation
//    measures is the line's normal;
//  - mag is |dx| + |dy|, zero below the threshold and within `reach` of the frame's border;
//    the state holds the edge direction where kept (vertical elsewhere), every pixel Free.
//    Only blocks of columns with a kept pixel are written: the maps stay cleared from one frame
//    to the next but for those (the writes of a dense map cost more than finding the ridge).
// The maps cover the frame's first rows (the far rows, where lines are thin), in the frame's
// coordinates.
#include <cstdint>
#include <span>
#include <vector>

#include "elsed_types.hpp"
#include "ridge_rows_avx2.hpp"

#pragma GCC visibility push(hidden)  // private to the library (see line_model.hpp)

namespace fieldlines::elsed {

inline constexpr int kMaxRidgeReach = 8;  // DetectorParams::thin_reach's range

// The blocks one gradient pass (one row band) wrote: their first pixels' indices.
struct RidgeBlocks {
  std::vector<std::uint32_t> starts;  // room for every block the band may write; `count` used
  std::size_t count = 0;
};

// What the gradient pass writes the ridge maps into: `maps` (the band of the frame's first rows:
// ridge rows are [reach, min(maps->height, frame height - reach))) and, per row band of the pass,
// the list of what it wrote there.
struct RidgeTarget {
  int reach = 1;       // 1..kMaxRidgeReach (ElsedEngine::ridge_target clamps it)
  int first_row = 0;   // no ridge row above this one (the field's top: painted lines lie below it)
  int threshold = 1;   // on mag, 1..32767 (likewise)
  bool use_avx2 = false;
  GradientMaps* maps = nullptr;
  std::vector<RidgeBlocks>* blocks = nullptr;  // one per row band, sized by the pass
};

// Readies `maps` and `blocks` for a frame: a band `rows` high of a frame `width` wide. Only the
// blocks the last frame listed are cleared (nothing else was written), then the maps resized;
// every list emptied.
void ready_ridge_maps(int width, int rows, GradientMaps& maps, std::vector<RidgeBlocks>& blocks);
// One ridge row from 2 reach + 1 rows of the smoothed grey (`rows[reach]` the row itself), each
// `width` px; written and listed into `out`.
void ridge_row(const std::uint8_t* const* rows, int width, const RidgeTarget& target, const RidgeRow& out);
// The ridge maps' anchors: the full scale's grid (every scan_interval px) kept on every n-th of
// its columns and rows only, n returned here. On the ridge maps most grid points that are a
// local maximum lie on the turf's short bright blades, each drawn to no segment (on textured
// turf the drawing from them was about half the pass's cost), while a line needs one anchor per
// piece. The lattice lines lie min_line_length / sqrt 2 apart, to the nearest grid step, so a
// straight piece of the minimum length, whatever its direction and wherever it lies, spans that
// much across the columns or across the rows (less half a step at worst) and crosses a lattice
// line, whose grid points there are the full grid's: a level line is met on every lattice column
// at any grid row (a grid thinned both ways could miss it between its rows). Rounded rather than
// floored: the built-in grid of 10 px at the thin pass's 28 px keeps every 2nd line (1.98), not
// every one, for the pass's cost.
int ridge_anchor_lattice(int min_line_length, int scan_interval);
// The thin-line pass's minimum length: kThinLengthShare of the detector's. A ridge is validated on
// both of its flanks (a line's two edges at once), so a shorter piece of it is as much evidence as
// an edge of the full length; and a far line reaches the drawing in short pieces, broken where
// robots and posts stand on it (Bangkok's far penalty-area lines). Held out on the MSL venues:
// Bangkok marking recall 0.771 -> 0.785 at precision 0.956 -> 0.959, the other venues within
// 0.002; at 0.5 of it Bordeaux's precision falls (docs/detector.md).
inline constexpr double kThinLengthShare = 0.7;
int thin_min_length(int min_line_length);
// Blocks a band of `rows` rows `width` wide may list at most.
std::size_t max_ridge_blocks(int width, int rows);

}  // namespace fieldlines::elsed

#pragma GCC visibility pop
