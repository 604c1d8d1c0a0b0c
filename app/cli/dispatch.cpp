#include <cstdio>
#include <exception>
#include <string_view>

#include "app/cli/commands.hpp"
#include "fieldlines/detect/error.hpp"

namespace fieldlines::cli {
namespace {

struct Command {
  std::string_view name;
  int (*run)(const Args&);
  std::string_view summary;
};

constexpr Command kCommands[] = {
    {"detect", cmd_detect, "detect and classify field lines in images or folders"},
    {"bench", cmd_bench, "time the detector against OpenCV's line detectors"},
    {"calibrate", cmd_calibrate, "fit thresholds for a new field from unlabelled images (no labels)"},
    {"calibrate-camera", cmd_calibrate_camera, "fit a standing camera's pitch, roll (and height) from the field lines"},
    {"train", cmd_train, "train classification thresholds with PSO on labelled data"},
    {"eval", cmd_eval, "evaluate thresholds on labelled data or synthetic ground truth"},
    {"sweep", cmd_sweep, "precision/recall over training fractions (the paper's Table 3)"},
    {"synth", cmd_synth, "render synthetic fields with exact ground truth"},
    {"autolabel", cmd_autolabel, "label detected segments of a synthetic set from its ground truth"},
    {"convert", cmd_convert, "convert labels between a project file and the reference CSV"},
};

void print_usage(std::FILE* to) {
  std::fprintf(to, "usage: fieldlines <command> [options]   (fieldlines <command> --help)\n\ncommands:\n");
  for (const auto& c : kCommands)
    std::fprintf(to, "  %-16s %s\n", std::string(c.name).c_str(), std::string(c.summary).c_str());
  std::fprintf(to, R"(
  --version  print the version;  --help  this list

examples:
  fieldlines detect --draw overlays/ frames/
  fieldlines calibrate venue-photos/ -o robot.json
  fieldlines calibrate-camera standing/ --camera nominal.json -o camera.json --line-width 0.05
  fieldlines train labels/project.json -o robot.json
  fieldlines convert labels/project.json -o labels.csv
  fieldlines detect --thresholds robot.json --video /dev/video0
  fieldlines synth --demo
)");
}

}  // namespace

int run(int argc, char** argv) {
  if (argc < 2) {
    print_usage(stderr);
    return 2;
  }
  const std::string_view name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_usage(stdout);
    return 0;
  }
  if (name == "--version") {
    std::printf("fieldlines %s\n", FIELDLINES_VERSION);
    return 0;
  }
  for (const auto& c : kCommands) {
    if (c.name != name) continue;
    try {
      return c.run(Args(argv + 2, argv + argc));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fieldlines %s: error: %s\n", argv[1], e.what());
      return 2;
    }
  }
  std::fprintf(stderr, "fieldlines: unknown command '%s'\n", argv[1]);
  print_usage(stderr);
  return 2;
}

}  // namespace fieldlines::cli
