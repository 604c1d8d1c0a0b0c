#include "labelled_data.hpp"

#include <cctype>
#include <filesystem>

#include "fieldlines/dataset.hpp"
#include "fieldlines/error.hpp"
#include "fieldlines/reference_csv.hpp"

namespace fieldlines::cli {

LoadedData load_labelled_data(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw Error("'" + path + "' is not a file");
  LoadedData d;
  d.path = path;
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".csv" || looks_like_reference_csv(path)) {
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
