// `fieldlines synth`: render synthetic field images with exact ground truth.
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "app/cli/subcommand.hpp"
#include "fieldlines/synth/demo.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp = R"(usage: fieldlines synth --scene ssl|kid --n N --seed S -o DIR [options]
       fieldlines synth --demo [-o DIR]

Renders N synthetic camera frames of a soccer field with exact ground truth:
  DIR/<scene>_<seed>_<index>.png        the image (640x480 by default)
  DIR/masks/<scene>_<seed>_<index>.png  label mask (0 other, 1 carpet, 2 paint, 3 field wall, 4 object)
  DIR/truth/<scene>_<seed>_<index>.json visible lines as image polylines with widths (docs/synth.md)
The same scene, options, seed and index always give the same image bytes.

options:
  --scene ssl|kid      RoboCup SSL division B (black wall) or Humanoid Kid size (required)
  --condition C        artificial (default), natural, mixed, dim, shadows, or all (cycled);
                       a comma-separated list is cycled too
  --line-width M       painted line width in metres (default: the rule, 0.01 SSL, 0.05 Kid)
  --n N                number of images (1..100000, required)
  --seed S             set seed (0..2^31-1, required)
  --first I            index of the first image (default 0), to extend a set
  --no-effects         no vignetting, blur, noise or JPEG (clean renders)
  --height LO:HI       camera height above the carpet in metres (SSL 0.12:0.30, Kid 0.40:0.90)
  --pitch LO:HI        camera pitch below the horizon in degrees (SSL 2:22, Kid 10:45)
  --roll MAX|LO:HI     largest |roll| in degrees (SSL 4, Kid 6), or the range it is drawn from
  --fx LO:HI           focal length in pixels, fy = fx (default 600:680)
  -o, --output DIR     output folder (created if needed; required)
  --demo               make the built-in demo project if it is missing (30 SSL frames, all
                       conditions, 10 labelled) in DIR or the user's data folder
                       ($XDG_DATA_HOME/fieldlines/demo or ~/.local/share/fieldlines/demo)
                       and print the project file's path
  --quiet              no progress on stderr
  -h, --help           this help

examples:
  fieldlines synth --scene ssl --n 20 --seed 1 -o synth/ssl_train
  fieldlines synth --scene kid --condition all --line-width 0.06 --n 50 --seed 2 -o synth/kid
  fieldlines synth --scene ssl --height 0.4:0.6 --pitch 15:30 --n 20 --seed 3 -o synth/high_cam
  fieldlines synth --scene kid --height 0.6:0.6 --pitch 25:25 --roll 2:2 --fx 640:640 --n 10 --seed 4 -o synth/one_camera
)";

std::vector<synth::Condition> parse_conditions(const std::string& text) {
  if (text == "all") {
    const auto all = synth::all_conditions();
    return {all.begin(), all.end()};
  }
  std::vector<synth::Condition> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    out.push_back(synth::parse_condition(name));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

int cmd_synth(const Args& args) {
  const auto parsed = parse_or_print_help(args,
                     {"--scene", "--condition", "--line-width", "--n", "--seed", "--first", "-o", "--output",
                      "--height", "--pitch", "--roll", "--fx"},
                     {"--no-effects", "--demo", "--quiet"}, kHelp);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  if (!a.positionals().empty()) throw Error("unexpected argument '" + a.positionals().front() + "'");
  if (a.flag("--demo")) {
    DemoParams demo;
    if (const auto o = a.has("-o") ? a.value("-o") : a.value("--output")) demo.folder = *o;
    std::printf("%s\n", ensure_demo(demo).string().c_str());
    return 0;
  }
  for (const char* required : {"--scene", "--n", "--seed"})
    if (!a.has(required)) throw Error(std::string(required) + " is required (see fieldlines synth --help)");
  const auto out = a.has("-o") ? a.value("-o") : a.value("--output");
  if (!out) throw Error("-o DIR is required (see fieldlines synth --help)");

  synth::SynthParams p;
  p.field.scene = synth::parse_scene(*a.value("--scene"));
  p.field.line_width = a.double_or("--line-width", 0, 0.001, 0.3);
  p.conditions = parse_conditions(a.value_or("--condition", "artificial"));
  p.camera_effects = !a.flag("--no-effects");
  if (a.has("--height") || a.has("--pitch") || a.has("--roll") || a.has("--fx")) {
    synth::CameraRanges c = synth::default_camera_ranges(p.field.scene);
    if (const auto v = a.value("--height")) std::tie(c.height_min, c.height_max) = parse_interval(*v, "--height", 0.02, 5);
    if (const auto v = a.value("--pitch")) std::tie(c.pitch_min, c.pitch_max) = parse_interval(*v, "--pitch", -30, 89);
    if (const auto v = a.value("--roll")) {
      if (v->find(':') == std::string::npos) c.roll_max = a.double_or("--roll", c.roll_max, 0, 45);
      else c.roll = parse_interval(*v, "--roll", -45, 45);
    }
    if (const auto v = a.value("--fx")) std::tie(c.fx_min, c.fx_max) = parse_interval(*v, "--fx", 50, 5000);
    p.camera = c;
  }
  const int n = a.int_or("--n", 1, 1, 100000);
  const int seed = a.int_or("--seed", 0, 0, 2147483647);
  const int first = a.int_or("--first", 0, 0, 100000000);
  const bool quiet = a.flag("--quiet");

  const fs::path dir = *out;
  for (int i = 0; i < n; ++i) {
    const synth::SynthSample sample = synth::generate(p, static_cast<std::uint64_t>(seed), first + i);
    synth::write_sample(sample, dir);
    if (!quiet) std::fprintf(stderr, "\rsynth: %d/%d", i + 1, n);
  }
  if (!quiet) std::fprintf(stderr, "\n");
  std::printf("wrote %d images with ground truth to %s\n", n, dir.string().c_str());
  return 0;
}

}  // namespace fieldlines::cli
