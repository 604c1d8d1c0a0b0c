#pragma once
// Autosave off the UI thread: a save of a 4,000-segment project takes 7-16 ms here, a whole
// frame. The UI thread hands over a copy of the project (well under a millisecond) and a
// background Job (gui/model/job.hpp) writes it atomically. Saves never overlap and never
// reorder: while one runs, only the newest snapshot waits, so a burst of edits costs two writes.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "fieldlines/data/project.hpp"
#include "gui/model/job.hpp"

namespace fieldlines::studio {

class ProjectSaver {
 public:
  ProjectSaver() = default;
  ProjectSaver(const ProjectSaver&) = delete;
  ProjectSaver& operator=(const ProjectSaver&) = delete;
  ~ProjectSaver() { finish(); }  // nothing queued is lost on a normal exit

  void save(Project snapshot, std::filesystem::path file);

  struct Done {
    std::size_t saved = 0;  // saves completed since the last poll
    std::string error;      // why the last one that failed did, if any failed
  };
  Done poll();  // UI thread, once per frame
  Done finish();  // blocks until everything queued is written (exit, tests)
  bool busy() const { return job_.running() || pending_.has_value(); }

 private:
  void start(std::pair<Project, std::filesystem::path> work);
  std::optional<std::pair<Project, std::filesystem::path>> pending_;
  Job<int, bool> job_;
};

}  // namespace fieldlines::studio
