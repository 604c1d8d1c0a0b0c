#pragma once
// A progress report on stderr for batch commands, safe to call from worker threads.
//
// On a terminal it is one bar redrawn in place; otherwise (a log file, a pipe, a test) it prints
// a plain line at most every 10%, so logs stay readable. Nothing is shown for a single item.
// Messages (e.g. a bad file) go through message() so they never get mixed into the bar.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>
#include <string_view>

namespace fieldlines::cli {

struct ProgressParams {
  enum class Mode { Auto, Bar, Lines, Off };
  Mode mode = Mode::Auto;  // Auto: Bar on a terminal, Lines otherwise, Off for <= 1 item
  int width = 30;          // bar width in characters
};

class Progress {
 public:
  Progress(std::string label, std::size_t total, std::FILE* out = stderr, ProgressParams params = {});
  ~Progress();  // finishes the bar line
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::size_t n = 1);
  // Prints `line` (a newline is added) on its own line, then redraws the bar.
  void message(std::string_view line);
  void finish();

  ProgressParams::Mode mode() const { return mode_; }

 private:
  void draw_locked();
  void clear_locked();

  std::mutex mutex_;
  std::string label_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::size_t last_decile_ = 0;
  std::FILE* out_;
  ProgressParams params_;
  ProgressParams::Mode mode_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace fieldlines::cli
