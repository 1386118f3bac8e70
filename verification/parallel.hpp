// Runs the independent cases of a verification suite on every core of the machine.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace verification {

/// Calls task(k) for k = 0 .. count-1, each exactly once, on one thread per core. Threads take
/// the next k as they free up, so list the most expensive cases first.
template <class Task>
unsigned run_in_parallel(std::size_t count, Task task) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t k; (k = next++) < count;) task(k);
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < cores; ++t) threads.emplace_back(worker);
  for (auto& thread : threads) thread.join();
  return cores;
}

}  // namespace verification
