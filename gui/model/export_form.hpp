#pragma once
// The Export tab's form, window-free: the path as typed, where it resolves (export_path.hpp), the
// actions (export the robot's thresholds file, create its folder first, import one, export the
// labels as the reference CSV), the one line each reports, the written file's text, and the
// folder browser's place. Every file read and path built for the tab is here; the panel draws.
#include <filesystem>
#include <string>
#include <vector>

#include "gui/model/action_report.hpp"
#include "gui/model/export_path.hpp"
#include "gui/model/folder_listing.hpp"

namespace fieldlines::studio {

class StudioController;

class ExportForm {
 public:
  // Once per frame, before drawing: a newly opened project starts from its own default path
  // (never inside its image folder) with no message; then the typed path is resolved (so the tab
  // always says where Export will write) from the project file's folder.
  void update(const StudioController& controller);
  // After an edit of path(): resolves it again.
  void resolve();

  std::string& path() { return path_; }  // as typed: the text field edits it
  const ExportTarget& target() const { return target_; }
  // Relative paths start here: the project file's folder, the same on every launch.
  const std::filesystem::path& base() const { return base_; }

  // The actions. Each reports in message(); a failure gives its reason and sets failed().
  // Writes where target() says; refuses (message only) when the folder does not exist, as
  // creating folders is never a side effect of a typo: that is create_folder_and_export().
  void export_thresholds(const StudioController& controller);
  void create_folder_and_export(const StudioController& controller);
  void import_thresholds(StudioController& controller);
  // Beside the thresholds file: `<project stem>-labels.csv`.
  void export_labels_csv(const StudioController& controller);

  const std::string& message() const { return report_.text(); }
  bool failed() const { return report_.failed(); }
  const std::string& preview() const { return preview_; }  // the file last written or imported

  // The folder browser: the nearest existing folder of the target's (or of the base when the
  // path is unusable), its subfolders (listed at most once a second), and choosing one, which
  // replaces the folder part of the path.
  const std::filesystem::path& browsed_folder() const { return browsed_; }
  const std::vector<std::filesystem::path>& subfolders(double now_s) { return listing_.subfolders(browsed_, now_s); }
  void choose_folder(const std::filesystem::path& folder);

 private:
  std::string write(const StudioController& controller);  // the line to report

  std::string path_;
  std::filesystem::path project_;  // the project file the default path was made for
  std::filesystem::path base_;
  ExportTarget target_;
  std::filesystem::path browsed_;
  std::string file_name_;  // what choose_folder keeps
  FolderListing listing_;
  ActionReport report_;
  std::string preview_;
};

}  // namespace fieldlines::studio
