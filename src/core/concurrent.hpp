// Independent jobs (shear loads, calibration design runs) on a few threads.
#pragma once
#include <algorithm>
#include <cstddef>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/interrupt.hpp"

namespace colza {

// Calls job(k) for k = 0 .. count-1 on up to `threads` threads (the caller's thread is one
// of them). Jobs must be independent; each writes only its own results. The first
// exception stops the handing out of further jobs and is rethrown after all threads end.
// Every job runs with the caller's OpenMP thread count (--threads): a new std::thread would
// otherwise start from OpenMP's default (one per core), so with --jobs 2 each extra job ran
// its force loop on all cores, oversubscribing them (a 1263-sphere shear load went from 2 s
// to > 5 min on 2 busy cores, spinning at the OpenMP barriers).
// `threads_per_job` > 0 gives each job that many OpenMP threads instead of the caller's.
// After Ctrl-C or SIGTERM no job starts: the next one throws Interrupted (core/interrupt.hpp),
// so jobs that never step (an analytic calibration model) stop as promptly as DEM runs.
template <class Job>
void run_concurrently(std::size_t count, int threads, Job&& job, int threads_per_job = 0) {
  std::mutex mutex;
  std::exception_ptr failure;
  std::size_t next = 0;
#ifdef _OPENMP
  const int omp_threads = threads_per_job > 0 ? threads_per_job : omp_get_max_threads();
#else
  (void)threads_per_job;
#endif
  auto worker = [&]() {
#ifdef _OPENMP
    omp_set_num_threads(omp_threads);
#endif
    while (true) {
      std::size_t k;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (next >= count || failure) return;
        k = next++;
      }
      try {
        throw_if_interrupted();
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
#ifdef _OPENMP
  const int caller_threads = omp_get_max_threads();  // the caller's thread is a worker too:
#endif
  worker();
#ifdef _OPENMP
  omp_set_num_threads(caller_threads);  // give it back its own count (threads_per_job may differ)
#endif
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

// The OpenMP threads a run started here would use: 1 inside a parallel region (no nested
// teams) or without OpenMP.
inline int worker_threads_here() {
#ifdef _OPENMP
  return omp_in_parallel() ? 1 : omp_get_max_threads();
#else
  return 1;
#endif
}

// A value made once per key (a settled packing per seed, say): callers asking for different
// keys make theirs at the same time; callers asking for the same key wait for the first,
// which makes it. If making throws, the next caller tries again.
template <class Key, class Value>
class OncePerKey {
 public:
  template <class Make>
  Value get(const Key& key, Make&& make) {
    std::shared_ptr<Slot> slot;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto& s = slots_[key];
      if (!s) s = std::make_shared<Slot>();
      slot = s;
    }
    std::lock_guard<std::mutex> lock(slot->mutex);
    if (!slot->value) slot->value = make();
    return *slot->value;
  }

 private:
  struct Slot {
    std::mutex mutex;
    std::optional<Value> value;
  };
  std::mutex mutex_;
  std::map<Key, std::shared_ptr<Slot>> slots_;
};

}  // namespace colza
