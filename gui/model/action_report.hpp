#pragma once
// The one line a form shows after an action: what it did, or why it failed. An action is a
// callable that returns its line; what it throws becomes the failure's line (the form's state is
// the action's to keep unchanged on failure).
#include <exception>
#include <string>
#include <utility>

namespace fieldlines::studio {

class ActionReport {
 public:
  template <typename Action>
  void run(Action&& action) {
    try {
      set(std::forward<Action>(action)(), false);
    } catch (const std::exception& e) {
      set(e.what(), true);
    }
  }
  void set(std::string text, bool failed) {
    text_ = std::move(text);
    failed_ = failed;
  }
  void clear() { set({}, false); }
  const std::string& text() const { return text_; }
  bool failed() const { return failed_; }

 private:
  std::string text_;
  bool failed_ = false;
};

}  // namespace fieldlines::studio
