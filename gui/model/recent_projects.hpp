#pragma once
// The list of recently opened projects (most recent first), kept in a small text file.
#include <filesystem>
#include <string>
#include <vector>

namespace fieldlines::studio {

// $XDG_CONFIG_HOME/fieldlines/recent-projects.txt, else ~/.config/...; empty if neither is set.
std::filesystem::path default_recent_file();

// One absolute path per line; a missing or unreadable file gives an empty list.
std::vector<std::string> load_recent(const std::filesystem::path& file);
// Moves (or inserts) `project` to the front, keeps at most `max` entries.
void remember(std::vector<std::string>& recent, const std::string& project, std::size_t max = 10);
// Atomic save; failures are ignored (a missing recent list must never stop the studio).
void save_recent(const std::filesystem::path& file, const std::vector<std::string>& recent);

}  // namespace fieldlines::studio
