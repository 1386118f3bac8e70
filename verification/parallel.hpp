// Runs the independent cases of a verification suite on the machine's cores, never more threads
// than cores at once (cases x threads <= cores), and says on the terminal when each long case and
// each group of cases has finished.
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <ctime>
#include <map>
#include <mutex>
#include <string>
#include <exception>
#include <thread>
#include <vector>

#include "mpm/core/parallel.hpp"

namespace verification {

/// CPU seconds of the calling thread: a case runs on one thread, so its CPU time, unlike its wall time, hardly moves
/// with the other processes on the cores.
inline double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

/// The cores a suite uses: --threads N among its arguments (removed from them), or every core this
/// process may run on (as nproc counts them). \returns 0 for a bad value.
inline unsigned suite_threads(int& argc, char** argv) {
  unsigned threads = static_cast<unsigned>(mpm::available_cores());
  for (int k = 1; k + 1 < argc; ++k)
    if (std::string(argv[k]) == "--threads") {
      const std::string value = argv[k + 1];
      threads = value.find_first_not_of("0123456789") == std::string::npos && value.size() < 5 ? std::stoul("0" + value) : 0;
      for (int j = k; j + 2 < argc; ++j) argv[j] = argv[j + 2];
      argc -= 2;
      break;
    }
  return threads;
}

/// A suite's part: 1 for "--part figures", 2 for "--part studies" (removed from argv); 0 when absent or unknown.
inline int suite_part(int& argc, char** argv) {
  for (int k = 1; k + 1 < argc; ++k)
    if (std::string(argv[k]) == "--part") {
      const std::string value = argv[k + 1];
      for (int j = k; j + 2 < argc; ++j) argv[j] = argv[j + 2];
      argc -= 2;
      return value == "figures" ? 1 : value == "studies" ? 2 : 0;
    }
  return 0;
}

/// The group of a case, for the progress lines: its name without the last "_part" (dyka_lme_npc_640 ->
/// dyka_lme_npc, the mesh sweep of LME with the predictor-corrector).
inline std::string case_group(const std::string& name) {
  const auto cut = name.rfind('_');
  return cut == std::string::npos ? name : name.substr(0, cut);
}

/// Calls task(k, threads) for every case k: first the `wide` ones, one at a time on all `cores`; then
/// the others, `cores` at a time on one thread each, taking the next k as they free up (list the most
/// expensive first). The suites mark no case wide: measured on the shared 2-core development machine
/// (load ~14), a run on two threads took 2-4 times as long as on one, its threads waiting for each
/// other at every parallel loop while other processes held the cores; one thread per case is robust.
template <class Task>
void run_cases(const std::string& suite, const std::vector<std::string>& names, const std::vector<bool>& wide,
               unsigned cores, Task task) {
  const auto start = std::chrono::steady_clock::now();
  std::map<std::string, int> left;
  for (const auto& name : names) ++left[case_group(name)];
  std::mutex lock;
  std::size_t done = 0;
  // A line for every group when its last case ends, and for every case of 10 s or more (the groups all
  // hold a large case, and the largest run first, so the group lines alone come in a burst at the end).
  auto finished = [&](std::size_t k, double case_seconds) {
    std::lock_guard<std::mutex> guard(lock);
    ++done;
    if (case_seconds >= 10.0)
      std::printf("figures: %s: %s took %.0f s (%zu of %zu cases done, %.0f s)\n", suite.c_str(), names[k].c_str(), case_seconds,
                  done, names.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()),
          std::fflush(stdout);
    const std::string group = case_group(names[k]);
    if (--left[group] == 0)
      std::printf("figures: %s: %s done (%.0f s)\n", suite.c_str(), group.c_str(),
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()),
          std::fflush(stdout);
  };
  std::vector<std::size_t> narrow;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (!wide[k]) {
      narrow.push_back(k);
      continue;
    }
    task(k, static_cast<int>(cores));
    std::printf("figures: %s: %s done on %u threads (%.0f s)\n", suite.c_str(), names[k].c_str(), cores,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    std::fflush(stdout);
    finished(k, 0.0);
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr first_error;  // a case that threw (a scene that does not read): rethrown here, after the others
  auto worker = [&] {
    for (std::size_t n; (n = next++) < narrow.size();) {
      const auto case_start = std::chrono::steady_clock::now();
      try {
        task(narrow[n], 1);
      } catch (...) {
        std::lock_guard<std::mutex> guard(lock);
        if (!first_error) first_error = std::current_exception();
        next = narrow.size();  // no new case starts
        return;
      }
      finished(narrow[n], std::chrono::duration<double>(std::chrono::steady_clock::now() - case_start).count());
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < cores; ++t) threads.emplace_back(worker);
  for (auto& thread : threads) thread.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace verification
