#pragma once
// Private: runs independent jobs on several threads. Each job writes only its own slot of
// the caller's output, so the results do not depend on the number of threads or on which
// thread ran what (bit-identical fits, docs/fitting.md).

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace bounce::analysis::detail {

/// The threads to use: `requested`, or every core for 0; never more than `jobs`.
inline unsigned worker_count(unsigned requested, std::size_t jobs) {
  unsigned n = requested != 0 ? requested : std::max(1U, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::min<std::size_t>(n, std::max<std::size_t>(jobs, 1)));
}

/// job(i, worker) for i in [0, count), handed out one at a time (jobs differ in cost); the
/// first exception a job throws stops the handing out and is rethrown here.
template <class Job>
void parallel_for(std::size_t count, unsigned threads, const Job& job) {
  const unsigned workers = worker_count(threads, count);
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&](unsigned worker) {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        job(i, worker);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = count;
      }
    }
  };
  if (workers <= 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (unsigned w = 1; w < workers; ++w) pool.emplace_back(work, w);
    work(0);
    for (auto& t : pool) t.join();
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace bounce::analysis::detail
