#pragma once
// Turns a video into a folder of frames (every n-th) on a worker thread, so the studio can show a
// progress bar and then open the folder as a project.
#include <atomic>
#include <filesystem>
#include <string>
#include <thread>

namespace fieldlines::studio {

// True for the file extensions treated as video (mp4, avi, mkv, mov, webm, m4v), case-insensitive.
bool has_video_extension(const std::filesystem::path& path);

// <video folder>/<video stem>-every<N>: another --every gets its own folder (and labels) rather
// than silently reusing frames taken at a different rate.
std::filesystem::path frames_folder_for(const std::filesystem::path& video, int every);

struct VideoFramesParams {
  int every = 10;  // keep frame 0, every, 2*every, ...
};

class VideoFramesJob {
 public:
  VideoFramesJob() = default;
  ~VideoFramesJob();
  VideoFramesJob(const VideoFramesJob&) = delete;
  VideoFramesJob& operator=(const VideoFramesJob&) = delete;

  // Writes frame_000000.png ... into `folder` (created). A running job is cancelled first.
  void start(const std::filesystem::path& video, const std::filesystem::path& folder, const VideoFramesParams& params);
  void cancel();
  void wait();
  bool finished() const { return finished_.load(); }
  // In [0, 1]; frames read / frames in the file (when the container tells the count).
  float progress() const { return progress_.load(); }
  int written() const { return written_.load(); }
  // Set when finished with a failure (unreadable video, no frames, unwritable folder). Read it
  // only after finished() is true.
  const std::string& error() const { return error_; }

 private:
  std::jthread worker_;
  std::atomic<bool> finished_{false};
  std::atomic<float> progress_{0};
  std::atomic<int> written_{0};
  std::string error_;
};

}  // namespace fieldlines::studio
