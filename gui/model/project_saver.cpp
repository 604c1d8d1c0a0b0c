#include "gui/model/project_saver.hpp"

namespace fieldlines::studio {

void ProjectSaver::start(std::pair<Project, std::filesystem::path> work) {
  job_.start([work = std::move(work)](std::stop_token, const auto&) {
    work.first.save(work.second);  // atomic (fieldlines/detect/atomic_file.hpp); throws on failure
    return true;
  });
}

void ProjectSaver::save(Project snapshot, std::filesystem::path file) {
  pending_.emplace(std::move(snapshot), std::move(file));
  if (!job_.running()) start(*std::exchange(pending_, std::nullopt));
}

ProjectSaver::Done ProjectSaver::poll() {
  Done done;
  const bool was_running = job_.running();
  job_.poll();
  if (was_running && !job_.running()) {
    if (job_.outcome()->ok()) {
      ++done.saved;
    } else {
      done.error = job_.outcome()->error();
    }
    if (pending_) start(*std::exchange(pending_, std::nullopt));
  }
  return done;
}

ProjectSaver::Done ProjectSaver::finish() {
  Done all;
  while (busy()) {
    job_.wait();
    const Done d = poll();
    all.saved += d.saved;
    if (!d.error.empty()) all.error = d.error;
  }
  return all;
}

}  // namespace fieldlines::studio
