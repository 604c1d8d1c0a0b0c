#pragma once
// The field features a synthetic frame shows, from its field and camera (the truth file's scene,
// line width, intrinsics and pose), and scores for detected features against them.
//
// Intersections: where two straight painted lines of the field meet (their centrelines cross
// within a line width of both), with one arm per side on which a line goes on. A junction is
// visible when its centre projects into the frame within 3 px (or a line width) of a visible
// painted line of the truth (robots hide some) where the paint is at least `min_width_px` wide
// (1 px); an arm is visible when it reaches 12 px from the centre inside the frame and its own
// line's paint is visible there, as wide as that. Its type is what is visible:
// 2 arms an L, 3 a T, 4 an X; fewer than 2 arms, or 2 nearly opposite, is no junction in the
// image. Headings as soccer_vision_2d_msgs: radians in [0, 2pi), 0 along +x, pi/2 image down,
// ascending. Junctions that do not meet these conditions, and the centre circle's crossings with
// the halfway line, are `ignored`.
//
// The centre circle: the image ellipse of the whole circle (when all of it is in front of the
// camera, cv::fitEllipse on 720 projected points of its centreline) and the share of it visible
// (inside the frame, within 2 px of the truth's visible "centre circle" polylines, where the paint
// is at least `min_width_px` wide).
//
// The field boundary: per image column, the first row from the top whose pixel centre sees the
// carpet (the green, run-off included) through the camera, objects left out: the outline a
// convex boundary around the field follows (field_boundary.hpp's hull bridges a robot in front on
// purpose). With the frame's label mask, a column whose top of carpet is hidden by an object (a
// robot, a goal) is left out too: the frame does not show where its green ends. A column left
// out, or showing no carpet, has -1.
//
// The markings (stripe centre lines, field_features.hpp): each pixel along a detected marking is
// on its line when it lies within half the true line's width + 1 px of the centreline of a
// visible painted line of the truth.
#include <array>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/synth/truth.hpp"

namespace fieldlines::synth {

struct TruthCircle {
  MarkingEllipse ellipse;   // confidence 1
  float visible_share = 0;  // of its centreline, in [0, 1]
};

struct FeatureTruth {
  std::vector<Intersection> intersections;  // confidence 1
  // Scored neither way (a detection within reach of one is no false positive, and it is not
  // needed for recall): hidden or thinner than 1 px, cut by the frame to one line, and the
  // centre circle's crossings with straight lines. Position only.
  std::vector<Intersection> ignored;
  std::optional<TruthCircle> circle;        // none when not all of it is in front of the camera
  std::vector<float> carpet_top;            // per column (the image's width): its row, or -1
};

// `mask`: the frame's label mask (render.hpp's MaskClass, CV_8UC1 of the frame's size) or empty.
// `min_width_px`: paint narrower than this is too thin to see (gt_eval.hpp's, for the segments).
FeatureTruth feature_truth(const GroundTruth& truth, const cv::Mat& mask = {}, float min_width_px = 1);
// The carpet_top rows alone.
std::vector<float> carpet_top_rows(const GroundTruth& truth, const cv::Mat& mask = {});

struct FeatureScoreParams {
  float max_distance_px = 6;          // a detected junction matches a true one this close
  float min_circle_share = 0.3f;      // circles at least this visible must be found...
  float max_centre_error = 0.1f;      // ...with the centre within this share of the radius
  float max_boundary_px = 4;          // a boundary column is right this close to the carpet's top
  float marking_margin_px = 1;        // a marking pixel is on its line within half its width + this
};

struct FeatureScore {
  long detected = 0, truth = 0, matched = 0, type_correct = 0;  // intersections
  long circles = 0, circles_found = 0;  // frames with a circle visible enough; found in those
  long ellipses = 0, ellipses_wrong = 0;  // detected; of those, matching no visible circle
  // Columns showing carpet; of those, where the detected boundary is within max_boundary_px of
  // it (none when the detector saw no field). Pixels along detected markings; on their line.
  long boundary_columns = 0, boundary_right = 0;
  long marking_px = 0, marking_on_line_px = 0;
  double precision() const { return detected > 0 ? double(matched) / detected : 0; }
  double recall() const { return truth > 0 ? double(matched) / truth : 0; }
  double type_accuracy() const { return matched > 0 ? double(type_correct) / matched : 0; }
  double circle_rate() const { return circles > 0 ? double(circles_found) / circles : 0; }
  double boundary_share() const { return boundary_columns > 0 ? double(boundary_right) / boundary_columns : 0; }
  double marking_share() const { return marking_px > 0 ? double(marking_on_line_px) / marking_px : 0; }
  FeatureScore& operator+=(const FeatureScore& o);
};

// Detected and true junctions paired (indices into detected.intersections, truth.intersections):
// every pair within max_distance_px, nearest first, each side used once.
std::vector<std::pair<std::size_t, std::size_t>> matched_junctions(const FeatureTruth& truth, const FieldFeatures& detected,
                                                                   const FeatureScoreParams& params = {});

// The circle's "radius" in the image is the geometric mean of the ellipse's semi-axes. Junctions
// match as matched_junctions() pairs them.
// The boundary counts on every column showing carpet: a detector that was not asked for it
// scores 0 there.
FeatureScore score_features(const FeatureTruth& truth, const FieldFeatures& detected,
                            const FeatureScoreParams& params = {});
// The same, and the markings scored against the frame's painted lines.
FeatureScore score_features(const GroundTruth& frame, const FeatureTruth& truth, const FieldFeatures& detected,
                            const FeatureScoreParams& params = {});

}  // namespace fieldlines::synth
