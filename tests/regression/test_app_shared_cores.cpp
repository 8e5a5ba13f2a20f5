// Issue 12: with both cores busy, a run with 2 threads was 7-20x slower than with 1 thread
// (libgomp threads spinning at every barrier hold the core their partner needs). Issue 13:
// slamsph's own threads (core/parallel.cpp) sleep instead of spinning and a run's loops use
// only the CPUs other programs leave free. This test loads the two CPUs the test may use
// with one busy process each, runs the same short case with 1 and with 2 threads pinned to
// those CPUs, and requires 2 threads to take less than 1.5x the time of 1 thread (libgomp
// spinning: ~10x; libgomp passive: ~1.7-2.5x; sleeping at once but keeping both threads:
// 1.4-1.9x, docs/validation.md §6 "Threads").
#include <gtest/gtest.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const char* kCase =
    "schema_version = 1\n"
    "name = \"shared_cores\"\n"
    "[numerics]\n"
    "dx = 0.0125\n"
    "end_time = 10.0\n"
    "[numerics.domain]\n"
    "min = [-0.5, -0.5]\n"
    "max = [1.5, 1.5]\n"
    "[fluid]\n"
    "sound_speed = 20.0\n"
    "[[fluid.block]]\n"
    "min = [0.0, 0.0]\n"
    "max = [0.5, 0.5]\n"
    "[[body]]\n"
    "name = \"tank\"\n"
    "kind = \"rigid_fixed\"\n"
    "[body.shape]\n"
    "type = \"tank\"\n"
    "min = [0.0, 0.0]\n"
    "max = [1.0, 1.0]\n";

// A child process that spins on one CPU until killed.
pid_t busy_on(int cpu) {
  const pid_t pid = fork();
  if (pid == 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    sched_setaffinity(0, sizeof set, &set);
    volatile unsigned long x = 0;
    for (;;) x = x + 1;
  }
  return pid;
}

// Wall seconds of a 300-step run; with `out`, the run writes its results there (summary.json).
double run_seconds(const fs::path& dir, const std::string& cpus, int threads,
                   const std::string& out = "") {
  const std::string where = out.empty() ? " --no-output" : " --overwrite --out '" + out + "'";
  const std::string cmd = "cd '" + dir.string() + "' && env -u SLAMSPH_SPIN_US " + "taskset -c " +
                          cpus + " '" + SLAMSPH_BINARY + "' run case.toml" + where +
                          " --quiet --max-steps 300 --threads " + std::to_string(threads);
  const auto t0 = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(SharedCores, TwoThreadsOnBusyCoresTakeLessThanOneAndAHalfTimesOneThread) {
  if (std::system("command -v taskset >/dev/null 2>&1") != 0) GTEST_SKIP() << "no taskset";
  cpu_set_t mask;
  CPU_ZERO(&mask);
  ASSERT_EQ(sched_getaffinity(0, sizeof mask, &mask), 0);
  std::vector<int> cpus;
  for (int c = 0; c < CPU_SETSIZE && cpus.size() < 2; ++c)
    if (CPU_ISSET(c, &mask)) cpus.push_back(c);
  if (cpus.size() < 2) GTEST_SKIP() << "needs two CPUs";
  const std::string list = std::to_string(cpus[0]) + "," + std::to_string(cpus[1]);

  const fs::path dir = fs::temp_directory_path() / ("slamsph_shared_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml") << kCase;
  const pid_t a = busy_on(cpus[0]), b = busy_on(cpus[1]);
  ASSERT_GT(a, 0);
  ASSERT_GT(b, 0);
  // Alternate and keep the best of two, so one unlucky moment on a shared machine does not
  // decide the outcome.
  double t1 = 1e30, t2 = 1e30;
  for (int rep = 0; rep < 2; ++rep) {
    t1 = std::min(t1, run_seconds(dir, list, 1));
    t2 = std::min(t2, run_seconds(dir, list, 2));
  }
  // The run saw the busy CPUs and put loops on one thread (ThreadPool::threads_now): without
  // the adaptation, 2 threads next to two busy processes were 1.4-1.9x one thread (the
  // timing above only catches collapse-scale spinning on this short case).
  run_seconds(dir, list, 2, (dir / "out").string());
  std::ifstream summary(dir / "out" / "summary.json");
  std::stringstream text;
  text << summary.rdbuf();
  const std::string key = "\"loops_on_fewer_threads\": ";
  const std::size_t at = text.str().find(key);
  ASSERT_NE(at, std::string::npos) << text.str();
  const long reduced = std::stol(text.str().substr(at + key.size()));
  kill(a, SIGKILL);
  kill(b, SIGKILL);
  waitpid(a, nullptr, 0);
  waitpid(b, nullptr, 0);
  fs::remove_all(dir);
  std::printf("busy cores: 1 thread %.2f s, 2 threads %.2f s (ratio %.2f)\n", t1, t2, t2 / t1);
  EXPECT_LT(t2, 1.5 * t1) << "2 threads on busy cores collapse (threads spinning? not adapting?)";
  EXPECT_GT(reduced, 0) << "2 threads next to two busy processes never ran a loop on fewer";
}

}  // namespace
