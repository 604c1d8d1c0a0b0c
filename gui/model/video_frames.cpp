#include "gui/model/video_frames.hpp"

#include "fieldlines/data/video_io.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <exception>
#include <system_error>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::studio {

bool has_video_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  constexpr std::array kVideo{".mp4", ".avi", ".mkv", ".mov", ".webm", ".m4v"};
  return std::find(kVideo.begin(), kVideo.end(), ext) != kVideo.end();
}

std::filesystem::path frames_folder_for(const std::filesystem::path& video, int every) {
  return video.parent_path() / (video.stem().string() + "-every" + std::to_string(every));
}

VideoFramesJob::~VideoFramesJob() {
  if (worker_.joinable()) {
    worker_.request_stop();
    worker_.join();
  }
}

void VideoFramesJob::start(const std::filesystem::path& video, const std::filesystem::path& folder,
                           const VideoFramesParams& params) {
  if (worker_.joinable()) {
    worker_.request_stop();
    worker_.join();
  }
  finished_ = false;
  progress_ = 0;
  written_ = 0;
  error_.clear();
  worker_ = std::jthread([this, video, folder, params](std::stop_token stop) {
    try {
      if (params.every < 1) throw Error("video: every-n-th frame must be >= 1");
      cv::VideoCapture capture;
      if (!open_video_file(capture, video.string())) throw Error(video.string() + ": cannot open as a video");
      std::error_code ec;
      std::filesystem::create_directories(folder, ec);
      if (ec) throw Error(folder.string() + ": cannot create the frames folder (" + ec.message() + ")");
      const double total = capture.get(cv::CAP_PROP_FRAME_COUNT);
      cv::Mat frame;
      for (long index = 0; !stop.stop_requested() && capture.read(frame); ++index) {
        if (index % params.every == 0) {
          char name[32];
          std::snprintf(name, sizeof name, "frame_%06ld.png", index);
          const auto path = folder / name;
          if (!cv::imwrite(path.string(), frame)) throw Error(path.string() + ": cannot write the frame");
          ++written_;
        }
        if (total > 0) progress_ = static_cast<float>(std::min(1.0, static_cast<double>(index + 1) / total));
      }
      if (written_ == 0 && !stop.stop_requested()) throw Error(video.string() + ": no frame could be decoded");
      progress_ = 1;
    } catch (const std::exception& e) {
      error_ = e.what();
    }
    finished_ = true;  // publishes error_ (written before, read after finished() by the UI)
  });
}

void VideoFramesJob::cancel() {
  if (worker_.joinable()) worker_.request_stop();
}

void VideoFramesJob::wait() {
  if (worker_.joinable()) worker_.join();
}

}  // namespace fieldlines::studio
