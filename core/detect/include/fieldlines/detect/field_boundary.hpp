#pragma once
// The field boundary of a frame: where the field's green ends, as a polyline left to right.
//
// The field's colour is the frame's own (light.hpp's estimate); a pixel is field when its
// chromaticity is within a tolerance of the field's and its brightness within a range of it: a
// loose "green dominates" test also passes grey walls under a greenish camera. Each sampled column
// is scanned from the bottom up (the field is below the camera's horizon) for the top of its field:
// field pixels interrupted by less than a gap (a ball, a robot's foot) belong to it, and so does
// paint (a line near the camera can be wider than any gap); the first longer stretch without field
// ends it. A gap that long is the field's own only when the field goes on well beyond it: the top
// then settles below any band without field nearly as long as the gap (a wall) that less than twice
// its length of field lies above (a green curtain or poster over the wall). A lone run of field a
// few samples long above a band without field half the gap long (a shoe's greenish sliver, the
// next field's turf between people's legs) carries the scan on but is no top. A line painted along
// the turf's edge, with the field's dark surround right beyond it, raises the top to its own
// (`edge_line_fraction`). A column whose scan a robot or a person standing on the field ended looks
// on above it: turf there, no higher than the rest of the boundary, is the field's
// (`past_occluder_run`, `past_occluder_rise`). Column tops are median-filtered across 7
// neighbouring columns (a column running up a green poster, pole or shirt is an outlier, and so are
// up to 3 side by side), then replaced by their upper convex hull: a robot or player standing on
// the field hides the green behind it and pulls its columns down, but the boundary of a flat field
// seen from inside it is convex in the image, so the hull bridges such notches (B-Human's field
// boundary does the same). A notch at the frame's side has no column beyond it to bridge to: a
// robot standing at the side, a fisheye's dark corner or turf in a light the field colour misses
// pulls the hull's end down towards the bottom corner, and everything on that side would lie above
// the field. So the hull's end pieces that fall towards the frame's side more steeply than
// `max_end_slope` are dropped, and so are those steeper than `shoulder_slope` that together fall
// by more than the gap (a robot's gentler shoulder); the boundary is held level from the last
// piece kept (FieldBoundary::y_at). A frame without green gives an empty boundary. Buffers are the caller's
// and keep their capacity: no allocation once warm.
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/segment.hpp"
#include "fieldlines/detect/turf_colours.hpp"


namespace fieldlines {

struct FieldBoundaryParams {
  int column_step = 8;         // px between scanned columns
  int row_step = 2;            // px between samples along a column
  double gap_fraction = 0.06;  // a run without green this share of the height ends the field...
  int min_gap_px = 8;          // ...and at least this long
  // A band without field at least this share of the gap (a wall: a ball or a foot is shorter)
  // costs this many field samples per sample: the field above it must outweigh it to count.
  double band_fraction = 0.8;
  float band_cost = 2.0f;
  // ...and a band at least a third paint this share (a light floor strip before the next field).
  double paint_band_fraction = 0.5;
  // A run of field above a band without field at least this share of the gap long is the
  // column's top only when it is at least `min_top_samples` long: a lone greenish sample (a shoe,
  // the next field's turf between people's legs above the floor strip before it) carries the
  // scan on but is no top. Humanoid within 4 px 0.828 -> 0.841 (montreal _aa_000001 0.25 ->
  // 0.84; the turf inside a goal, under its net, is such a sliver too: frame2150 0.64 -> 0.39).
  double lone_band_fraction = 0.5;
  int min_top_samples = 3;
  // While a column's top settles, a sample as saturated as `settle_chain_saturation` of the field
  // colour (its distance from grey) whose chromaticity lies within `settle_chain_step` of the
  // last turf sample above it is turf too (ChainedTurf, field_pixel.hpp): turf in a light the
  // frame's colours miss, such as under a goal's net, continues the field rather than reading as
  // a band without it. 0: off. Humanoid within 4 px 0.841 -> 0.859 (frame2150 0.39 -> 0.54); the
  // MSL venues and SSL unchanged or +0.002. In the column scan as well it ran up greenish walls
  // (Bordeaux 0.995 -> 0.77).
  float settle_chain_step = 0.03f;
  float settle_chain_saturation = 0.6f;
  double min_columns = 0.25;   // columns with field needed, as a share: fewer is no boundary
  float chroma_tolerance = 0.07f;       // |r/s - r_f/s_f| + |g/s - g_f/s_f|, s = r + g + b
  // ...and this with the frame's turf colours, which hold the turf in every light the frame
  // shows: the field's surround (a dark band, a greyish carpet) is often as near the median.
  float turf_chroma_tolerance = 0.05f;
  TurfBrightness brightness;           // s / s_f: shade to sun patch
  int median_columns = 7;      // window of the filter over column tops (odd)
  float paint_brightness = 1.4f;     // paint: s / s_f at least this...
  float paint_chroma = 0.1f;         // ...and |r/s - 1/3| + |g/s - 1/3| at most this
  double max_paint_fraction = 0.15;  // a run of paint longer than this share of the height is a wall
  // Paint right above the field's top, at most this share of the height, then within a blur a
  // dark sample: a line along the turf's edge, which raises the top to the dark (MSL Bordeaux:
  // within 4 px 0.667 -> 0.834). Wider paint there is a white wall or a light floor.
  double edge_line_fraction = 0.02;
  float dark_brightness = 0.5f;  // dark: s / s_f below this (the field's surround, a wall's foot)
  // Inside the field, the sample up to this many steps up is tested first and those between
  // skipped when it is field (capped so that the skipped run is shorter than the gap): the same
  // tops as testing every sample (0), with a few reads per column.
  int max_jump = 8;
  // Rows per column: a hull end falling towards the frame's side more steeply is dropped (37
  // degrees: a field corner seen from inside falls away at about half that; a robot's shoulder
  // at the side of a fisheye frame at 0.86). At 0.5 the synthetic frames' corners are cut.
  float max_end_slope = 0.75f;
  // ...and the end pieces steeper than `shoulder_slope` when together they fall by at least
  // `shoulder_fall` of the gap: a robot's shoulder at a fisheye frame's side, its pieces at
  // 0.63-0.73 rows per column over 1.4 gaps (MSL Bordeaux `_104852`, the pale turf beyond it no
  // field colour): within 4 px 0.893 -> 0.995, the other venues the same. A synthetic field's
  // far edge falls at 0.67 for 0.55 of a gap at a frame's corner: with every end steeper than
  // 0.6 dropped, one wrong marking on the light table's shadows frames (built-in detector).
  float shoulder_slope = 0.6f;
  float shoulder_fall = 1.0f;
  // Turf past an occluder: a column whose scan ended at a robot or a person standing on the
  // field looks on above it, and takes the top of the first field there that reaches at least
  // this share of the gap above the first field sample it met (0: never; a robot's dark green
  // panel is shorter: from 0.9 to 1.5 the venues' figures are the same, at 0.8 Bangkok within
  // 4 px loses 0.065, at 1.7 De Locht 0.03)...
  double past_occluder_run = 1.2;
  // ...when that top lies at most this share of the gap above the boundary's highest point: the
  // field's turf beside the rest of its edge, not the next field beyond a floor strip. Within 4
  // px, MSL Bordeaux 0.859 -> 0.893 and De Locht 0.753 -> 0.783 (robots at a fisheye frame's
  // side), Bangkok 0.958 -> 0.953 (its dark green surround, field to the scan, above a robot);
  // any rise from 0.25 to 1.5 gives the same figures, 0 loses De Locht's gain.
  double past_occluder_rise = 0.5;
};

struct FieldBoundary {
  struct Point {
    float x = 0, y = 0;
  };
  std::vector<Point> points;     // the hull, left to right; empty: no field seen
  std::vector<Point> columns;    // each scanned column's top of green (before the hull)
  std::vector<int> scan_ends;    // per column, the row where its scan ended (-1: the frame's top)
  int image_height = 0;
  bool empty() const { return points.empty(); }
  void clear() { points.clear(), columns.clear(), scan_ends.clear(); }
  // The boundary's row at column x (linear between hull points, held flat past the ends);
  // -1 when empty (every row is below it).
  float y_at(float x) const;
  // The row of the boundary's highest point (its least y); -1 when empty.
  float highest() const;
  // Whether the field reaches the frame's top row in at least half of the columns with field:
  // the camera looks down at the turf, and no row of the frame is far (the coarse pass's band
  // then starts at the top: DetectorParams::coarse_from).
  bool fills_top() const;
};

// Whether the point (x, y) lies above the boundary by more than a line's own blur (4 px); false
// when the boundary is empty.
bool lies_above(float x, float y, const FieldBoundary& boundary);

// Where a segment's midpoint lies: above the boundary by more than a line's own blur, along it
// (within along_band_px), or below it. Below when the boundary is empty.
enum class BoundaryPlace { Above, Along, Below };
// The band along the boundary, either side, px: 3 % of the image height, at least 6 px (its blur
// and the hull's chords over a far edge).
float along_band_px(int image_height);
BoundaryPlace place_of(const Segment& segment, const FieldBoundary& boundary);

// The segment's label under the gate: a marking above the boundary and a boundary edge not along
// it become none (Thresholds::field_boundary_gate).
Label gate_by_field_boundary(const Segment& segment, const FieldBoundary& boundary);

// 8-bit BGR input; anything else gives an empty boundary. The first form measures the frame's
// field colour itself (light.hpp); the second takes it from a caller that already has it, with
// the frame's turf colours when given (a field in sun and shade: turf_colours.hpp).
void find_field_boundary(const cv::Mat& bgr8, FieldBoundary& out, const FieldBoundaryParams& params = {});
void find_field_boundary(const cv::Mat& bgr8, const Rgb& field_colour, FieldBoundary& out,
                         const FieldBoundaryParams& params = {}, const TurfColours* turf = nullptr);

}  // namespace fieldlines
