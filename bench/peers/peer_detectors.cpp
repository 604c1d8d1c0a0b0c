#include "bench/peers/peer_detectors.hpp"

#include <memory>

#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/edge_drawing.hpp>
#include <opencv2/ximgproc/fast_line_detector.hpp>

namespace fieldlines::peers {
namespace {

// Buffers shared by the OpenCV peers: reused so no peer pays for allocation we do not.
struct GreyLines {
  cv::Mat grey;
  std::vector<cv::Vec4f> lines;
};

}  // namespace

std::vector<TimedDetector> make_timed_detectors(const DetectorParams& params, const Thresholds& thresholds) {
  std::vector<TimedDetector> out;

  auto segments = std::make_shared<std::vector<Segment>>();
  // One of our rows: `detector` into the shared segment buffer.
  const auto ours = [&](const char* name, const char* what, std::shared_ptr<LineDetector> detector) {
    out.push_back({name, what, [detector, segments](const cv::Mat& bgr) {
                     detector->detect(bgr, *segments);
                     return segments->size();
                   }});
  };
  ours("fieldlines", "fieldlines LineDetector: ELSED + colour gradients + classification",
       std::make_shared<LineDetector>(params, thresholds));

  // The robot's per-frame light adaptation on (light.hpp): what it adds to a detect.
  Thresholds adapted = thresholds;
  adapted.light = {true, {60, 130, 60}};
  ours("fieldlines+light", "the same with per-frame light adaptation (field colour, one gain)",
       std::make_shared<LineDetector>(params, adapted));

  // The stripes stage on (stripes.hpp): what checking every marking across its width adds.
  DetectorParams striped = params;
  striped.stripes = true;
  ours("fieldlines+stripes", "the same with the stripes stage (profiles across every marking)",
       std::make_shared<LineDetector>(striped, thresholds));

  // The coarse pass (DetectorParams::coarse_scale) as calibration chooses it where near lines
  // break up (DetectorCalibrationParams: the lower 0.7 drawn again at a third of the size, the
  // upper 0.2 of it keeping the lines it resolves).
  DetectorParams coarse = params;
  coarse.coarse_scale = 3;
  coarse.coarse_from = 0.5;
  coarse.coarse_twins_from = 0.3;
  ours("fieldlines+coarse", "the same with the coarse pass (the lower 0.7 again at a third of the size)",
       std::make_shared<LineDetector>(coarse, thresholds));

  // The thin-line pass (DetectorParams::thin_reach) as calibration turns it on: the upper 0.6
  // of the frame drawn again on the ridge of lines up to 3 px wide; and both passes together,
  // what a venue with wide near lines runs.
  DetectorParams thin = params;
  thin.thin_reach = 2;
  thin.thin_to = 0.6;
  ours("fieldlines+thin", "the same with the thin-line pass (the upper 0.6 again on lines' ridges)",
       std::make_shared<LineDetector>(thin, thresholds));
  DetectorParams scales = coarse;
  scales.thin_reach = thin.thin_reach;
  scales.thin_to = thin.thin_to;
  ours("fieldlines+scales", "the same with both: the coarse pass and the thin-line pass",
       std::make_shared<LineDetector>(scales, thresholds));

  // The stripes, the field boundary and the junctions, not the centre circle: the field features
  // from the detector's own drawing (the circle draws the frame a second time).
  DetectorParams lines = with_every_feature(params);
  lines.centre_circle = false;
  auto ours_junctions = std::make_shared<LineDetector>(lines, thresholds);
  ours_junctions->set_find_field_boundary(true);
  ours("fieldlines+junctions", "the same with the stripes, field boundary and junctions (no circle)", ours_junctions);

  // Every field feature on (field_features.hpp): stripes, junctions, centre circle, boundary.
  auto ours_features = std::make_shared<LineDetector>(with_every_feature(params), thresholds);
  ours_features->set_find_field_boundary(true);
  ours("fieldlines+features", "the same with every field feature (stripes, junctions, circle, boundary)",
       ours_features);

  // The same with a camera (ground_features.hpp): the circle also fitted on the turf, the
  // junctions checked square on it, every feature projected onto it. A robot's head camera for
  // the frame's size (a 60-degree view, 30 degrees down, 0.6 m up): the cost does not depend on
  // the pose being the true one.
  auto ours_ground = std::make_shared<LineDetector>(with_every_feature(params), thresholds);
  ours_ground->set_find_field_boundary(true);
  out.push_back({"fieldlines+ground", "the same with a camera: every feature also on the ground",
                 [ours_ground, segments](const cv::Mat& bgr) {
                   GroundCamera camera;
                   camera.fx = camera.fy = bgr.cols;
                   camera.cx = 0.5 * (bgr.cols - 1), camera.cy = 0.5 * (bgr.rows - 1);
                   camera.pitch_rad = 0.5236, camera.height_m = 0.6;
                   ours_ground->set_camera(camera);
                   ours_ground->detect(bgr, *segments);
                   return segments->size();
                 }});

  auto ed = cv::ximgproc::createEdgeDrawing();
  auto ed_state = std::make_shared<GreyLines>();
  out.push_back({"edlines", "OpenCV ximgproc EdgeDrawing, EDLines (detectEdges + detectLines)",
                 [ed, ed_state](const cv::Mat& bgr) {
                   cv::cvtColor(bgr, ed_state->grey, cv::COLOR_BGR2GRAY);
                   ed->detectEdges(ed_state->grey);
                   ed->detectLines(ed_state->lines);
                   return ed_state->lines.size();
                 }});

  auto fld = cv::ximgproc::createFastLineDetector();
  auto fld_state = std::make_shared<GreyLines>();
  out.push_back({"fld", "OpenCV ximgproc FastLineDetector", [fld, fld_state](const cv::Mat& bgr) {
                   cv::cvtColor(bgr, fld_state->grey, cv::COLOR_BGR2GRAY);
                   // OpenCV 4.6's FLD asserts (cv::Exception) on images with a side under 6 px;
                   // such a frame has no lines for any detector, so report none.
                   if (bgr.cols < 6 || bgr.rows < 6) {
                     fld_state->lines.clear();
                     return std::size_t{0};
                   }
                   fld->detect(fld_state->grey, fld_state->lines);
                   return fld_state->lines.size();
                 }});

  auto lsd = cv::createLineSegmentDetector();
  auto lsd_state = std::make_shared<GreyLines>();
  out.push_back({"lsd", "OpenCV LineSegmentDetector (LSD)", [lsd, lsd_state](const cv::Mat& bgr) {
                   cv::cvtColor(bgr, lsd_state->grey, cv::COLOR_BGR2GRAY);
                   lsd->detect(lsd_state->grey, lsd_state->lines);
                   return lsd_state->lines.size();
                 }});

  // Our first stage alone (the fused grey + Gaussian + Sobel + magnitude + direction pass), so
  // the bench shows what the drawing, validation and classification add on top of it.
  auto gradients = std::make_shared<LineDetector>(params, thresholds);
  out.push_back({"gradients", "fieldlines gradients only: fused grey, Gaussian, Sobel x/y, |dx|+|dy|, direction",
                 [gradients](const cv::Mat& bgr) {
                   gradients->compute_gradients(bgr);
                   return std::size_t{0};
                 }});

  struct Floor {
    cv::Mat grey, blurred, gx, gy;
  };
  auto floor = std::make_shared<Floor>();
  out.push_back({"floor", "cvtColor + 5x5 Gaussian + Sobel x and y (no segments)", [floor](const cv::Mat& bgr) {
                   cv::cvtColor(bgr, floor->grey, cv::COLOR_BGR2GRAY);
                   cv::GaussianBlur(floor->grey, floor->blurred, {5, 5}, 0);
                   cv::Sobel(floor->blurred, floor->gx, CV_16S, 1, 0);
                   cv::Sobel(floor->blurred, floor->gy, CV_16S, 0, 1);
                   return std::size_t{0};
                 }});
  return out;
}

}  // namespace fieldlines::peers
