#include "app/cli/progress.hpp"

#include <unistd.h>

#include <algorithm>

namespace fieldlines::cli {
namespace {

using Mode = ProgressParams::Mode;

Mode resolve(Mode requested, std::size_t total, std::FILE* out) {
  if (requested != Mode::Auto) return requested;
  if (total <= 1) return Mode::Off;
  return isatty(fileno(out)) ? Mode::Bar : Mode::Lines;
}

std::string format_seconds(double s) {
  char buf[32];
  if (s < 60) std::snprintf(buf, sizeof buf, "%.0fs", s);
  else std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  return buf;
}

}  // namespace

Progress::Progress(std::string label, std::size_t total, std::FILE* out, ProgressParams params)
    : label_(std::move(label)), total_(total), out_(out), params_(params),
      mode_(resolve(params.mode, total, out)) {
  std::lock_guard lock(mutex_);
  draw_locked();
}

Progress::~Progress() { finish(); }

void Progress::advance(std::size_t n) {
  std::lock_guard lock(mutex_);
  done_ = std::min(total_, done_ + n);
  draw_locked();
}

void Progress::message(std::string_view line) {
  std::lock_guard lock(mutex_);
  clear_locked();
  std::fprintf(out_, "%.*s\n", static_cast<int>(line.size()), line.data());
  if (!finished_) draw_locked();
  std::fflush(out_);
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (mode_ == Mode::Bar) {
    last_draw_ = {};  // force the final state
    draw_locked();
    std::fputc('\n', out_);
    std::fflush(out_);
  }
}

void Progress::clear_locked() {
  if (mode_ == Mode::Bar && !finished_) std::fputs("\r\033[2K", out_);
}

void Progress::draw_locked() {
  if (finished_ || mode_ == Mode::Off || total_ == 0) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (mode_ == Mode::Lines) {
    // One line per 10% step (and the first item), so a log gets about ten lines per batch.
    const std::size_t decile = done_ * 10 / total_;
    if (done_ == 0 || decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(out_, "%s: %zu/%zu (%zu%%) %s\n", label_.c_str(), done_, total_, done_ * 100 / total_,
                 format_seconds(elapsed).c_str());
    std::fflush(out_);
    return;
  }
  // Bar: redraw at most ~20 times a second; the terminal is slower than the detector.
  if (done_ != total_ && now - last_draw_ < std::chrono::milliseconds(50)) return;
  last_draw_ = now;
  const int filled = static_cast<int>(done_ * static_cast<std::size_t>(params_.width) / total_);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(static_cast<std::size_t>(params_.width), '.');
  std::string eta;
  if (done_ > 0 && done_ < total_)
    eta = " eta " + format_seconds(elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_));
  std::fprintf(out_, "\r\033[2K%s [%s] %zu/%zu %s%s", label_.c_str(), bar.c_str(), done_, total_,
               format_seconds(elapsed).c_str(), eta.c_str());
  std::fflush(out_);
}

}  // namespace fieldlines::cli
