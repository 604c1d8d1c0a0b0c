#pragma once
// The subfolders of one folder, listed once and kept: the Export tab's folder browser draws every
// frame, and listing a folder 60 times a second is disk work for nothing. The listing is redone
// when the folder changes or when it is older than `max_age_s` (a folder made meanwhile appears).
#include <cstddef>
#include <filesystem>
#include <vector>

namespace fieldlines::studio {

class FolderListing {
 public:
  explicit FolderListing(double max_age_s = 1.0) : max_age_s_(max_age_s) {}

  // The non-hidden subfolders of `folder`, sorted; `now_s` is any monotonic clock in seconds.
  // An unreadable folder lists as empty.
  const std::vector<std::filesystem::path>& subfolders(const std::filesystem::path& folder, double now_s);

  // How many times a folder was actually read (for tests).
  std::size_t listings() const { return listings_; }

 private:
  double max_age_s_;
  std::filesystem::path folder_;
  double listed_at_s_ = 0;
  std::size_t listings_ = 0;
  std::vector<std::filesystem::path> subfolders_;
};

}  // namespace fieldlines::studio
