// Crash safety of the CLI's saves: `fieldlines train -o FILE` and `fieldlines autolabel -o
// PROJECT` are killed with SIGKILL at random (seeded) moments, many times. After every kill the
// file must be the old version byte for byte or a complete new one its loader accepts.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "bad_input_support.hpp"
#include "fieldlines/atomic_file.hpp"
#include "fieldlines/dataset.hpp"
#include "fieldlines/thresholds_file.hpp"

namespace fs = std::filesystem;
using fieldlines::test::BadInputTest;
using fieldlines::test::cli_path;
using fieldlines::test::read_text;

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

// Hidden temporary files a killed save leaves beside `file` (".<name>.tmpNNN"): the only debris
// allowed, never a damaged `file`.
int temporaries(const fs::path& file) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(file.parent_path()))
    if (e.path().filename().string().rfind("." + file.filename().string() + ".tmp", 0) == 0) ++n;
  return n;
}

// Kills `args` kKills times, before each run `file` holding `old`: half the kills at uniform
// random moments of the whole run (0 to 1.2 x its length), half in its last 15 % where the save
// happens. `accepts` must load a complete new file without throwing.
template <typename Accepts>
Outcome kill_many_times(const std::vector<std::string>& args, const fs::path& file, const std::string& old,
                        Accepts accepts) {
  const double full = full_run_seconds(args);
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> anywhere(0.0, 1.2 * full), near_end(0.85 * full, 1.05 * full);
  Outcome o;
  for (int k = 0; k < kKills; ++k) {
    fieldlines::write_file_atomically(file, old);
    const int temps_before = temporaries(file);
    const double at = (k % 2 == 0) ? anywhere(rng) : near_end(rng);
    const pid_t pid = spawn(args);
    std::this_thread::sleep_for(std::chrono::duration<double>(at));
    ::kill(pid, SIGKILL);
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
  EXPECT_EQ(o.old_kept + o.new_complete, kKills);
  // The kill moments span the whole run, so both outcomes must have occurred.
  EXPECT_GT(o.old_kept, 0);
  EXPECT_GT(o.new_complete, 0);
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
  EXPECT_EQ(o.old_kept + o.new_complete, kKills);
  EXPECT_GT(o.old_kept, 0);
  EXPECT_GT(o.new_complete, 0);
}

}  // namespace
