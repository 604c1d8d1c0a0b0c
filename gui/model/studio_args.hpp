#pragma once
// Command line of fieldlines-studio.
#include <optional>
#include <string>
#include <vector>

namespace fieldlines::studio {

struct StudioArgs {
  std::string input;          // project file, image folder or video; empty: the demo (or --last)
  bool last = false;          // reopen the most recent project instead of the demo
  int window_width = 1280, window_height = 800;
  int bench_frames = 0;       // > 0: render this many frames, print the median frame time, exit
  bool bench_features = true; // the bench scene's field features drawn (--bench-no-features: not)
  int video_every = 10;       // a video opens as every n-th frame
  bool auto_train = true;     // retrain after every label change (--no-auto-train: off)
  std::string state_file;     // automation: write the UI state (view, hover, saves) here as JSON
  std::string camera_file;    // a fixed camera over the field (camera_file.hpp): the circle is also fitted on the turf
  bool help = false;
  bool version = false;
};

// Throws fieldlines::Error on an unknown option or a bad value.
StudioArgs parse_studio_args(const std::vector<std::string>& args);
const char* studio_usage();

}  // namespace fieldlines::studio
