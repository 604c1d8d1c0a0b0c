#include "output_file.hpp"

#include <string>
#include <system_error>

#include "fieldlines/atomic_file.hpp"
#include "fieldlines/error.hpp"

namespace fieldlines::cli {

void write_output_file(const std::filesystem::path& path, std::string_view contents) {
  write_file_atomically(path, contents);
}

void check_output_path(std::string_view option, const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec))
    throw Error(std::string(option) + " " + path.string() + ": folder " + parent.string() + " does not exist");
  if (fs::is_directory(path, ec))
    throw Error(std::string(option) + " " + path.string() + ": is a folder, expected a file name");
}

}  // namespace fieldlines::cli
