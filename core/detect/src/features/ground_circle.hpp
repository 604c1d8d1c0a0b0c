#pragma once
// Private: the centre circle fitted on the turf when the camera is known (ground_camera.hpp).
//
// Seen from close by, the centre circle is a large image ellipse of which the frame shows one
// arc; an image conic's five unknowns are then barely determined by it (the far arc alone fits
// many ellipses). On the turf it is a circle of the rules' radius: each piece, a chord, puts its
// centre at one of two points, and the centre whose pieces cover most of its turn is the seed
// (a piece counts when its samples lie within a quarter of the radius of the circle, its chord
// along it, and its middle no deeper inside than a short chord's). The pose a robot knows is a
// little off (its pitch and roll by a degree or two, its height by some per cent), which bends
// the circle on the turf: the centre, the radius and the pitch and roll are refined together by
// Gauss-Newton, each pose angle held near the given one (2 degrees) and the radius near the
// rules' (a tenth), on the pieces' ends (on the curve; a chord's middle lies inside it) weighed
// in px; then the pieces within an eighth of the radius are its support, and it is refined
// again on them, and on the paint read across its image and followed round it (centre_circle.cpp). Its image
// ellipse is the circle's 36 points through the refined pose, fitted as a conic (conic_fit.hpp):
// exact, as the whole turn is known. A circle that passes behind the camera has no image ellipse.
// A pose off by a degree moves the centre of an ellipse far below the frame by a sixth of its
// radius, which the visible arc cannot correct: the fit's use is a camera known that well.
#include <span>

#include "conic_fit.hpp"
#include "fieldlines/detect/ground_camera.hpp"

#pragma GCC visibility push(hidden)

namespace fieldlines {

// The circle of `radius` m among `pieces` (stripe centre lines) seen through `camera`: the share
// of its turn on the turf that its pieces cover (0: none found), its image ellipse in `fit`,
// its pieces in work.ground_support.
float fit_on_ground(std::span<const Marking> pieces, const GroundCamera& camera, double radius, CircleWorkspace& work,
                    Fit& fit);

// After fit_on_ground() on the same camera: the circle and the pose refined again on `paint`
// (image points on the paint's centre line round the ellipse found), which replaces `fit`
// when most of them lie within `tolerance` px of the new ellipse (true then).
bool refit_on_ground(std::span<const CircleWorkspace::Point> paint, const GroundCamera& camera, double radius,
                     float tolerance, CircleWorkspace& work, Fit& fit);

}  // namespace fieldlines

#pragma GCC visibility pop
