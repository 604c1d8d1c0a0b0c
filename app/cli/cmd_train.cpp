// `fieldlines train`: PSO-train the classification thresholds on labelled data and write the
// thresholds file the robot loads.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/split_spec.hpp"
#include "fieldlines/train/splits.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fieldlines/train/training.hpp"
#include "app/cli/labelled_data.hpp"
#include "app/cli/subcommand.hpp"
#include "app/cli/progress.hpp"
#include "app/cli/training_options.hpp"
#include "app/cli/training_report.hpp"

namespace fieldlines::cli {
namespace {

constexpr const char* kHelp = R"(usage: fieldlines train DATA... -o FILE [options]

Trains the classification thresholds on labelled segments and writes the thresholds file
(schema: docs/training.md). DATA is a labelling project file or a reference annotation CSV;
several are pooled. The data is split into train and test parts; the file's provenance records
both parts' precision and recall. A project's recorded split (the studio's test split) is the
default; --split, --train-fraction and --seed override it. With --folds K, a K-fold cross-validation with the same
options runs first: its per-fold test precision/recall, mean and standard deviation go to stderr
and to the provenance ("cross_validation"); the thresholds written are then trained as without
it. Progress on stderr, a summary on stdout.

options:
  -o, --output FILE    the thresholds file to write (required)
  --split S            image (default: no image on both sides) or row (the paper's)
  --train-fraction F   share of images/rows used for training, (0, 1] (default 0.7;
                       1 trains on everything and leaves no test part)
  --seed S             seed of the split and of PSO (default 1)
                       (these defaults are a project's recorded split when DATA is one)
  --folds K            cross-validate over K folds first: 2..50, at most the number of
                       images (of rows with --split row); split and seeded like the above
)";

constexpr const char* kExamples = R"(
examples:
  fieldlines train labels/project.json -o robot.json
  fieldlines train D1_ssl_natural_light.csv --split row --train-fraction 0.4 --seed 3 -o t.json
  fieldlines train a.csv b.csv --class both --objective fbeta:0.5 -o both.json
  fieldlines train field.csv --protocol paper --train-fraction 1 -o paper.json
  fieldlines train D1_ssl_natural_light.csv --folds 5 -o t.json
)";

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

nlohmann::json bounds_json(const ThresholdBounds& b) {
  return {{"min_projection", {b.projection.lo, b.projection.hi}},
          {"max_angle_deg", {b.angle_deg.lo, b.angle_deg.hi}},
          {"min_length", {b.length.lo, b.length.hi}}};
}

// K-fold cross-validation of `spec` on `all` (the same split mode and seed as the final split):
// each fold trains on its train part and is counted on its test part.
CrossValidation cross_validate(const LabelledSet& all, const Thresholds& start, const ProtocolSpec& spec, int k,
                               std::uint64_t seed, bool quiet) {
  CrossValidation cv;
  cv.split = spec.split;
  cv.seed = seed;
  cv.target = spec.train.target;
  const std::vector<Split> folds = k_fold(all, spec.split, k, seed);
  Progress progress("cross-validation", folds.size() * static_cast<std::size_t>(spec.train.pso.iterations), stderr,
                    {quiet ? ProgressParams::Mode::Off : ProgressParams::Mode::Auto});
  for (const Split& fold : folds) {
    const LabelledSet train_set = all.subset(fold.train), test_set = all.subset(fold.test);
    const TrainResult r = train(train_set.segments, start, spec.train, [&](const TrainingProgress&) { progress.advance(); });
    cv.folds.push_back({train_set.size(), test_set.size(), evaluate(test_set, r.thresholds).total});
  }
  return cv;
}

}  // namespace

int cmd_train(const Args& args) {
  std::set<std::string> values = training_value_options();
  values.insert({"-o", "--output", "--split", "--train-fraction", "--seed", "--folds"});
  const auto parsed = parse_or_print_help(
      args, values, {"--quiet"},
      kHelp + training_options_help() + "  --quiet              nothing on stderr but errors\n" + kExamples);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  // Checked before a possibly long training: the folder must exist, and an existing file is only
  // replaced when it is a thresholds file (never the labels: `-o project.json` would lose them).
  const std::filesystem::path output = required_output_path(a, "-o", "FILE");
  if (a.positionals().empty()) throw Error("no DATA given (see --help)");
  if (std::filesystem::exists(output)) {
    try {
      (void)load_thresholds_file(output);
    } catch (const Error& e) {
      throw Error("refusing to overwrite -o " + output.string() + ", it is not a thresholds file we can read (" +
                  e.what() + ")");
    }
  }

  std::vector<LoadedData> data;
  for (const std::string& p : a.positionals()) data.push_back(load_labelled_data(p));
  const LabelledSet all = merge(data);
  if (all.size() == 0) throw Error("the DATA files hold no labelled segments");

  Thresholds start = data[0].project.thresholds;
  const DetectorParams detector = data[0].project.detector;
  ProtocolSpec spec = apply_training_options(a, start);
  // The split the first DATA records: a project's is the studio's test split, so training the
  // project here tests on the segments the studio tests on; a CSV records SplitSpec's defaults.
  // Options override it, and so does --protocol's split mode (the paper's splits by row).
  const SplitSpec recorded = data[0].project.split;
  if (!a.has("--protocol")) spec.split = recorded.mode;
  if (const auto v = a.value("--split"); v && !parse_split_mode(*v, spec.split))
    throw Error("--split: expected image or row, got '" + *v + "'");
  const double fraction = a.double_or("--train-fraction", recorded.train_fraction, 1e-9, 1.0);
  // A recorded seed is used whole: the studio splits with all 64 bits of it.
  const std::uint64_t seed =
      a.has("--seed") ? static_cast<std::uint64_t>(a.int_or("--seed", 0, 0, 2147483647)) : recorded.seed;
  spec.train.pso.seed = seed;
  const int folds = a.int_or("--folds", 0, 2, 50);  // 0: no cross-validation
  const bool quiet = a.flag("--quiet");
  if (folds > 0) {
    // Checked here rather than by k_fold so the message names the option and the way out.
    const bool by_row = spec.split == SplitMode::ByRow;
    const std::size_t units = by_row ? all.size() : all.images.size();
    if (static_cast<std::size_t>(folds) > units)
      throw Error("--folds " + std::to_string(folds) + ": the data has only " + std::to_string(units) +
                  (by_row ? " labelled rows" : " images (--split image)") + ", so at most " +
                  std::to_string(units) + " folds" + (by_row ? "" : "; --split row splits by row"));
  }
  const Split split = split_train_test(all, spec.split, fraction, seed);
  const LabelledSet train_set = all.subset(split.train), test_set = all.subset(split.test);
  std::optional<CrossValidation> cv;
  if (folds > 0) {
    cv = cross_validate(all, start, spec, folds, seed, quiet);
    if (!quiet) print_cross_validation(stderr, *cv);
  }

  if (!quiet)
    std::fprintf(stderr, "training %s on %zu segments (%zu images), testing on %zu segments\n",
                 std::string(to_string(spec.train.target)).c_str(), train_set.size(), train_set.images.size(),
                 test_set.size());

  const auto t0 = std::chrono::steady_clock::now();
  TrainResult r;
  {
    Progress progress("PSO", static_cast<std::size_t>(spec.train.pso.iterations), stderr,
                      {quiet ? ProgressParams::Mode::Off : ProgressParams::Mode::Auto});
    r = train(train_set.segments, start, spec.train, [&](const TrainingProgress&) { progress.advance(); });
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  const Counts train_counts = evaluate(train_set, r.thresholds).total;
  const std::optional<Counts> test_counts =
      test_set.size() ? std::optional<Counts>(evaluate(test_set, r.thresholds).total) : std::nullopt;

  ThresholdsFile file;
  file.detector = detector;
  file.thresholds = r.thresholds;
  nlohmann::json& p = file.provenance;
  p["data"] = nlohmann::json::array();
  for (const LoadedData& d : data) p["data"].push_back(d.path);
  p["counts"] = {{"segments", all.size()},
                 {"images", all.images.size()},
                 {"marking", all.count(Label::Marking)},
                 {"boundary", all.count(Label::Boundary)},
                 {"none", all.count(Label::None)},
                 {"train_segments", train_set.size()},
                 {"test_segments", test_set.size()}};
  p["class"] = to_string(spec.train.target);
  p["objective"] = spec.train.objective.name();
  p["seed"] = seed;
  p["split"] = to_string(spec.split);
  p["train_fraction"] = fraction;
  p["pso"] = {{"particles", spec.train.pso.particles},
              {"iterations", spec.train.pso.iterations},
              {"inertia", spec.train.pso.inertia},
              {"cognitive", spec.train.pso.cognitive},
              {"social", spec.train.pso.social},
              {"polish", spec.train.polish}};
  p["bounds"] = {{"marking", bounds_json(spec.train.marking_bounds)},
                 {"boundary", bounds_json(spec.train.boundary_bounds)}};
  p["score"] = r.score;
  p["date"] = utc_now();
  p["fieldlines_version"] = FIELDLINES_VERSION;
  p["train"] = counts_json(train_counts);
  p["test"] = test_counts ? counts_json(*test_counts) : nlohmann::json(nullptr);
  if (cv) p["cross_validation"] = cross_validation_json(*cv);
  save_thresholds_file(output, file);

  const auto show = [](const char* name, const ColourClass& c) {
    std::printf("%-9s min projection %8.3f  max angle %7.3f deg  min length %8.3f\n", name,
                c.thresholds.min_projection, c.thresholds.max_angle_deg, c.thresholds.min_length);
  };
  show("boundary", r.thresholds.boundary);
  show("marking", r.thresholds.marking);
  std::printf("train %s = %g (PSO %g) in %.1f ms\n", spec.train.objective.name().c_str(), r.score, r.pso_score, ms);
  print_counts_header(stdout, 20);
  print_counts(stdout, "train", train_counts);
  if (test_counts) print_counts(stdout, "test", *test_counts);
  std::printf("wrote %s\n", output.c_str());
  return 0;
}

}  // namespace fieldlines::cli
