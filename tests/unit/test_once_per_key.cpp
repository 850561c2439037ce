// OncePerKey (core/concurrent.hpp): a value is made once per key however many threads ask
// for it at once, and a make that throws is tried again by the next caller. At the end,
// run_concurrently: its OpenMP thread counts, and no job starts after Ctrl-C.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "core/concurrent.hpp"
#include "core/interrupt.hpp"

using colza::OncePerKey;

TEST(OncePerKey, MakesEachKeyOnceUnderContention) {
  OncePerKey<int, std::string> cache;
  std::atomic<int> makes[3] = {0, 0, 0};
  std::vector<std::thread> threads;
  std::atomic<int> wrong{0};
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      for (int k = 0; k < 300; ++k) {
        const int key = (k + t) % 3;
        const std::string v = cache.get(key, [&] {
          ++makes[key];
          std::this_thread::yield();
          return "value " + std::to_string(key);
        });
        if (v != "value " + std::to_string(key)) ++wrong;
      }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(wrong.load(), 0);
  for (int key = 0; key < 3; ++key) EXPECT_EQ(makes[key].load(), 1) << key;
}

TEST(OncePerKey, AFailedMakeIsTriedAgain) {
  OncePerKey<std::string, int> cache;
  EXPECT_THROW(cache.get("a", []() -> int { throw std::runtime_error("disk full"); }), std::runtime_error);
  EXPECT_EQ(cache.get("a", [] { return 7; }), 7);
  EXPECT_EQ(cache.get("a", [] { return 8; }), 7);  // made once: the first success stands
}

#ifdef _OPENMP
TEST(RunConcurrently, JobsGetTheirThreadCountAndTheCallerKeepsItsOwn) {
  // The caller's thread works as one of the job threads; a per-job thread count must not
  // stay with it afterwards (it did: every later design run then ran on one thread).
  const int before = omp_get_max_threads();
  omp_set_num_threads(3);
  std::atomic<int> seen[2] = {0, 0};
  colza::run_concurrently(2, 2, [&](std::size_t k) { seen[k] = omp_get_max_threads(); }, 1);
  EXPECT_EQ(seen[0].load(), 1);
  EXPECT_EQ(seen[1].load(), 1);
  EXPECT_EQ(omp_get_max_threads(), 3);
  colza::run_concurrently(2, 2, [&](std::size_t k) { seen[k] = omp_get_max_threads(); });  // the caller's count
  EXPECT_EQ(seen[0].load(), 3);
  EXPECT_EQ(seen[1].load(), 3);
  omp_set_num_threads(before);
}
#endif

TEST(RunConcurrently, StartsNoJobAfterCtrlC) {
  // After SIGINT, run_concurrently starts no job and throws Interrupted, so a calibration
  // whose model never steps (the identity model) stops at the first press, not the second.
  // In a child process: the handlers and the flag they set last for the whole process.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    colza::install_interrupt_handlers();
    std::raise(SIGINT);  // recorded, not fatal
    std::atomic<int> started{0};
    try {
      colza::run_concurrently(4, 2, [&](std::size_t) { ++started; });
    } catch (const colza::Interrupted& e) {
      ::_exit(e.signal_number() == SIGINT && started.load() == 0 ? 0 : 1);
    }
    ::_exit(2);  // not interrupted
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: a job started or the wrong signal; 2: no Interrupted";
}
