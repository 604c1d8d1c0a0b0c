#pragma once
// Painted lines as stripes. A colour transition at one edge cannot tell a painted line from a
// wall's foot, a goal post or a robot's white bar; geometry can: a painted line is a stripe,
// turf, then paint of a plausible width, then turf again.
//
// Each segment labelled Marking is checked by profiles across it at `stripe_samples` points
// along its length, read in the 8-bit BGR frame from outside its edge into its bright side (the
// side its colour gradient points to; the image decides when the gradients are zero):
//  - turf in the frame's field colour (features/field_pixel.hpp) outside the edge, or the
//    frame's dark rim (below) just past its blur, when turf past the paint is in that colour;
//  - paint: a peak brighter by a tenth than the turf on both sides, or than the field colour
//    where that is darker (turf in a wall's shade, down to 0.8 of the field colour), and out of
//    the field colour (see ThinLines for paint too thin to leave it);
//  - turf again past the paint, within the largest plausible width: in the field colour or in
//    the colour of the turf outside (far turf in haze misses the frame's colour), and darker
//    than half-way to the paint; or the frame's dark rim (a fisheye's corner, the robot's own
//    body at the frame's bottom): dark, and mostly dark with no field from there to the frame's
//    bottom or side border within a tenth of the height. The largest plausible width grows
//    linearly towards the image bottom, where the field is nearest: `stripe_max_width` times the
//    image height on the bottom row, a quarter of that on the top rows (calibration sets it from
//    the venue's own stripes: fieldlines/train/stripe_width.hpp);
//  - between paint and turf on either side only a fade (at most 10 px, for motion blur, or a
//    lens's colour fringe; none darker than 0.7 of the field colour): a robot's dark body beside
//    its white bar is no turf.
// The width is the distance between the two half-way crossings of brightness (paint to turf),
// so it does not depend on where in the edge's blur the segment was fitted. A profile that
// leaves the image through its bottom or sides while still in paint counts neither way (a line
// near the camera running out of the frame); one leaving through the top is no stripe (above
// the field are walls). A segment is a stripe when at least one profile is, and no fewer are
// than are not.
//
// A stripe edge whose opposite-sign twin is a stripe too (parallel within 5 degrees,
// overlapping along its length, at about the measured width on its paint side) is merged with
// it into one Marking: over the union of their lengths, the line half-way between the two edges
// at each end (a line seen in perspective narrows with distance, so its edges converge), and
// their mean measured width. A stripe without a twin (its second edge was not detected: too
// short, broken by a robot, below the detector's minimum length) is still a marking, its
// centre line through the profiles' centres (a robust line fit of the centre offset along the
// edge, for the same narrowing), unless `stripe_require_twin` is
// set (measured in docs/detector.md: requiring twins costs recall and buys no precision).
// Every other Marking segment, and every one when the frame shows no field, becomes None, so
// every consumer of labels sees the check. Buffers are the caller's: no allocation once warm.
//
// A marking segment drawn on a blur ramp rather than at the paint's edge (motion blur or a
// ghost copy spreads the edge over several px, and the gradient's ridge need not lie half-way) is
// moved onto the edge its profiles measure: when their edges lie at least 2 px off it (a sharp
// edge's ridge is within a pixel of its half-way crossing), all within 1 px of one line (a
// chord of a curve spreads more) and at most the blur's 10 px away at either end. Two marking
// segments a move puts on one edge (a ghost's two drawn steps) become one: the longer spans
// both, the shorter is none. Held-out SSL frames, calibrated: marking P/R 0.862/0.765 ->
// 0.939/0.776; the MSL venues and Humanoid as before (docs/detector.md).
//
// A caller that wants straight lines only (the junctions: Shape::Straight) gets no candidate
// whose paint bows from its edge's line by more than 1 px or a fifth of its width, whichever is
// more (the mean offset of its middle profiles, a quarter to three quarters along, from the
// robust line through all, less that of the outer ones; a profile whose width strays from the
// median as a twin's distance may not crossed other paint and has no say): a chord of a curve,
// such as the centre circle's, bows by 1.3 to 4.5 px; a straight line a few px wide by under 0.9.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/detector_params.hpp"
#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/detect/segment.hpp"
#include "fieldlines/detect/turf_colours.hpp"

namespace fieldlines {

// Scratch reused between frames; its contents mean nothing to a caller.
struct StripeWorkspace {
  struct Candidate {
    std::size_t segment = 0;     // index into the segments
    float ux = 0, uy = 0;        // unit direction, x0,y0 -> x1,y1
    float sx = 0, sy = 0;        // unit normal towards the paint
    // The paint's centre along (sx, sy) at the segment's two ends, px: a line through the
    // profiles' centres, since a line seen in perspective widens towards the camera and its
    // centre drifts from the edge. The median width, px.
    float offset0 = 0, offset1 = 0, width = 0;
    float bow = 0;  // px: how far the middle profiles' centres lie off that line, beyond the outer ones'
    // The paint's near edge (its half-way crossing) the same way: a line through the profiles'
    // edges, their median, and how far the farthest lies off that line, px.
    float edge0 = 0, edge1 = 0, edge_median = 0, edge_spread = 0;
    bool paired = false;
    bool moved = false;  // onto its paint's edge (see above)
    bool twin_only = false;  // a marking only as a marking's twin
  };
  std::vector<Candidate> candidates;
  std::vector<float> brightness;       // one profile: R + G + B per step
  std::vector<std::uint8_t> is_field;  // one profile: field colour or not per step
  std::vector<const std::uint8_t*> pixels;  // one profile: the pixel of each step
};

// A line too thin to fill a pixel (the synthetic SSL field's 1 cm lines a few metres off, a real
// field's far lines) blends a little grey into turf: its peak stays in the field colour. Such a
// peak is paint when its chromaticity lies at least half-way from the turf's on both sides to
// what grey light brightening that turf to the peak would give (brighter turf keeps the turf's
// chromaticity). Accepted: on any segment. Level: only on a segment at least 40 px long and
// within 30 degrees of the image's rows, as the detector runs it: a far line seen from a robot's
// height runs nearly level in the image, while thin grey posts and robot limbs stand upright or
// are short (docs/detector.md). The studio proposes every such line as paint
// (gui/model/proposal_gate.hpp).
enum class ThinLines : std::uint8_t { Level, Accepted };

// The `stripe_max_width` under which paint `width` px wide, centred on row `y` of a frame `rows`
// high, is just plausible: the largest plausible width's rule (above) inverted. Calibration
// measures a venue's stripes with it (fieldlines/train/stripe_width.hpp).
float width_share(float width, float y, int rows);

// Which stripes a caller takes: any, or straight ones only (see above).
enum class Shape : std::uint8_t { Any, Straight };

// `bgr8`: the frame the segments were detected in (8-bit BGR; anything else keeps no marking).
// `field`: the frame's field colour (LineDetector measures it), with its turf colours when the
// detector measured them (DetectorParams::stripe_turf_colours); empty: no turf anywhere.
// `on_field`: when given, a stripe whose paint's centre lies above that field boundary by more
// than a line's blur (lies_above) is none: paint lies on the field, and an edge along the
// boundary whose bright side is beyond it is the field's edge against a light floor or boards.
// With `on_field`, a segment labelled None along that boundary that is the outer edge of a line
// painted along the field's edge (the field's dark surround, paint, turf; edge_lines.hpp in
// the sources) becomes a Marking, with its stripe: the surround's strong edge is the one the
// detector draws there, and its colours are no marking's.
// Relabels `segments` in place and writes one Marking per stripe into `out` (cleared first).
void find_stripes(const cv::Mat& bgr8, const FieldColours& field, std::span<Segment> segments,
                  const DetectorParams& params, StripeWorkspace& work, std::vector<Marking>& out,
                  ThinLines thin = ThinLines::Level, Shape shape = Shape::Any, const FieldBoundary* on_field = nullptr);

// Every segment checked as a stripe as though its colours made it a marking, whatever its label:
// what the stripes stage would keep of it under any thresholds. Calibration fits the markings on
// these, the studio proposes through them. Buffers reused between frames.
class StripeCheck {
 public:
  // False when the frame allows no check (no field colour, not 8-bit BGR); otherwise flags()
  // holds one flag per segment, 1 for a stripe.
  bool run(const cv::Mat& bgr8, const FieldColours& field, std::span<const Segment> segments,
           const DetectorParams& params, ThinLines thin = ThinLines::Level);
  const std::vector<std::uint8_t>& flags() const { return flags_; }
  // After run(): per segment, its paint's median width as width_share() at the paint's centre; 0
  // where it is no stripe.
  const std::vector<float>& width_shares() const { return width_shares_; }

  // run() with ThinLines::Level into flags() and with ThinLines::Accepted into thin_flags(),
  // from one set of profiles per segment (the two differ only in the profiles whose peak is
  // paint too thin to leave the field colour): the same flags as the two runs, at about half
  // their cost.
  bool run_with_thin_lines(const cv::Mat& bgr8, const FieldColours& field, std::span<const Segment> segments,
                           const DetectorParams& params);
  const std::vector<std::uint8_t>& thin_flags() const { return thin_flags_; }

 private:
  std::vector<Segment> checked_;
  StripeWorkspace work_;
  std::vector<StripeWorkspace::Candidate> level_;  // run_with_thin_lines()'s ThinLines::Level candidates
  std::vector<Marking> stripes_;
  std::vector<std::uint8_t> flags_, thin_flags_;
  std::vector<float> width_shares_;
};

}  // namespace fieldlines
