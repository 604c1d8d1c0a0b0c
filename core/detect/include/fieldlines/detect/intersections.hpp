#pragma once
// L, T and X junctions of painted lines, from stripe centre lines (stripes.hpp). LineDetector
// passes its own segments that are straight stripes (Shape::Straight: a chord of the centre
// circle bows) and, when the centre circle is on, the pieces of its second drawing, which may be
// shorter than the detector's minimum length (DetectorParams::piece_length: a line running into
// a crossing stops short of it), less those on the circle (centre_circle.hpp), whose chords bend
// into each other and cross the halfway line.
//
// Two centre lines at more than `intersection_min_angle` degrees to each other meet where their
// infinite lines cross, when that point lies on both or within a reach of one of their ends:
// `intersection_reach` times the narrower line's width plus 4 px (a line's edges stop short of the
// paint they run into, by about half the other line's width and the edge detector's blur; a
// field's lines share one width, and the narrower estimate is the one a blurred or merged edge
// has not widened). Each line gives the junction one ray per side of the crossing on which it
// extends by more than that reach: a line ending at the crossing gives one ray, a line passing
// through gives two. Pairs whose crossings lie within that reach of each other are one junction
// (a line broken at a crossing, several lines of one corner); their rays merge when within 25
// degrees, or 10 when both are longer than three reaches (a far corner in perspective is that
// acute; a short stub beside an arm is the same line's end or a curve's next chord). A junction
// keeps its (at most four) longest rays: 2 are an L, 3 a T, 4 an X; two rays nearly opposite
// (more than 150 degrees apart, nothing else) are a straight line, not a junction.
// Buffers are the caller's: no allocation once warm.
#include <array>
#include <span>
#include <vector>

#include <opencv2/core/types.hpp>

#include "fieldlines/detect/detector_params.hpp"
#include "fieldlines/detect/field_features.hpp"

namespace fieldlines {

// Scratch reused between frames; its contents mean nothing to a caller.
struct IntersectionWorkspace {
  struct Ray {
    float ux = 0, uy = 0;  // unit heading, weighted sum while merging
    float length = 0;      // px from the junction to the arm's far end
  };
  struct Junction {
    float x = 0, y = 0, weight = 0;  // weighted mean of the pair crossings
    float reach = 0;                 // px
    int num_rays = 0;
    std::array<Ray, 8> rays{};
  };
  std::vector<Junction> junctions;
};

// Writes the junctions of `markings` into `out` (cleared first). With a non-empty `frame`, a
// junction whose centre lies outside it (lines that would meet out of view) is dropped.
void find_intersections(std::span<const Marking> markings, const DetectorParams& params,
                        IntersectionWorkspace& work, std::vector<Intersection>& out, cv::Size frame = {});

}  // namespace fieldlines
