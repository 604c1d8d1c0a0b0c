#include "gui/model/studio_args.hpp"

#include <charconv>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::studio {

namespace {
int parse_int(const std::string& text, const std::string& option, int lo, int hi) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || value < lo || value > hi) {
    throw Error(option + ": expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got '" +
                text + "'");
  }
  return value;
}
}  // namespace

const char* studio_usage() {
  return "usage: fieldlines-studio [PROJECT.json | IMAGE_FOLDER | VIDEO | --last] [--every N] [--window-size WxH]\n"
         "                         [--camera FILE] [--no-auto-train] [--bench-frames N [--bench-no-features]] [--version]\n"
         "  PROJECT.json     a studio project (labels are autosaved into it)\n"
         "  IMAGE_FOLDER     images to label; creates IMAGE_FOLDER/fieldlines-project.json\n"
         "  VIDEO            mp4/avi/mkv/mov/webm: every N-th frame (--every, default 10) goes to\n"
         "                   VIDEO_STEM-everyN/ next to it, which then opens as an image folder\n"
         "  (nothing)        the built-in demo: synthetic field pictures, some labelled, made on first use\n"
         "  --last           reopen the most recent project (also listed in the Images tab)\n"
         "  --window-size    initial window size, default 1280x800\n"
         "  --camera FILE    the robot's camera (intrinsics, pitch, roll, height; as `fieldlines detect\n"
         "                   --camera`): the field features fit the centre circle on the turf too\n"
         "  --no-auto-train  start with live retraining off (it retrains both classes after every\n"
         "                   label change; the Train tab's checkbox toggles it)\n"
         "  --bench-frames N render N frames as fast as possible, print the median frame time, exit\n"
         "                   (without a project: a 640x480 image with 300 segments and field\n"
         "                   features of every kind, all four layers drawn)\n"
         "  --bench-no-features  the same scene with no feature layer drawn, for comparison\n"
         "  --state-file F   write the view transform, hovered segment and save count to F as JSON\n"
         "                   whenever they change (for automated UI tests)\n"
         "examples:\n"
         "  fieldlines-studio                          # the demo\n"
         "  fieldlines-studio ~/venue/pictures/        # label a folder of field pictures\n"
         "  fieldlines-studio match.mp4 --every 15     # every 15th frame of a video\n"
         "  fieldlines-studio --last                   # carry on where you stopped\n";
}

StudioArgs parse_studio_args(const std::vector<std::string>& args) {
  StudioArgs out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw Error(a + ": missing value");
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      out.help = true;
    } else if (a == "--version") {
      out.version = true;
    } else if (a == "--last") {
      out.last = true;
    } else if (a == "--bench-frames") {
      out.bench_frames = parse_int(value(), a, 1, 1'000'000);
    } else if (a == "--bench-no-features") {
      out.bench_features = false;
    } else if (a == "--window-size") {
      const std::string& v = value();
      const auto x = v.find('x');
      if (x == std::string::npos) throw Error(a + ": expected WIDTHxHEIGHT, got '" + v + "'");
      out.window_width = parse_int(v.substr(0, x), a, 200, 16384);
      out.window_height = parse_int(v.substr(x + 1), a, 200, 16384);
    } else if (a == "--no-auto-train") {
      out.auto_train = false;
    } else if (a == "--every") {
      out.video_every = parse_int(value(), a, 1, 100000);
    } else if (a == "--state-file") {
      out.state_file = value();
    } else if (a == "--camera") {
      out.camera_file = value();
    } else if (!a.empty() && a[0] == '-') {
      throw Error("unknown option " + a);
    } else if (out.input.empty()) {
      out.input = a;
    } else {
      throw Error("only one project or folder can be opened, got '" + out.input + "' and '" + a + "'");
    }
  }
  if (!out.bench_features && out.bench_frames == 0) throw Error("--bench-no-features: only with --bench-frames");
  if (out.last && !out.input.empty()) throw Error("--last reopens the most recent project; do not name one too");
  return out;
}

}  // namespace fieldlines::studio
