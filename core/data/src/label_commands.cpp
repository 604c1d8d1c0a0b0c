#include "fieldlines/data/label_commands.hpp"

#include "fieldlines/detect/error.hpp"

namespace fieldlines {

void LabelHistory::check(const Project& project, const SegmentRef& r) {
  if (r.image >= project.images.size() || r.segment >= project.images[r.image].segments.size())
    throw Error("label edit: segment " + std::to_string(r.segment) + " of image " + std::to_string(r.image) +
                " does not exist");
}

bool LabelHistory::apply(Project& project, std::span<const SegmentRef> targets, Label label,
                         std::string description) {
  std::vector<LabelEdit> edits;
  for (const SegmentRef& r : targets) edits.push_back({r, Label::Unlabelled, label});
  return apply(project, edits, std::move(description));
}

bool LabelHistory::apply(Project& project, std::span<const LabelEdit> requested, std::string description) {
  for (const LabelEdit& e : requested) check(project, e.ref);  // validate all before changing any
  LabelCommand cmd{std::move(description), {}};
  for (const LabelEdit& e : requested) {
    Label& current = project.images[e.ref.image].segments[e.ref.segment].label;
    if (current == e.after) continue;
    cmd.edits.push_back({e.ref, current, e.after});
    current = e.after;
  }
  if (cmd.edits.empty()) return false;
  done_.push_back(std::move(cmd));
  if (done_.size() > max_steps_) done_.erase(done_.begin());
  undone_.clear();  // a new edit forks history: the old redo branch is gone
  ++revision_;
  return true;
}

void LabelHistory::set(Project& project, const std::vector<LabelEdit>& edits, bool forward) {
  for (const LabelEdit& e : edits) check(project, e.ref);
  if (forward) {
    for (const LabelEdit& e : edits) project.images[e.ref.image].segments[e.ref.segment].label = e.after;
  } else {
    // Reverse order restores the first `before` when one segment was edited twice in a step.
    for (auto it = edits.rbegin(); it != edits.rend(); ++it)
      project.images[it->ref.image].segments[it->ref.segment].label = it->before;
  }
  ++revision_;
}

bool LabelHistory::undo(Project& project) {
  if (done_.empty()) return false;
  set(project, done_.back().edits, false);
  undone_.push_back(std::move(done_.back()));
  done_.pop_back();
  return true;
}

bool LabelHistory::redo(Project& project) {
  if (undone_.empty()) return false;
  set(project, undone_.back().edits, true);
  done_.push_back(std::move(undone_.back()));
  undone_.pop_back();
  return true;
}

void LabelHistory::clear() {
  done_.clear();
  undone_.clear();
  ++revision_;
}

}  // namespace fieldlines
