#include "app/cli/output_file.hpp"

#include <string>
#include <system_error>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"

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

void check_not_an_input(std::string_view option, const std::filesystem::path& path,
                        const std::vector<std::string>& inputs) {
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (std::filesystem::equivalent(path, input, ec))
      throw Error(std::string(option) + " " + path.string() + ": is also an input file, refusing to overwrite it");
  }
}

}  // namespace fieldlines::cli
