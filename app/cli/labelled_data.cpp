#include "app/cli/labelled_data.hpp"

#include <filesystem>

#include "app/cli/args.hpp"

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/reference_csv.hpp"

namespace fieldlines::cli {

namespace {
void require_file(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw Error("'" + path + "' is not a file");
}
}  // namespace

bool is_reference_csv_data(const std::string& path) {
  return lower_extension(path) == ".csv" || looks_like_reference_csv(path);
}

Project load_data_as_project(const std::string& path) {
  require_file(path);
  if (is_reference_csv_data(path)) return project_from_reference_rows(read_reference_csv(path));
  return Project::load(path);
}

LoadedData load_labelled_data(const std::string& path) {
  require_file(path);
  LoadedData d;
  d.path = path;
  if (is_reference_csv_data(path)) {
    const std::vector<ReferenceRow> rows = read_reference_csv(path);
    d.set = labelled_set_from_rows(rows);
    d.unlabelled = rows.size() - d.set.size();
    return d;
  }
  const Project p = Project::load(path);
  d.set = p.labelled();
  for (const ImageEntry& e : p.images) d.unlabelled += e.segments.size();
  d.unlabelled -= d.set.size();
  d.detector = p.detector;
  d.thresholds = p.thresholds;
  return d;
}

LabelledSet merge(const std::vector<LoadedData>& data) {
  if (data.size() == 1) return data[0].set;
  LabelledSet out;
  for (const LoadedData& d : data)
    for (std::size_t i = 0; i < d.set.size(); ++i)
      out.add(d.path + ":" + d.set.images[d.set.image_of[i]], d.set.segments[i]);
  return out;
}

}  // namespace fieldlines::cli
