#pragma once
// How far the detector's features lie from the truth on the ground (ground_features.hpp), for
// synthetic frames whose true camera is known: the figures a robot localising on them feels.
//
// Junctions: each pair matched in the image (feature_truth.hpp's matched_junctions), its
// detected centre through the camera the detector was given, its true centre through the true
// camera; the error as a share of the true distance (a robot's odometry and its localisation
// weigh near points more). The centre circle: in each frame whose circle is visible enough
// (FeatureScoreParams::min_circle_share) and whose centre lies within max_circle_distance_m,
// the detector's nearest ground circle's centre error in metres; a frame with no ground circle
// adds none (the circle rate counts it).
#include <vector>

#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/detect/ground_features.hpp"
#include "fieldlines/synth/feature_truth.hpp"

namespace fieldlines::synth {

struct GroundScore {
  std::vector<double> junction_error_share;  // per matched junction
  std::vector<double> junction_distance_m;   // its true distance, same order
  std::vector<double> circle_error_m;        // per frame with a near circle found on the ground
  long near_circles = 0;                     // frames with a circle visible enough within reach
  GroundScore& operator+=(const GroundScore& o);
};

struct GroundScoreParams {
  double max_circle_distance_m = 4;
};

// `given`: the camera the detector was given (it made `detected_ground`); `truth_camera`: the
// frame's own.
GroundScore score_ground(const FeatureTruth& truth, const FieldFeatures& detected, const GroundFeatures& detected_ground,
                         const GroundCamera& given, const GroundCamera& truth_camera,
                         const FeatureScoreParams& params = {}, const GroundScoreParams& ground = {});

}  // namespace fieldlines::synth
