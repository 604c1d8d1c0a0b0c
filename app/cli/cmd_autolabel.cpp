// `fieldlines autolabel DIR`: a labelled project from a synthetic set, without a person.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/gt_eval.hpp"
#include "fieldlines/data/image_io.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/synth/synth.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "app/cli/subcommand.hpp"
#include "app/cli/synth_set.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp = R"(usage: fieldlines autolabel DIR [-o PROJECT] [options]

Detects the segments of every image of a synthetic set DIR (made by `fieldlines synth`) and
labels each from the exact ground truth: marking or boundary when it follows that class's line
edges for >= 60% of its length (within 2.5 px and 10 degrees), none otherwise. Writes a
labelling project that `fieldlines train` and the studio open.

options:
  -o, --output PROJECT  project file to write (default DIR/project.json); image paths in it are
                        relative to its folder
  --csv OUT             also write the labelled segments in the reference annotation CSV format
                        (what the method's original tools read; `fieldlines train` reads it too)
  --thresholds FILE     detector parameters and start thresholds (default: built-in defaults)
  --max-distance PX     edge match distance (default 2.5)
  --quiet               no summary on stdout
  -h, --help            this help

examples:
  fieldlines synth --scene ssl --n 40 --seed 1 -o train && fieldlines autolabel train
  fieldlines train train/project.json -o thresholds.json
)";

}  // namespace

int cmd_autolabel(const Args& args) {
  const auto parsed = parse_or_print_help(args, {"-o", "--output", "--csv", "--thresholds", "--max-distance"}, {"--quiet"}, kHelp);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  if (a.positionals().size() != 1) throw Error("expected one synthetic set folder DIR (see --help)");
  const fs::path dir = a.positionals().front();
  const fs::path out = output_path(a, "-o").value_or(dir / "project.json");
  const std::optional<fs::path> csv = output_path(a, "--csv");
  ThresholdsFile file;
  if (const auto t = a.value("--thresholds")) file = load_thresholds_file(*t);
  GtMatchParams match;
  match.max_distance_px = static_cast<float>(a.double_or("--max-distance", match.max_distance_px, 0.1, 50));

  Project project;
  project.detector = file.detector;
  project.thresholds = file.thresholds;
  LineDetector detector(file.detector, file.thresholds);
  const fs::path base = fs::absolute(out).parent_path();
  std::array<long, 3> totals{0, 0, 0};
  std::vector<ReferenceRow> rows;
  int failed = 0;
  for (const auto& [image, truth_file] : list_synth_set(dir)) {
    try {
      const synth::GroundTruth truth = synth::load_truth(truth_file);
      const cv::Mat img = load_image(image);
      ImageEntry entry;
      const auto start = std::chrono::steady_clock::now();
      entry.segments = detector.detect(img);
      entry.detect_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      const auto counts = label_from_truth(entry.segments, truth, match);
      for (std::size_t i = 0; i < 3; ++i) totals[i] += counts[i];
      entry.path = fs::relative(fs::absolute(image), base).generic_string();
      for (const Segment& s : entry.segments) rows.push_back({entry.path, s});
      project.images.push_back(std::move(entry));
    } catch (const Error& e) {
      std::fprintf(stderr, "fieldlines autolabel: %s\n", e.what());
      ++failed;
    }
  }
  // An all-failed run must not replace a previous project (labels included) with an empty one.
  if (project.images.empty())
    throw Error(dir.string() + ": no image could be labelled (see the messages above); " + out.string() + " not written");
  project.save(out);
  if (csv) write_reference_csv(*csv, rows);
  if (!a.flag("--quiet"))
    std::printf("%s: %zu images, %ld marking, %ld boundary, %ld none segments\n", out.string().c_str(),
                project.images.size(), totals[2], totals[1], totals[0]);
  return failed > 0 ? 1 : 0;
}

}  // namespace fieldlines::cli
