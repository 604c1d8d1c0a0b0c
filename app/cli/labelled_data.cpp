#include "app/cli/labelled_data.hpp"

namespace fieldlines::cli {

LoadedData load_labelled_data(const std::string& path) { return {path, load_data_as_project(path)}; }

LabelledSet merge(const std::vector<LoadedData>& data) {
  if (data.size() == 1) return data[0].project.labelled();
  // Each project's labelled() rows, in its order, under prefixed image names.
  LabelledSet out;
  for (const LoadedData& d : data)
    for (const ImageEntry& e : d.project.images)
      for (const Segment& s : e.segments) out.add(d.path + ":" + e.path, s);
  return out;
}

}  // namespace fieldlines::cli
