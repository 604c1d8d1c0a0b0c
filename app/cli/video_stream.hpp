#pragma once
// `fieldlines detect --video SOURCE`: detection on a video file or camera with a live
// frames-per-second and latency readout, and an optional overlay video.
#include <filesystem>
#include <optional>
#include <string>

#include "fieldlines/detect/thresholds_file.hpp"

#include "fieldlines/detect/ground_camera.hpp"

namespace fieldlines::cli {

struct VideoOptions {
  std::string source;                         // file path, or /dev/videoN for a camera
  std::optional<std::filesystem::path> overlay_out;  // MJPG .avi with the overlays drawn
  long max_frames = -1;                       // stop after this many frames (-1: until the end)
  bool quiet = false;
  std::optional<GroundCamera> camera;         // a fixed camera over the turf (--camera)
  std::optional<double> steady_ms;            // --steady: hold junctions and the circle this long
};

// Returns the exit code; throws fieldlines::Error when the source cannot be opened.
int run_video_detection(const VideoOptions& options, const ThresholdsFile& config);

}  // namespace fieldlines::cli
