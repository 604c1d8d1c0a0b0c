#pragma once
// The robot camera's pose as a person nudges it in the Camera tab: by its -/+ buttons, or a
// step per key press (shortcuts.hpp: Up / Down pitch, Ctrl+Left / Ctrl+Right roll, Page Up /
// Page Down height). Window-free; camera_tuning.hpp turns a pose into a camera and back.
namespace fieldlines::studio {

struct CameraPose {
  double pitch_deg = 0, roll_deg = 0, height_cm = 0;
};
// One click of the tab's -/+ buttons (and with Ctrl held): fine enough to square lines 10 m
// away, whose ground heading a 0.05 degree pitch turns by a few tenths of a degree.
inline constexpr double kAngleStepDeg = 0.05, kAngleFastStepDeg = 1;
inline constexpr double kHeightStepCm = 0.5, kHeightFastStepCm = 5;

enum class CameraAxis { None, Pitch, Roll, Height };
struct CameraNudge {
  CameraAxis axis = CameraAxis::None;
  int direction = 0;  // +1: pitch down (the view sinks), roll clockwise on screen, higher; -1 back
};

// `pose` moved one step (kAngleStepDeg or kHeightStepCm) along the nudge; unclamped (with_pose
// clamps).
constexpr CameraPose nudged(CameraPose pose, CameraNudge nudge) {
  switch (nudge.axis) {
    case CameraAxis::Pitch: pose.pitch_deg += nudge.direction * kAngleStepDeg; break;
    case CameraAxis::Roll: pose.roll_deg += nudge.direction * kAngleStepDeg; break;
    case CameraAxis::Height: pose.height_cm += nudge.direction * kHeightStepCm; break;
    case CameraAxis::None: break;
  }
  return pose;
}

}  // namespace fieldlines::studio
