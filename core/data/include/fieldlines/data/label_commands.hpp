#pragma once
// Undo/redo of label edits on a Project as a command stack. Every apply() is one undoable step,
// whether it changes one segment or a whole selection (batch edit).
//
// Usage (the studio binds undo/redo to keys):
//   LabelHistory h;
//   h.apply(project, {{img, seg}}, Label::Marking, "mark segment");
//   h.undo(project);  h.redo(project);
// After replacing an image's segments (re-detection) call clear(): indices no longer match.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "fieldlines/data/project.hpp"

namespace fieldlines {

struct SegmentRef {
  std::size_t image = 0, segment = 0;
  bool operator==(const SegmentRef&) const = default;
};

struct LabelEdit {
  SegmentRef ref;
  Label before = Label::Unlabelled, after = Label::Unlabelled;
};

struct LabelCommand {
  std::string description;
  std::vector<LabelEdit> edits;
};

class LabelHistory {
 public:
  explicit LabelHistory(std::size_t max_steps = 1000) : max_steps_(max_steps) {}

  // Sets `label` on every target, as one step. Edits that change nothing are dropped; when none
  // is left nothing is recorded and false is returned. Throws fieldlines::Error (changing
  // nothing) when a target is out of range.
  bool apply(Project& project, std::span<const SegmentRef> targets, Label label, std::string description = {});
  // Sets each target to its own label (e.g. paste, or a classifier's suggestions), as one step.
  bool apply(Project& project, std::span<const LabelEdit> edits, std::string description = {});
  bool undo(Project& project);  // false when there is nothing to undo
  bool redo(Project& project);
  bool can_undo() const { return !done_.empty(); }
  bool can_redo() const { return !undone_.empty(); }
  const LabelCommand* next_undo() const { return done_.empty() ? nullptr : &done_.back(); }
  const LabelCommand* next_redo() const { return undone_.empty() ? nullptr : &undone_.back(); }
  // Increases on every apply/undo/redo: compare with a saved value to know if edits are unsaved.
  std::size_t revision() const { return revision_; }
  void clear();

 private:
  static void check(const Project& project, const SegmentRef& ref);
  void set(Project& project, const std::vector<LabelEdit>& edits, bool forward);

  std::vector<LabelCommand> done_, undone_;
  std::size_t max_steps_;
  std::size_t revision_ = 0;
};

}  // namespace fieldlines
