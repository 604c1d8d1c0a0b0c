// `fieldlines eval`: precision/recall of a thresholds file on labelled data.
#include <cstdio>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/metrics.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "app/cli/labelled_data.hpp"
#include "app/cli/subcommand.hpp"
#include "app/cli/training_report.hpp"

namespace fieldlines::cli {
namespace {

constexpr const char* kHelp = R"(usage: fieldlines eval DATA... --thresholds FILE [options]

Classifies every labelled segment of DATA (a labelling project file or a reference annotation
CSV) with the thresholds FILE and prints TP, FP, FN, precision, recall and F1 per class, per
DATA file and pooled. Unlabelled segments are ignored.

options:
  --thresholds FILE  thresholds file written by `fieldlines train` (required)
  --per-image        also one line per image
  --json OUT         write the counts as JSON: {"files": [{"file", "total", "images": [...]}],
                     "total": {...}}
  --gt ...           evaluate detections against synthetic ground truth instead (see
                     `fieldlines eval --gt --help`)
  --hand ...         ... or against hand-drawn truth of real frames (same help)
  -h, --help         this help
Exit codes: 0 ok, 2 usage or fatal error (a malformed DATA row names its file and line).

examples:
  fieldlines eval labels/project.json --thresholds robot.json
  fieldlines eval D2_ssl_mixed_light.csv D3_ssl_artificial_light.csv --thresholds t.json --per-image
  fieldlines eval --gt synth/ssl_test --thresholds robot.json
)";

bool wants_ground_truth(const Args& args) {
  for (const std::string& a : args)
    if (a == "--gt" || a.rfind("--gt=", 0) == 0 || a == "--hand" || a.rfind("--hand=", 0) == 0) return true;
  return false;
}

}  // namespace

int cmd_eval(const Args& args) {
  if (wants_ground_truth(args)) {
    return cmd_eval_gt(args);
  }
  const auto parsed = parse_or_print_help(args, {"--thresholds", "--json"}, {"--per-image"}, kHelp);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  const auto thresholds_path = a.value("--thresholds");
  if (!thresholds_path) throw Error("missing --thresholds FILE (see --help)");
  if (a.positionals().empty()) throw Error("no DATA given (see --help)");
  // Checked before the work, which can be long: an unwritable --json would only fail at the end.
  std::vector<std::string> inputs = a.positionals();
  inputs.push_back(*thresholds_path);
  const auto json_path = output_path(a, "--json", inputs);
  const ThresholdsFile file = load_thresholds_file(*thresholds_path);

  nlohmann::json out = {{"thresholds", *thresholds_path}, {"files", nlohmann::json::array()}};
  Counts total;
  print_counts_header(stdout, 20);
  for (const std::string& path : a.positionals()) {
    const LoadedData d = load_labelled_data(path);
    const Evaluation ev = evaluate(d.project.labelled(), file.thresholds);
    nlohmann::json images = nlohmann::json::array();
    for (const ImageCounts& ic : ev.per_image) {
      if (a.flag("--per-image")) print_counts(stdout, "  " + ic.image, ic.counts);
      images.push_back({{"image", ic.image}, {"counts", counts_json(ic.counts)}});
    }
    print_counts(stdout, path, ev.total);
    out["files"].push_back({{"file", path}, {"total", counts_json(ev.total)}, {"images", std::move(images)}});
    total += ev.total;
  }
  if (a.positionals().size() > 1) print_counts(stdout, "all", total);
  out["total"] = counts_json(total);
  if (json_path) write_file_atomically(*json_path, out.dump(2) + "\n");
  return 0;
}

}  // namespace fieldlines::cli
