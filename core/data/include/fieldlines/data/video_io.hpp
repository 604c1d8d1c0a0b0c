#pragma once
// Video files for the CLI and the studio (not detect: the robot needs no videoio): which paths
// are videos, and opening one.
//
// FFmpeg reads nearly every file and stream; OpenCV's own MJPEG reader needs no codec library.
// Letting OpenCV probe every backend (GStreamer, Aravis...) only adds console noise and, on a
// file that is no video, leaks inside those libraries. Their failed attempts are silenced;
// the caller's error message says what matters.
#include <algorithm>
#include <array>
#include <filesystem>
#include <string>

#include <opencv2/core/utils/logger.hpp>
#include <opencv2/videoio.hpp>

#include "fieldlines/data/image_io.hpp"

namespace fieldlines {

// True for the file extensions treated as video (mp4, avi, mkv, mov, webm, m4v), case-insensitive.
inline bool has_video_extension(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  constexpr std::array kVideo{".mp4", ".avi", ".mkv", ".mov", ".webm", ".m4v"};
  return std::find(kVideo.begin(), kVideo.end(), ext) != kVideo.end();
}

inline bool open_video_file(cv::VideoCapture& capture, const std::string& path) {
  const auto level = cv::utils::logging::getLogLevel();
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  bool opened = false;
  for (const int backend : {cv::CAP_FFMPEG, cv::CAP_OPENCV_MJPEG})
    if ((opened = capture.open(path, backend))) break;
  cv::utils::logging::setLogLevel(level);
  return opened;
}

// Walks an open video: grabs every frame (cheap) and decodes only every `every`-th, the one
// rule the studio's video import and `fieldlines calibrate` share. Calls on_frame(index, frame)
// for every grabbed frame, with `frame` empty for the skipped ones (so a caller can report
// progress), until on_frame returns false, the video ends or a kept frame cannot be decoded.
template <typename OnFrame>
void for_each_nth_frame(cv::VideoCapture& capture, int every, OnFrame&& on_frame) {
  cv::Mat frame;
  cv::Mat skipped;  // stays empty
  for (long index = 0; capture.grab(); ++index) {
    const bool keep = index % every == 0;
    if (keep && (!capture.retrieve(frame) || frame.empty())) return;
    if (!on_frame(index, keep ? frame : skipped)) return;
  }
}

}  // namespace fieldlines
