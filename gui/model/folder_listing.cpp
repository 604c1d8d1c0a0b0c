#include "gui/model/folder_listing.hpp"

#include <algorithm>
#include <system_error>

namespace fieldlines::studio {

namespace fs = std::filesystem;

const std::vector<fs::path>& FolderListing::subfolders(const fs::path& folder, double now_s) {
  if (listings_ > 0 && folder == folder_ && now_s - listed_at_s_ < max_age_s_) return subfolders_;
  subfolders_.clear();
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_directory(ec) && it->path().filename().string().rfind('.', 0) != 0) subfolders_.push_back(it->path());
  }
  std::sort(subfolders_.begin(), subfolders_.end());
  folder_ = folder;
  listed_at_s_ = now_s;
  ++listings_;
  return subfolders_;
}

}  // namespace fieldlines::studio
