#pragma once
// Opening a video file for the CLI and the studio (not core: the robot needs no videoio).
//
// FFmpeg reads nearly every file and stream; OpenCV's own MJPEG reader needs no codec library.
// Letting OpenCV probe every backend (GStreamer, Aravis...) only adds console noise and, on a
// file that is no video, leaks inside those libraries. Their failed attempts are silenced;
// the caller's error message says what matters.
#include <string>

#include <opencv2/core/utils/logger.hpp>
#include <opencv2/videoio.hpp>

namespace fieldlines::app {

inline bool open_video_file(cv::VideoCapture& capture, const std::string& path) {
  const auto level = cv::utils::logging::getLogLevel();
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  bool opened = false;
  for (const int backend : {cv::CAP_FFMPEG, cv::CAP_OPENCV_MJPEG})
    if ((opened = capture.open(path, backend))) break;
  cv::utils::logging::setLogLevel(level);
  return opened;
}

}  // namespace fieldlines::app
