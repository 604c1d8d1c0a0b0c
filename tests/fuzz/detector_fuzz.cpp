// Fuzzes LineDetector::detect, with and without the field feature stages, with small images of any size, channel count and depth.
// Layout of the input: width, height, type selector, then pixel bytes (repeated to fill).
#include <cstddef>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <vector>

#include <opencv2/core.hpp>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  const int width = 1 + data[0] % 96, height = 1 + data[1] % 96;
  static const int kTypes[] = {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4, CV_8UC2, CV_32FC3};
  const int type = kTypes[data[2] % 8];
  cv::Mat image(height, width, type);
  const std::uint8_t* pixels = data + 3;
  const std::size_t n = size - 3;
  auto* dst = image.ptr<std::uint8_t>();
  const std::size_t bytes = image.total() * image.elemSize();
  for (std::size_t i = 0; i < bytes; ++i) dst[i] = pixels[i % n];
  if (image.depth() == CV_32F) cv::patchNaNs(image, 0.0);
  static fieldlines::LineDetector detector;  // reused across inputs, as a robot would
  try {
    const std::vector<fieldlines::Segment> segments = detector.detect(image);
    // A detector that has seen other images must give what a fresh one gives: no state may
    // leak from one call into the next (a stale-buffer bug was found this way).
    const std::vector<fieldlines::Segment> fresh = fieldlines::LineDetector().detect(image);
    if (fresh.size() != segments.size()) __builtin_trap();
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const fieldlines::Segment& s = segments[i];
      // Every output must be finite.
      if (!std::isfinite(s.x0) || !std::isfinite(s.y0) || !std::isfinite(s.x1) || !std::isfinite(s.y1) ||
          !std::isfinite(s.saliency) || !std::isfinite(s.grad_x[0]) || !std::isfinite(s.grad_y[0]))
        __builtin_trap();
      if (std::memcmp(&s.x0, &fresh[i].x0, sizeof(float)) != 0 || s.saliency != fresh[i].saliency) __builtin_trap();
    }
    // Every feature stage (stripes, intersections, centre circle) on the same frame, with the
    // gradient threshold following the frame's field (dark_field above any field): finite
    // markings of positive width no wider than the frame is high, sane junctions and ellipses,
    // and no state leaking between calls either (the threshold changes from frame to frame).
    static const fieldlines::DetectorParams kStripes = [] {
      fieldlines::DetectorParams p;
      p.stripes = p.intersections = p.centre_circle = true;
      p.dark_field = 765;
      return p;
    }();
    static fieldlines::LineDetector striped(kStripes);
    const std::vector<fieldlines::Segment> labelled = striped.detect(image);
    const std::vector<fieldlines::Marking> markings = striped.features().markings;
    fieldlines::LineDetector fresh_striped(kStripes);
    const std::vector<fieldlines::Segment> fresh_labelled = fresh_striped.detect(image);
    if (labelled.size() != fresh_labelled.size() || markings.size() != fresh_striped.features().markings.size())
      __builtin_trap();
    for (std::size_t i = 0; i < labelled.size(); ++i)
      if (labelled[i].label != fresh_labelled[i].label) __builtin_trap();
    for (const fieldlines::Marking& m : markings)
      if (!std::isfinite(m.x0) || !std::isfinite(m.y0) || !std::isfinite(m.x1) || !std::isfinite(m.y1) ||
          !(m.width > 0) || m.width > float(image.rows))
        __builtin_trap();
    const fieldlines::FieldFeatures& f = striped.features();
    if (f.intersections.size() != fresh_striped.features().intersections.size() ||
        f.ellipses.size() != fresh_striped.features().ellipses.size() || f.ellipses.size() > 1)
      __builtin_trap();
    const auto check_junctions = [](const std::vector<fieldlines::Intersection>& junctions) {
      for (const fieldlines::Intersection& j : junctions) {
        if (!std::isfinite(j.x) || !std::isfinite(j.y) || j.num_rays < 2 || j.num_rays > 4 || !(j.confidence >= 0) ||
            j.confidence > 1)
          __builtin_trap();
        for (int k = 0; k < j.num_rays; ++k)
          if (!(j.heading_rays[k] >= 0) || !(j.heading_rays[k] < 6.2832f) ||
              (k > 0 && j.heading_rays[k] < j.heading_rays[k - 1]))
            __builtin_trap();
      }
    };
    check_junctions(f.intersections);
    // The junctions without the circle: the detector's own straight stripes, no second drawing.
    static const fieldlines::DetectorParams kLines = [] {
      fieldlines::DetectorParams p = kStripes;
      p.centre_circle = false;
      return p;
    }();
    static fieldlines::LineDetector lines(kLines);
    lines.detect(image);
    if (!lines.features().ellipses.empty()) __builtin_trap();
    check_junctions(lines.features().intersections);
    const auto check_ellipses = [](const std::vector<fieldlines::MarkingEllipse>& ellipses) {
      if (ellipses.size() > 1) __builtin_trap();
      for (const fieldlines::MarkingEllipse& e : ellipses)
        if (!std::isfinite(e.cx) || !std::isfinite(e.cy) || !(e.width > 0) || !(e.height > 0) ||
            !std::isfinite(e.width) || !std::isfinite(e.height) || !std::isfinite(e.angle_deg) ||
            !(e.confidence > 0) || e.confidence > 1)
          __builtin_trap();
    };
    check_ellipses(f.ellipses);
    // The camera known (the circle also fitted on the turf), a pose drawn from the input's first
    // bytes, changed per frame as a walking robot's: sane ellipses, and the same as a fresh
    // detector's with that camera.
    const fieldlines::GroundCamera camera{.fx = 50.0 + 4 * data[0], .fy = 50.0 + 4 * data[1],
                                          .cx = 0.5 * width, .cy = 0.5 * height,
                                          .pitch_rad = (5 + data[2] % 55) * 0.01745, .roll_rad = ((data[3] % 21) - 10) * 0.01745,
                                          .height_m = 0.2 + 0.01 * data[3]};
    static fieldlines::LineDetector with_camera(kStripes);
    with_camera.set_camera(camera);
    with_camera.detect(image);
    fieldlines::LineDetector fresh_camera(kStripes);
    fresh_camera.set_camera(camera);
    fresh_camera.detect(image);
    check_ellipses(with_camera.features().ellipses);
    if (with_camera.features().ellipses.size() != fresh_camera.features().ellipses.size()) __builtin_trap();
  } catch (const fieldlines::Error&) {
    // Unsupported types are reported, not crashed on.
  }
  return 0;
}
