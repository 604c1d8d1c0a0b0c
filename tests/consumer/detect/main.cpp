// The README's robot example against the installed package only: load a thresholds file,
// detect on a frame, read marking and boundary segments.
#include <cstdio>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include <opencv2/imgproc.hpp>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer THRESHOLDS.json\n");
    return 2;
  }
  const fieldlines::ThresholdsFile config = fieldlines::load_thresholds_file(argv[1]);
  fieldlines::LineDetector detector(config.detector, config.thresholds);
  cv::Mat frame(480, 640, CV_8UC3, cv::Scalar(50, 130, 40));
  cv::line(frame, {40, 300}, {600, 330}, cv::Scalar(235, 235, 235), 9, cv::LINE_AA);
  std::vector<fieldlines::Segment> segments;
  detector.detect(frame, segments);
  int markings = 0;
  for (const fieldlines::Segment& s : segments) markings += s.label == fieldlines::Label::Marking;
  std::printf("consumer: %d marking segments\n", markings);
  return markings >= 1 ? 0 : 1;
}
