#pragma once
// A standing robot's camera pitch and roll (and height) fitted from the painted lines it sees.
//
// On the turf a field's lines are all parallel or perpendicular. Projected onto the ground with
// the right pitch and roll (ground_camera.hpp) they are so too; with a wrong pose the ground
// directions of lines far apart in the image fan out. So, per frame, the lines' ground headings
// theta_i (weights w_i: how well each is known) give the frame's field heading
// theta0 = atan2(sum w sin 4theta, sum w cos 4theta) / 4
// (the factor 4 folds the four directions a field's lines take onto one; the frame's unknown yaw
// drops out), and each line's residual is its angle to the nearest of theta0 + k * 90 degrees.
// The pitch and roll that minimise the residuals of all frames together are the fit: a coarse
// grid around the start, then Nelder-Mead, under a robust (bounded) loss so that the few
// detections that are not straight field lines (chords of the centre circle, a robot's white
// bar) do not pull. The focal lengths' scale is fitted with the pose, under a prior (focal_sd):
// a focal length a little off bends the lines far from the image centre, which a pose alone
// would take up in the pitch. The height does not change a direction: it scales every ground distance, so
// the painted width, when known, gives it (the median ground width of the stripes, measured
// across each at its middle, against the width the rules paint).
//
// Pure geometry on image lines (no image I/O): `fieldlines calibrate-camera` detects the frames.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/detect/ground_camera.hpp"

namespace fieldlines {

// One frame of the camera: the detector's stripes (features().markings, image px) and the
// image size (to tell whether the camera sees any ground at all).
struct FrameLines {
  std::vector<Marking> markings;
  int width = 0, height = 0;
  std::string name;  // in messages; "frame <index>" when empty
};

struct CameraFitParams {
  double search_deg = 8;          // pitch and roll searched within +-search_deg of the start
  double grid_step_deg = 0.5;     // the coarse grid's step before Nelder-Mead
  double max_distance_m = 12;     // a line with an end farther than this on the ground is skipped
  // A line's residual counts in its sd: how far its ground heading turns when its image ends
  // move by end_noise_px across it (a long line near the camera is known better than a short
  // one far off), and at least min_sd_deg. A line with a larger sd than max_sd_deg (a short
  // piece near the horizon) tells nothing and is skipped.
  double end_noise_px = 1;
  double min_sd_deg = 0.2;
  double max_sd_deg = 3;
  double loss_scale_sd = 3;       // the robust loss's scale: residuals beyond it count less
  double min_length_px = 10;      // shorter image lines are skipped (their direction is noise)
  // The reported RMS (degrees, every line alike) leaves out this share of the lines that stray
  // most: detections that are no straight field lines (a centre circle in view adds as many
  // chords as there are lines).
  double trim_fraction = 0.5;
  // After the fit, an RMS above max_rms_deg or a fitting share (below) under min_fitting_share:
  // the frames contradict each other.
  double max_rms_deg = 3;
  double min_fitting_share = 0.8;
  // The fitted pitch's and roll's sd (from the lines' sds and how their residuals change with
  // the pose) above this: the lines do not pin the pose down, refused. The sd is that for 1 px
  // on the lines' ends, and the detector's ends stray by less: measured, the errors stay within
  // about 0.6 of it, so 0.5 keeps a fitted pose within about 0.3 degrees.
  double max_pose_sd_deg = 0.5;
  // Frames of two usable lines or more needed: the few lines of one or two frames can be
  // squared by poses far apart (a wrong pose with a small sd).
  int min_frames = 3;
  double min_direction_deg = 10;  // two image lines this far apart make two directions
  std::optional<double> line_width_m;  // the painted width: the height from the stripes' widths
  double min_width_px = 3;        // thinner stripes have no say in the height (blur, pixels)
  // How far off the start's focal lengths may be, as a share (its sd): the fit scales fx and fy
  // too, with this prior. A focal length 2 % off bends the ground directions of lines far from
  // the image centre, and a pose alone squares them with the pitch some 0.2 degrees off; the
  // lines of frames that show both field directions tell the scale. 0: the focal lengths kept.
  double focal_sd = 0.02;
};

// Throws fieldlines::Error naming the value when a parameter is out of range (not finite,
// search_deg outside (0, 45], a line width outside (0, 0.5] m, ...).
void validate(const CameraFitParams& params);

struct CameraFit {
  GroundCamera camera;            // the start's principal point with the fitted focal, pitch, roll, height
  double rms_before_deg = 0;      // RMS of the residuals at the start pose (trim_fraction left out)
  double rms_after_deg = 0;       // the same at the fitted pose
  int frames_used = 0;            // frames with at least two usable lines
  int lines_used = 0;             // usable lines of those frames at the fitted pose
  // The share of the lines' weight (1 / sd^2) within loss_scale_sd of their sd at the fitted
  // pose: all lines, and per frame (NaN for a frame not used).
  double fitting_share = 0;
  std::vector<double> frame_fitting_share;
  double pitch_sd_deg = 0, roll_sd_deg = 0;  // the fit's uncertainty for 1 px of noise on the ends
  double focal_scale = 1;         // the fitted fx and fy over the start's (1 when focal_sd is 0)
  bool height_fitted = false;     // true: from line_width_m; false: the start's height kept
  double median_width_m = 0;      // the stripes' median ground width at the start height (0: none)
  int widths_used = 0;            // stripes that measured it
};

// Throws fieldlines::Error with a message for the user when the start camera fails validate(),
// sees no ground in any frame (its horizon below the whole image), the frames hold no line or
// too few (fewer than two lines in two directions in frames of two lines or more, fewer than
// min_frames such frames), all lines
// lie above the start camera's horizon or too far, the fit leaves the lines straying by more
// than max_rms_deg or with less than min_fitting_share fitting (frames that disagree: it names
// the worst), the lines do not pin the pose down (max_pose_sd_deg), or the height is asked for and
// no stripe measures a width.
CameraFit fit_camera(std::span<const FrameLines> frames, const GroundCamera& start, const CameraFitParams& params = {});

}  // namespace fieldlines
