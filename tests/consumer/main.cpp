// Detects a painted line in a generated frame using only the installed fieldlines package.
#include <cstdio>

#include <fieldlines/detector.hpp>
#include <opencv2/imgproc.hpp>

int main() {
  cv::Mat frame(480, 640, CV_8UC3, cv::Scalar(50, 130, 40));
  cv::line(frame, {40, 300}, {600, 330}, cv::Scalar(235, 235, 235), 9, cv::LINE_AA);
  fieldlines::LineDetector detector;
  int markings = 0;
  for (const fieldlines::Segment& s : detector.detect(frame)) markings += s.label == fieldlines::Label::Marking;
  std::printf("consumer: %d marking segments\n", markings);
  return markings >= 1 ? 0 : 1;
}
