#include "gui/model/video_frames.hpp"

#include "fieldlines/data/video_io.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <exception>
#include <system_error>
#include <utility>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::studio {

std::filesystem::path frames_folder_for(const std::filesystem::path& video, int every) {
  return video.parent_path() / (video.stem().string() + "-every" + std::to_string(every));
}

void VideoFramesJob::start(const std::filesystem::path& video, const std::filesystem::path& folder,
                           const VideoFramesParams& params) {
  latest_ = {};
  job_.start([video, folder, params](std::stop_token stop, const auto& report) {
    if (params.every < 1) throw Error("video: every-n-th frame must be >= 1");
    cv::VideoCapture capture;
    if (!open_video_file(capture, video.string())) throw Error(video.string() + ": cannot open as a video");
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw Error(folder.string() + ": cannot create the frames folder (" + ec.message() + ")");
    const double total = capture.get(cv::CAP_PROP_FRAME_COUNT);
    VideoFramesProgress progress;
    for_each_nth_frame(capture, params.every, [&](long index, const cv::Mat& frame) {
      if (!frame.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%06ld.png", index);
        const auto path = folder / name;
        if (!cv::imwrite(path.string(), frame)) throw Error(path.string() + ": cannot write the frame");
        ++progress.written;
      }
      const float fraction = total > 0 ? static_cast<float>(std::min(1.0, static_cast<double>(index + 1) / total)) : 0;
      // A message per written frame or per percent, not per decoded frame.
      if (!frame.empty() || fraction - progress.fraction >= 0.01f) {
        progress.fraction = fraction;
        report(progress);
      }
      return !stop.stop_requested();
    });
    if (progress.written == 0 && !stop.stop_requested()) throw Error(video.string() + ": no frame could be decoded");
    if (!stop.stop_requested()) progress.fraction = 1;
    report(progress);
    return progress.written;
  });
}

void VideoFramesJob::poll() {
  for (const VideoFramesProgress& p : job_.poll()) latest_ = p;
}

VideoImport::VideoImport(std::filesystem::path video, int every)
    : video_(std::move(video)), folder_(frames_folder_for(video_, every)), every_(every),
      done_(std::filesystem::exists(folder_)) {
  if (!done_) job_.start(video_, folder_, {every_});
}

VideoImport::~VideoImport() {
  if (done_ || !job_.running()) return;
  job_.cancel();
  job_.wait();
  std::error_code ec;
  std::filesystem::remove_all(folder_, ec);
}

void VideoImport::poll() {
  if (done_) return;
  job_.poll();
  const auto& outcome = job_.outcome();
  if (!outcome) return;
  if (!outcome->ok()) {
    std::error_code ec;
    std::filesystem::remove_all(folder_, ec);
    throw Error(outcome->error());
  }
  done_ = true;
}

}  // namespace fieldlines::studio
