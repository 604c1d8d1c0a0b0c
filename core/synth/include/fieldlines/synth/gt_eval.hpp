#pragma once
// Scoring detected segments against synthetic ground truth (synth_truth.hpp).
//
// Truth "edges": a painted line gives its two edges (centreline +- width/2 across the image
// line); the SSL wall foot gives one. A segment point matches an edge when it lies within
// max_distance_px of it and the segment runs within max_angle_deg of it; a thin line's single
// centred segment thus matches both of its edges, a wide line needs one segment per edge.
//  - Truth label of a segment: Marking or Boundary when at least min_match of its length matches
//    that class's edges (the larger share wins), else None. Used by autolabel and for precision.
//  - Precision of a class: predicted segments of that class whose truth label agrees.
//  - Recall of a class: the share of its visible edge length (edges of parts at least
//    min_width_px wide; every wall foot) within max_distance_px of a segment predicted as that
//    class and parallel to it.
#include <array>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "fieldlines/detect/segment.hpp"
#include "fieldlines/synth/truth.hpp"

namespace fieldlines {

struct GtMatchParams {
  float max_distance_px = 2.5f;  // a segment point counts when this close to a truth edge
  float max_angle_deg = 10;      // and the segment this parallel to it
  float min_match = 0.6f;        // share of a segment's length needed for a truth label
  float min_width_px = 1.0f;     // thinner painted parts are too faint to count in recall
};
void validate(const GtMatchParams& params);  // throws fieldlines::Error naming the field

// Per predicted class: how many segments, how many of those the truth agrees with.
struct GtClassScore {
  long predicted = 0, correct = 0;
  double visible_px = 0, covered_px = 0;  // recall: edge length visible / covered
  double precision() const { return predicted > 0 ? static_cast<double>(correct) / predicted : 0.0; }
  double recall() const { return visible_px > 0 ? covered_px / visible_px : 0.0; }
  GtClassScore& operator+=(const GtClassScore& o);
};

struct GtScore {
  GtClassScore marking, boundary;
  long none_predicted = 0, none_correct = 0;  // predicted none and truly none
  int images = 0;
  GtScore& operator+=(const GtScore& o);
};

// Truth edges of one image, prepared once for many queries.
class GtEdges {
 public:
  GtEdges(const synth::GroundTruth& truth, const GtMatchParams& params = {});
  // Marking, Boundary or None for one segment (its own label is ignored).
  Label truth_label(const Segment& segment) const;
  // Scores `detected` (labels = the classifier's predictions) against the truth.
  GtScore score(std::span<const Segment> detected) const;

  struct Edge {
    Label label;
    float ax, ay, bx, by;   // one straight piece of an edge polyline
    bool visible;           // counts towards recall
  };
  const std::vector<Edge>& edges() const { return edges_; }

  // How a point of a visible truth edge is seen by the detected segments: Found when a segment
  // predicted as the edge's class, and truly of it, lies within max_distance_px and parallel
  // (what recall counts); OnSegment when only segments of another label or truth do (the
  // detector drew it, the classification lost it); Missed when no segment does.
  enum class Seen { Found, OnSegment, Missed };
  using EdgePointVisitor = std::function<void(const Edge& edge, float x, float y, float step, Seen seen)>;
  // Visits points along every visible edge, `step` px of it each (`detected`'s labels are the
  // classifier's predictions): what `fieldlines eval --draw` paints.
  void walk(std::span<const Segment> detected, const EdgePointVisitor& visit) const;

 private:
  // walk() with the segments' truth labels already known (score() has them).
  void walk(std::span<const Segment> detected, std::span<const Label> truths, const EdgePointVisitor& visit) const;
  GtMatchParams params_;
  std::vector<Edge> edges_;
};

// Labels each segment in place from the truth (autolabel); returns counts per label
// (index: 0 none, 1 boundary, 2 marking).
std::array<long, 3> label_from_truth(std::span<Segment> segments, const synth::GroundTruth& truth,
                                     const GtMatchParams& params = {});

}  // namespace fieldlines
