// OncePerKey (core/concurrent.hpp): a value is made once per key however many threads ask
// for it at once, and a make that throws is tried again by the next caller.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "core/concurrent.hpp"

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
