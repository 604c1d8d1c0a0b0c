#pragma once
// Private: an image conic fitted to points by algebraic least squares, and the ellipse it is
// (the centre circle's fits, centre_circle.cpp and ground_circle.cpp).
//
// The fit is written out (a 5x5 solve on the stack) rather than cv::fitEllipse, which allocates
// per call: warm detect allocates nothing with the circle on.
#include <span>
#include <vector>

#include "fieldlines/detect/centre_circle.hpp"

#pragma GCC visibility push(hidden)

namespace fieldlines {

using ConicSample = CircleWorkspace::Point;

// A conic A u^2 + B uv + C v^2 + D u + E v + F = 0 in coordinates centred on (mx, my) and scaled
// by s (u = (x - mx) / s), and the ellipse it is.
struct Fit {
  double a = 0, b = 0, c = 0, d = 0, e = 0, f = 0;
  double mx = 0, my = 0, s = 1;
  MarkingEllipse ellipse;
  float theta = 0, semi_a = 0, semi_b = 0;  // radians, px
};

// The image point (x, y) in the fit's centred and scaled coordinates (u, v), and the conic's
// gradient (gu, gv) there.
struct ConicPoint {
  double u = 0, v = 0, gu = 0, gv = 0;
};
ConicPoint conic_point(const Fit& fit, float x, float y);

// Sampson's first-order distance of (x, y) from the conic, in px.
float distance(const Fit& fit, float x, float y);

// Whether at least half of `points` lie within `tolerance` px of the conic (a refit on the
// paint replaces the ellipse only then).
bool most_within(const Fit& fit, std::span<const ConicSample> points, float tolerance);

// The ellipse of the conic in `fit` (coefficients and frame set); false when it is none, or
// no circle's image (an axis under 4 px, more than 12:1).
bool to_ellipse(Fit& fit);

// Least squares over the points marked inlier; false when they make no ellipse. `aligned`
// leaves out the uv term (axes along the image's turned by `roll` radians): four unknowns,
// which two short pieces determine where the full conic's five need three.
bool fit_conic(const std::vector<ConicSample>& points, Fit& fit, bool aligned = false, float roll = 0);
// The conic's coefficients alone, whatever its kind (false: too few points, or degenerate); a
// hyperbola still ranks points by their distance from it.
bool solve_conic(const std::vector<ConicSample>& points, Fit& fit, bool aligned = false, float roll = 0);

}  // namespace fieldlines

#pragma GCC visibility pop
