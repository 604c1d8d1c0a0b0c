// `fieldlines convert`: a labelling project to the reference annotation CSV and back.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "fieldlines/data/image_io.hpp"
#include "fieldlines/data/data_file.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "app/cli/subcommand.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp = R"(usage: fieldlines convert DATA -o OUT [--quiet]

Converts labelled data between the two formats every DATA argument of train, eval and sweep
accepts. DATA is a labelling project file or a reference annotation CSV (told apart as train
does: a .csv name or a CSV header). The format of OUT is chosen by its name:

  OUT.csv   the reference annotation CSV: one row per segment with a human label (marking,
            boundary or none), images in project order. Unlabelled segments are NOT written
            (the format has exactly one True label column per row) and are counted in the
            summary; nor are the project's detector parameters, thresholds and timings.
  OUT.json  a labelling project: the CSV rows grouped by image, unlabelled rows kept as
            unlabelled segments, default detector parameters and thresholds.

Image paths are copied exactly as written (a project reads them relative to its own folder;
the images need not exist: rows without images still train and evaluate). Coordinates,
gradients and saliency are written so that they read back bit for bit, so CSV -> project ->
CSV gives back every labelled row with the same values (the same bytes when fieldlines wrote
the CSV) and project -> CSV -> project every labelled segment.
OUT is written atomically; an input file is never overwritten, nor an existing OUT that is
not a file of OUT's kind. A one-line summary goes to stderr.

options:
  -o, --output OUT  the file to write, ending in .csv or .json (required)
  --quiet           no summary
  -h, --help        this help
Exit codes: 0 ok, 2 usage or fatal error (a malformed DATA row names its file and line;
nothing is written).

examples:
  fieldlines convert labels/project.json -o labels.csv
  fieldlines convert D4_humanoid_kid.csv -o d4/project.json
  fieldlines autolabel synth/train && fieldlines convert synth/train/project.json -o train.csv
)";

// "1 image", "2 images".
std::string count(std::size_t n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace

int cmd_convert(const Args& args) {
  const auto parsed = parse_or_print_help(args, {"-o", "--output"}, {"--quiet"}, kHelp);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  if (a.positionals().empty()) throw Error("no DATA given (see --help)");
  if (a.positionals().size() > 1)
    throw Error("expected one DATA file, got " + std::to_string(a.positionals().size()) + " (see --help)");
  const std::string data = a.positionals().front();
  // All output checks before reading DATA: the folder exists, OUT is not DATA, and an existing
  // OUT is only replaced when it is a file of the same kind (never, say, a thresholds file).
  const fs::path out = required_output_path(a, "-o", "OUT", {data});
  const std::string ext = lower_extension(out);
  if (ext != ".csv" && ext != ".json")
    throw Error("-o " + out.string() + ": expected a name ending in .csv (reference CSV) or .json (project)");
  const bool to_csv = ext == ".csv";
  if (fs::exists(out)) {
    if (to_csv) {
      if (!looks_like_reference_csv(out))
        throw Error("refusing to overwrite -o " + out.string() + ", it is not a reference CSV (no img_path/segment_length header)");
    } else {
      try {
        (void)Project::load(out);
      } catch (const Error& e) {
        throw Error("refusing to overwrite -o " + out.string() + ", it is not a project file we can read (" + e.what() + ")");
      }
    }
  }

  const Project project = load_data_as_project(data);
  std::size_t segments = 0;
  for (const ImageEntry& e : project.images) segments += e.segments.size();
  const std::size_t labelled = project.labelled_count();
  const std::size_t unlabelled = segments - labelled;

  if (to_csv) {
    const std::vector<ReferenceRow> rows = reference_rows_from_project(project);
    write_reference_csv(out, rows);
    if (!a.flag("--quiet")) {
      std::size_t images = 0;
      for (const ImageEntry& e : project.images)
        for (const Segment& s : e.segments)
          if (s.label != Label::Unlabelled) {
            ++images;
            break;
          }
      std::string line = "convert: " + count(rows.size(), "labelled segment") + " from " + count(images, "image") +
                         " -> " + out.string();
      if (unlabelled > 0) line += "; " + count(unlabelled, "unlabelled segment") + " not exported";
      std::fprintf(stderr, "%s\n", line.c_str());
    }
  } else {
    project.save(out);
    if (!a.flag("--quiet"))
      std::fprintf(stderr, "convert: %zu labelled and %zu unlabelled segments from %s -> %s\n", labelled, unlabelled,
                   count(project.images.size(), "image").c_str(), out.string().c_str());
  }
  return 0;
}

}  // namespace fieldlines::cli
