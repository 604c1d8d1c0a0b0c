#pragma once
// The studio's one kind of background work (training, detection, video import): a std::jthread
// that reports progress and ends with exactly one result or error, both handed to the UI thread
// through a MessageQueue drained once per frame. The UI never waits on the worker, and the worker
// never touches UI state, so no lock is held across a frame.
//
// Lifetime: start() on a running job requests a stop and joins it first (its queued messages
// are dropped); destroying the job does the same, so no worker outlives its job.
#include <exception>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include "gui/model/message_queue.hpp"

namespace fieldlines::studio {

// How a job ended: its result, or the reason it failed (what its work threw).
template <typename Result>
class Outcome {
 public:
  static Outcome success(Result result) { return Outcome(std::move(result)); }
  static Outcome failure(std::string reason) { return Outcome(Failure{std::move(reason)}); }

  bool ok() const { return std::holds_alternative<Result>(value_); }
  const Result& value() const { return std::get<Result>(value_); }        // only when ok()
  const std::string& error() const { return std::get<Failure>(value_).reason; }  // only when !ok()

 private:
  struct Failure {
    std::string reason;
  };
  explicit Outcome(std::variant<Result, Failure> value) : value_(std::move(value)) {}
  std::variant<Result, Failure> value_;
};

template <typename Progress, typename Result>
class Job {
 public:
  using Report = std::function<void(Progress)>;
  // Runs on the worker: checks `stop` as often as it can, calls `report` for each step, returns
  // the result. Whatever it throws becomes the job's error.
  using Work = std::function<Result(std::stop_token stop, const Report& report)>;

  Job() = default;
  Job(const Job&) = delete;  // the worker refers to this job's queue
  Job& operator=(const Job&) = delete;

  void start(Work work) {
    worker_ = std::jthread();  // a running worker is asked to stop and joined (jthread's move)
    queue_.drain();
    outcome_.reset();
    running_ = true;
    worker_ = std::jthread([this, work = std::move(work)](std::stop_token stop) {
      const Report report = [this](Progress p) { queue_.push(Message(std::in_place_index<0>, std::move(p))); };
      queue_.push(Message(std::in_place_index<1>, run(work, stop, report)));
    });
  }
  // Asks the worker to stop; it ends (with what its work returns when stopped) at its next check.
  void cancel() { worker_.request_stop(); }
  // True from start() until poll() has taken the outcome.
  bool running() const { return running_; }
  // UI thread, once per frame: the progress reported since the last poll, oldest first; takes the
  // outcome when the worker has ended.
  std::vector<Progress> poll() {
    std::vector<Progress> progress;
    for (Message& m : queue_.drain()) {
      if (m.index() == 0) {
        progress.push_back(std::move(std::get<0>(m)));
      } else {
        outcome_ = std::move(std::get<1>(m));
        running_ = false;
      }
    }
    if (!running_ && worker_.joinable()) worker_.join();  // it has pushed its end: joins at once
    return progress;
  }
  // Blocks until the worker has ended (tests, shutdown); its messages stay queued for poll().
  void wait() {
    if (worker_.joinable()) worker_.join();
  }
  const std::optional<Outcome<Result>>& outcome() const { return outcome_; }

 private:
  using Message = std::variant<Progress, Outcome<Result>>;

  static Outcome<Result> run(const Work& work, std::stop_token stop, const Report& report) {
    try {
      return Outcome<Result>::success(work(std::move(stop), report));
    } catch (const std::exception& e) {
      return Outcome<Result>::failure(e.what());
    } catch (...) {
      return Outcome<Result>::failure("unknown error");
    }
  }

  MessageQueue<Message> queue_;
  bool running_ = false;
  std::optional<Outcome<Result>> outcome_;
  std::jthread worker_;  // last: destroyed (stopped and joined) before the queue it pushes to
};

}  // namespace fieldlines::studio
