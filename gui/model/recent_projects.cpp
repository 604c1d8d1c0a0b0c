#include "gui/model/recent_projects.hpp"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <system_error>

#include "fieldlines/detect/atomic_file.hpp"

namespace fieldlines::studio {

std::filesystem::path default_recent_file() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) {
    return std::filesystem::path(xdg) / "fieldlines" / "recent-projects.txt";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".config" / "fieldlines" / "recent-projects.txt";
  }
  return {};
}

std::vector<std::string> load_recent(const std::filesystem::path& file) {
  std::vector<std::string> out;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) out.push_back(line);
  }
  return out;
}

void remember(std::vector<std::string>& recent, const std::string& project, std::size_t max) {
  std::erase(recent, project);
  recent.insert(recent.begin(), project);
  if (recent.size() > max) recent.resize(max);
}

void save_recent(const std::filesystem::path& file, const std::vector<std::string>& recent) {
  if (file.empty()) return;
  try {
    std::filesystem::create_directories(file.parent_path());
    std::string text;
    for (const auto& r : recent) text += r + "\n";
    write_file_atomically(file, text);
  } catch (const std::exception&) {
    // Best effort by design: see the header.
  }
}

}  // namespace fieldlines::studio
