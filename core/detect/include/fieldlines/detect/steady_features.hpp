#pragma once
// The junctions and the centre circle on the ground held steady over a stream of frames.
//
// A detector misses a feature on some frames of a stream (motion blur, a robot's leg in front,
// a line's edge a few grey levels short), and a localiser fed that flicker jumps between
// hypotheses. As B-Human keep a seen circle for a few frames, a feature seen within the last
// hold_ms stays in the output while it is not seen, moved by the robot's own motion since
// (odometry: the camera's foot moved and turned on the turf); seen again, its position is
// smoothed with its track (an exponential average), so it does not jitter by a pixel's worth of
// ground either. Segments and the field boundary are passed through as seen: they change with
// every step of the robot and a localiser takes them frame by frame.
//
// Optional and outside the detector (which keeps no state across frames): a robot that wants it
// keeps one SteadyFeatures per camera. No allocation once its tracks have grown to a stream's
// steady number.
#include <vector>

#include "fieldlines/detect/ground_features.hpp"

namespace fieldlines {

struct SteadyParams {
  double hold_ms = 80;          // a feature not seen for longer is dropped
  double match_m = 0.3;         // a junction seen this close to a track (same type) is that track
  double circle_match_m = 0.5;  // a circle this close to the circle's track is that circle
  double smoothing = 0.5;       // the new observation's weight in a track's position, (0, 1]
};
// Throws fieldlines::Error naming the value unless hold_ms >= 0, the distances are positive
// and the smoothing lies in (0, 1].
void validate(const SteadyParams& params);

// The robot's motion since the last frame, in the last frame's ground frame: the camera's foot
// moved by (dx, dy) metres and turned by dyaw radians (counter-clockwise, to the left).
struct GroundMotion {
  double dx = 0, dy = 0, dyaw = 0;
};

class SteadyFeatures {
 public:
  explicit SteadyFeatures(SteadyParams params = {});

  // This frame's features (`seen`, at `time_ms` on any clock that does not go back) after the
  // robot moved by `motion` since the last call: returns the steady features (valid until the
  // next call). A held feature's confidence falls linearly with its age to 0 at hold_ms.
  const GroundFeatures& update(const GroundFeatures& seen, double time_ms, const GroundMotion& motion = {});
  // Forget every track (a new stream, the robot picked up).
  void reset();
  const SteadyParams& params() const { return params_; }

 private:
  template <class Feature>
  struct Track {
    Feature feature;         // as last output (position smoothed), confidence as last seen
    double last_seen_ms = 0;
    bool matched = false;    // by this frame's observations
  };
  SteadyParams params_;
  std::vector<Track<GroundIntersection>> junctions_;
  std::vector<Track<GroundEllipse>> circles_;
  GroundFeatures out_;
  double last_ms_ = 0;
  bool started_ = false;
};

}  // namespace fieldlines
