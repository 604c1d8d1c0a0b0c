#pragma once
// The centre circle as an image ellipse, from short stripe pieces: chains that bend smoothly,
// and pairs with the pieces along them.
//
// The detector's minimum segment length (40 px in the method's configuration) leaves no straight
// piece on a curve that bends quickly in the image. With `centre_circle` on, the frame is drawn
// a second time from the same gradients (anchors every 4 px, pieces from `piece_length`
// px), and those pieces that the classifier calls markings and the stripes check keeps
// (stripes.hpp) are the arc candidates. Two pieces chain when an end of one lies within two line
// widths plus 6 px of an end of the other and their directions differ by 3 to 40 degrees (a
// straight line broken in two does not bend; a corner bends more). The seed is one chain of at
// least three pieces or two chains of at least two (a flat ellipse's far and near arcs do not
// chain round its sharply bending ends), fitted with a conic (algebraic least squares under
// a + c = 1, which holds for every ellipse; three points per piece, centred and scaled), then
// again over a few rounds without the points off the last fit (a straight piece linked into a
// chain pulls the first fit away). It is a circle's image when the conic is an ellipse (axes at
// least 4 px, at most 12:1), its points lie on it (the median Sampson distance at most half the
// line width, at least 2.5 px: a piece is a chord, its middle inside the curve; three quarters
// within twice that), and they cover at least 150 degrees of it (seen from its centre, in its own
// axes; a piece covers the turn between its samples), or, when the frame cuts the ellipse (its
// centre beyond the frame's edge), 80 % of the turn inside the frame and at least 120 degrees. The best seed wins; every other chain
// joins it when the fit of both still passes and covers more of the turn (the circle cut by the
// halfway line or a robot is several chains).
//
// Pieces of a flat or faint circle often do not chain at all. So every pair of the 16 longest
// pieces is also a hypothesis: fitted with axes along the image's turned by -9 to 9 degrees in
// steps of 3 (four unknowns, which two pieces determine; the camera's roll is small, but a circle
// seen off the optical axis is a turned ellipse), its support is those pieces along it (their
// samples within twice the pair's tolerance, their direction within 20 degrees of its tangent:
// a line crossing the circle is no support), scored by the turn the support covers (at least
// four pieces). The best pair's support among all pieces is fitted in full and checked as a
// chain is, twice over; it replaces the chains' ellipse when it covers more of the turn. The
// cap bounds the cost (at most 120 pairs, 840 fits of four unknowns). At most one ellipse per frame (there
// is one centre circle); its confidence is the share of the turn its points cover.
//
// Given the frame, the ellipse is then refitted to the paint itself: at 72 points round it, on
// the turn its pieces cover, the middle of the bright pixels within 1.5 tolerances (at least 4
// px) along its normal. A piece is a straight fit to a curved run of pixels, a tangent whose
// ends stand off the paint near a flat ellipse's sharp ends, so the pieces' fit comes out too
// long; the paint's is not. Kept when at least 12 points are read and most lie on the refit.
// Given the field colour too, an ellipse is refused when more than 5 % of its points in the frame
// show bare turf across it (every pixel within the same reach in the field colour, none
// brighter): a circle's image lies on paint wherever the frame shows it, save behind a robot (no
// field colour there), while an ellipse fitted to one arc and a stray piece runs over turf. The
// chains' ellipse and the pairs' are tried in turn, the one covering more of the turn first.
// With the camera known, the circle fitted on the turf (ground_circle.hpp) is tried before them,
// and they are not fitted when the frame confirms it.
//
// The fits are our own (conic_fit.hpp): warm detect allocates nothing with this stage on.
#include <array>
#include <cstdint>
#include <optional>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>
#include <span>
#include <vector>

#include "fieldlines/detect/detector_params.hpp"
#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/detect/ground_camera.hpp"

namespace fieldlines {

// Scratch reused between frames; its contents mean nothing to a caller.
struct CircleWorkspace {
  struct Point {
    float x = 0, y = 0;
    std::uint8_t inlier = 0;
  };
  std::vector<int> parent;         // union-find over the pieces
  std::vector<int> chain_size;     // pieces per chain root
  std::vector<Point> points;       // samples of the chain being fitted
  std::vector<std::uint8_t> on_ellipse;  // per piece: part of the ellipse found
  std::vector<int> order;                // pieces by length
  std::vector<std::uint8_t> support;     // per piece: along the ellipse being tried
  std::vector<Point> refined;            // the paint's centre read round the ellipse
  // The fit on the turf (camera known):
  struct GroundPiece {
    std::array<cv::Point2d, 3> at;  // the piece's samples on the turf, metres
    bool valid = false;             // all three below the horizon, a chord's length
  };
  struct GroundSample {
    double u = 0, v = 0;  // px
    double scale = 0;     // metres per px there
  };
  std::vector<GroundPiece> ground;           // per piece
  std::vector<std::uint8_t> ground_support;  // per piece: along the circle on the turf
  std::vector<GroundSample> ground_samples;  // the support's samples, for the refinement
  std::array<double, 5> ground_fit{};        // centre x, y, radius (m); pitch, roll offsets (rad)
};

// Fits the centre circle to `pieces` (stripe centre lines of short segments) into `out`
// (cleared first: empty or one ellipse); `work.on_ellipse[i]` tells whether piece i is on it.
// `bgr`: the 8-bit BGR frame they were found in, for the refit on the paint; empty: none.
// `field`: the frame's field colour, for the bare-turf check; none: no check.
// `camera`: the camera over the field, when known, for the fit on the turf of a circle of
// `radius_m` metres (ground_camera.hpp); none: image fits alone.
void find_centre_circle(std::span<const Marking> pieces, CircleWorkspace& work, std::vector<MarkingEllipse>& out,
                        const cv::Mat& bgr = {}, const std::optional<Rgb>& field = std::nullopt,
                        const std::optional<GroundCamera>& camera = std::nullopt,
                        double radius_m = DetectorParams{}.centre_circle_radius);

}  // namespace fieldlines
