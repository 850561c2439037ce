// Independent jobs (shear loads, calibration design runs) on a few threads.
#pragma once
#include <algorithm>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace colza {

// Calls job(k) for k = 0 .. count-1 on up to `threads` threads (the caller's thread is one
// of them). Jobs must be independent; each writes only its own results. The first
// exception stops the handing out of further jobs and is rethrown after all threads end.
template <class Job>
void run_concurrently(std::size_t count, int threads, Job&& job) {
  std::mutex mutex;
  std::exception_ptr failure;
  std::size_t next = 0;
  auto worker = [&]() {
    while (true) {
      std::size_t k;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (next >= count || failure) return;
        k = next++;
      }
      try {
        job(k);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  const int n = std::max(1, std::min<int>(threads, static_cast<int>(count)));
  std::vector<std::thread> pool;
  for (int j = 1; j < n; ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace colza
