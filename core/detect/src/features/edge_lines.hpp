#pragma once
// Lines painted along the field's edge. A touch or goal line often lies right at the turf's edge,
// the field's dark surround beyond it: far off, such a line is a pixel or two of paint between
// the dark and the turf. Its inner edge is too faint for a segment of its own, and the segment the
// detector does draw, at the surround's edge, has a dark-to-turf colour transition that no marking
// class takes. Its geometry says what it is: a segment along the field boundary whose profiles
// show, from its dark side into its bright one, the surround, then at once paint (brighter than
// the turf beyond it, out of the field colour or grey blended into it, no wider than a stripe may
// be at its row), then turf, is that line's outer edge (stripes.hpp, find_stripes).
#include "fieldlines/detect/detector_params.hpp"
#include "fieldlines/detect/segment.hpp"
#include "fieldlines/detect/stripes.hpp"

#include <opencv2/core/mat.hpp>

namespace fieldlines {

class FieldPixel;

// Whether `s` (8-bit BGR `bgr`) is the outer edge of a line along the field's edge: its bright
// side faces down the frame (the field lies below its edge) and more than half of its
// `stripe_samples` profiles show surround, paint and turf. Then `c` holds its direction, the
// normal towards the paint, and the paint's median centre offset (both ends) and width.
bool edge_line(const cv::Mat& bgr, const FieldPixel& pixel, const Segment& s, const DetectorParams& params,
               StripeWorkspace::Candidate& c);

}  // namespace fieldlines
