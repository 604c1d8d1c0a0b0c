#include "fieldlines/data/data_file.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/detect/error.hpp"

namespace fieldlines {

bool is_reference_csv_data(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  constexpr std::string_view csv = ".csv";
  const bool named_csv = std::ranges::equal(ext, csv, [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == b;
  });
  return named_csv || looks_like_reference_csv(path);
}

Project load_data_as_project(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) throw Error("'" + path.string() + "' is not a file");
  if (is_reference_csv_data(path)) return project_from_reference_rows(read_reference_csv(path));
  return Project::load(path);
}

}  // namespace fieldlines
