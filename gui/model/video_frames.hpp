#pragma once
// Turns a video into a folder of frames (every n-th) in the background, so the studio can show a
// progress bar and then open the folder as a project.
#include <filesystem>
#include <optional>

#include "fieldlines/data/video_io.hpp"
#include "gui/model/job.hpp"

namespace fieldlines::studio {

// Which files are videos: the one rule of fieldlines/data/video_io.hpp, shared with the CLI.
using fieldlines::has_video_extension;

// <video folder>/<video stem>-every<N>: another --every gets its own folder (and labels) rather
// than silently reusing frames taken at a different rate.
std::filesystem::path frames_folder_for(const std::filesystem::path& video, int every);

struct VideoFramesParams {
  int every = 10;  // keep frame 0, every, 2*every, ...
};

struct VideoFramesProgress {
  float fraction = 0;  // in [0, 1]: frames read / frames in the file (when the container says)
  int written = 0;
};

// The background Job (gui/model/job.hpp) that writes the frames.
class VideoFramesJob {
 public:
  // Writes frame_000000.png ... into `folder` (created). A running job is cancelled first.
  void start(const std::filesystem::path& video, const std::filesystem::path& folder, const VideoFramesParams& params);
  void cancel() { job_.cancel(); }
  bool running() const { return job_.running(); }
  void poll();  // UI thread, once per frame
  void wait() {  // blocks until the worker has finished and everything is polled
    job_.wait();
    poll();
  }
  bool finished() const { return job_.outcome().has_value(); }
  float progress() const { return latest_.fraction; }
  int written() const { return latest_.written; }
  // The frames written (also when cancelled), or why it failed: unreadable video, no frames,
  // unwritable folder.
  const std::optional<Outcome<int>>& outcome() const { return job_.outcome(); }

 private:
  VideoFramesProgress latest_;
  Job<VideoFramesProgress, int> job_;
};

// A video given on the command line, turned into its frames folder while the main loop shows the
// progress as part of its normal frame; then the folder opens as a project. An existing folder is
// reused as it is, so a failed or stopped extraction must never leave one behind.
class VideoImport {
 public:
  VideoImport(std::filesystem::path video, int every);  // starts, unless the folder exists
  ~VideoImport();  // an unfinished extraction is stopped and its half-written folder removed
  VideoImport(const VideoImport&) = delete;
  VideoImport& operator=(const VideoImport&) = delete;

  // UI thread, once per frame. Throws fieldlines::Error with the reason when the extraction
  // failed (its folder removed first).
  void poll();
  bool done() const { return done_; }  // folder() is complete: open it
  const std::filesystem::path& video() const { return video_; }
  const std::filesystem::path& folder() const { return folder_; }
  int every() const { return every_; }
  float progress() const { return job_.progress(); }
  int written() const { return job_.written(); }

 private:
  std::filesystem::path video_, folder_;
  int every_;
  bool done_ = false;
  VideoFramesJob job_;
};

}  // namespace fieldlines::studio
