// Crash safety of the CLI's saves: `fieldlines train -o FILE` and `fieldlines autolabel -o
// PROJECT` are killed with SIGKILL at random (seeded) moments, many times. After every kill the
// file must be the old version byte for byte or a complete new one its loader accepts.
// ctest-label: slow

#include <fcntl.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "bad_input_support.hpp"
#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "save_watch.hpp"

namespace fs = std::filesystem;
using fieldlines::test::BadInputTest;
using fieldlines::test::cli_path;
using fieldlines::test::read_text;
using fieldlines::test::temporaries;
using fieldlines::test::wait_for_creation;

namespace {

constexpr int kKills = 40;

// Starts the CLI with stdout/stderr on /dev/null; returns its pid.
pid_t spawn(const std::vector<std::string>& args) {
  std::vector<std::string> argv_s = {cli_path().string()};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : argv_s) argv.push_back(s.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

// Wall time of one full run, to spread the kill moments over it.
double full_run_seconds(const std::vector<std::string>& args) {
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  ::waitpid(spawn(args), &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the uninterrupted run failed";
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Outcome {
  int old_kept = 0, new_complete = 0, finished = 0;
  int mid_save = 0;  // kills that left a temporary file: they landed inside the save itself
};

// Kills `args` kKills times, before each run `file` holding `old`, cycling three kinds of
// moment: uniform from 0 to 2x the length of a full run; from 0.8x to 1.2x, around the save;
// and 0-500 us after the save's temporary file appears (inotify), inside the save itself.
// Last, one uninterrupted run must replace `old` with a complete new file. `accepts` must load a
// complete new file without throwing.
template <typename Accepts>
Outcome kill_many_times(const std::vector<std::string>& args, const fs::path& file, const std::string& old,
                        Accepts accepts) {
  const double full = full_run_seconds(args);
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> anywhere(0.0, 2.0 * full), near_end(0.8 * full, 1.2 * full);
  std::uniform_int_distribution<int> in_save_us(0, 500);
  const std::string temp_prefix = fieldlines::temporary_prefix(file);
  Outcome o;
  for (int k = 0; k < kKills; ++k) {
    fieldlines::write_file_atomically(file, old);
    const int temps_before = temporaries(file);
    // Watch from here on, so the temporary file of our own write above is not an event.
    const int watch_fd = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    EXPECT_GE(watch_fd, 0);
    EXPECT_GE(::inotify_add_watch(watch_fd, file.parent_path().c_str(), IN_CREATE), 0);
    const pid_t pid = spawn(args);
    switch (k % 3) {
      case 0: std::this_thread::sleep_for(std::chrono::duration<double>(anywhere(rng))); break;
      case 1: std::this_thread::sleep_for(std::chrono::duration<double>(near_end(rng))); break;
      default:
        if (wait_for_creation(watch_fd, temp_prefix, std::chrono::duration<double>(10 * full + 5)))
          std::this_thread::sleep_for(std::chrono::microseconds(in_save_us(rng)));
        break;
    }
    ::kill(pid, SIGKILL);
    ::close(watch_fd);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (WIFEXITED(status)) ++o.finished;
    if (temporaries(file) > temps_before) ++o.mid_save;
    const std::string now = read_text(file);
    if (now == old) {
      ++o.old_kept;
      continue;
    }
    EXPECT_NO_THROW(accepts(file)) << "kill " << k << " left a file that does not load:\n" << now.substr(0, 400);
    ++o.new_complete;
  }
  fieldlines::write_file_atomically(file, old);
  EXPECT_GT(full_run_seconds(args), 0.0);
  EXPECT_NE(read_text(file), old);
  EXPECT_NO_THROW(accepts(file));
  return o;
}

using CrashSafety = BadInputTest;

TEST_F(CrashSafety, TrainKilledAnywhereLeavesOldOrCompleteThresholds) {
  const fs::path data = path("data.csv");
  fieldlines::write_reference_csv(data, fieldlines::test::labelled_rows(3000));
  const fs::path out = path("robot.json");
  fieldlines::ThresholdsFile previous;
  previous.provenance["note"] = "the old version";
  fieldlines::save_thresholds_file(path("old.json"), previous);
  const std::string old = read_text(path("old.json"));
  const Outcome o = kill_many_times({"train", data.string(), "--quiet", "--iterations", "60", "-o", out.string()}, out,
                                    old, [](const fs::path& f) { (void)fieldlines::load_thresholds_file(f); });
  std::printf("train: %d kills, old kept %d, new complete %d, finished before the kill %d, killed mid-save %d\n",
              kKills, o.old_kept, o.new_complete, o.finished, o.mid_save);
  // Kills before the save happened (a run takes tens of milliseconds at least).
  EXPECT_GT(o.old_kept, 0);
}

TEST_F(CrashSafety, AutolabelKilledAnywhereLeavesOldOrCompleteProject) {
  const fs::path set = synth_set("set");
  const fs::path out = path("labels.json");
  project("old.json", 12);
  const std::string old = read_text(path("old.json"));
  const Outcome o = kill_many_times({"autolabel", set.string(), "--quiet", "-o", out.string()}, out, old,
                                    [](const fs::path& f) {
                                      const auto p = fieldlines::Project::load(f);
                                      if (p.images.size() != 2) throw std::runtime_error("not the new project");
                                    });
  std::printf("autolabel: %d kills, old kept %d, new complete %d, finished before the kill %d, killed mid-save %d\n",
              kKills, o.old_kept, o.new_complete, o.finished, o.mid_save);
  EXPECT_GT(o.old_kept, 0);
}

}  // namespace
