// `fieldlines sweep`: precision and recall against training-set size, in the layout of the
// paper's Table 3 (one row per fraction, a precision/recall pair per DATA file).
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/sweep.hpp"
#include "app/cli/labelled_data.hpp"
#include "app/cli/subcommand.hpp"
#include "app/cli/progress.hpp"
#include "app/cli/training_options.hpp"

namespace fieldlines::cli {
namespace {

constexpr const char* kHelp = R"(usage: fieldlines sweep DATA... [options]

For each training fraction and seed 1..N: split each DATA file (a labelling project or a
reference CSV) into train and test, train, and measure the test precision and recall of the
trained class. Prints the median over seeds per fraction and file (the paper's Table 3).

options:
  --fractions LIST     comma-separated training fractions in (0, 1) (default 0.1,0.2,...,0.7)
  --seeds N            seeds per fraction (default 10)
  --split S            row (default, the paper's) or image
  --json OUT           write [{"file", "fraction", "precision", "recall", "seed_precision",
                       "seed_recall"}] to OUT: medians, and every seed's figures in seed order
  --quiet              no progress on stderr
)";

constexpr const char* kExamples = R"(
examples:
  fieldlines sweep D1_ssl_natural_light.csv --protocol paper
  fieldlines sweep D1_ssl_natural_light.csv D4_humanoid_kid.csv --fractions 0.2,0.4 --seeds 5 --json table3.json
)";

std::vector<double> parse_fractions(const std::string& text) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(parse_double(item, "--fractions", 1e-9, 1 - 1e-9));
  if (out.empty()) throw Error("--fractions: expected a comma-separated list");
  return out;
}

}  // namespace

int cmd_sweep(const Args& args) {
  std::set<std::string> values = training_value_options();
  values.insert({"--fractions", "--seeds", "--split", "--json"});
  const auto parsed = parse_or_print_help(args, values, {"--quiet"}, kHelp + training_options_help() + kExamples);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  if (a.positionals().empty()) throw Error("no DATA given (see --help)");
  // Checked before the work, which can be long: an unwritable --json would only fail at the end.
  const auto json_path = output_path(a, "--json", a.positionals());
  SweepParams sp;
  if (const auto v = a.value("--fractions")) sp.fractions = parse_fractions(*v);
  sp.seeds = a.int_or("--seeds", 10, 1, 100000);
  sp.split = SplitMode::ByRow;
  if (const auto v = a.value("--split"); v && !parse_split_mode(*v, sp.split))
    throw Error("--split: expected image or row, got '" + *v + "'");

  std::vector<LoadedData> data;
  std::vector<LabelledSet> sets;  // per file, its labelled view
  for (const std::string& p : a.positionals()) {
    data.push_back(load_labelled_data(p));
    sets.push_back(data.back().project.labelled());
    if (sets.back().size() == 0) throw Error(p + ": holds no labelled segments to split");
  }
  std::vector<std::vector<SweepCell>> results;
  {
    Progress progress("sweep", data.size() * sp.fractions.size() * static_cast<std::size_t>(sp.seeds), stderr,
                      {a.flag("--quiet") ? ProgressParams::Mode::Off : ProgressParams::Mode::Auto});
    for (std::size_t i = 0; i < data.size(); ++i) {
      SweepParams p = sp;
      p.start = data[i].project.thresholds;
      p.train = apply_training_options(a, p.start).train;
      results.push_back(run_sweep(sets[i], p, [&](int, int) { progress.advance(); }));
    }
  }

  // Table: one column pair per file, named by the file's stem.
  std::printf("%-9s", "set size");
  for (const LoadedData& d : data)
    std::printf(" | %-20.20s", std::filesystem::path(d.path).stem().string().c_str());
  std::printf("\n%-9s", "");
  for (std::size_t i = 0; i < data.size(); ++i) std::printf(" | %-9s %-10s", "precision", "recall");
  std::printf("\n");
  nlohmann::json json = nlohmann::json::array();
  for (std::size_t f = 0; f < sp.fractions.size(); ++f) {
    std::printf("%7.0f%% ", 100 * sp.fractions[f]);
    for (std::size_t i = 0; i < data.size(); ++i) {
      const SweepCell& c = results[i][f];
      std::printf(" | %9.2f %-10.2f", c.median_precision, c.median_recall);
      // Every seed's figures too: the paper's protocol stops PSO after 10 iterations, so one run
      // can land far from the median (this is how the published single runs are compared).
      nlohmann::json per_seed_precision = nlohmann::json::array(), per_seed_recall = nlohmann::json::array();
      for (const ClassCounts& t : c.test) {
        per_seed_precision.push_back(t.precision());
        per_seed_recall.push_back(t.recall());
      }
      json.push_back({{"file", data[i].path},
                      {"fraction", c.fraction},
                      {"precision", c.median_precision},
                      {"recall", c.median_recall},
                      {"seed_precision", per_seed_precision},
                      {"seed_recall", per_seed_recall}});
    }
    std::printf("\n");
  }
  if (json_path) write_file_atomically(*json_path, json.dump(2) + "\n");
  return 0;
}

}  // namespace fieldlines::cli
