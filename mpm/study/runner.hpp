/// \file
/// Runs a study's cases in parallel: `jobs` workers, each taking the next case and running its children one
/// after the other, so that at most `jobs` children run at once (each run on one thread: the cores are not
/// oversubscribed). After each case a progress line on stderr, rewritten in place when stderr is a terminal:
///   case 12/40 done, 3 running, 1 refused, 0 stopped, 0 failed
/// (and ", 2 interrupted" for the runs a stop signal of the study ended).
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <atomic>
#include <exception>
#include <algorithm>
#include <chrono>
#include <functional>
#include <iostream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <ostream>
#include <thread>
#include <vector>

#include "mpm/study/cases.hpp"

namespace mpm::study {

/// The progress line after `finished` of `total` cases, `running` still going, counted by outcome.
inline std::string progress_line(std::size_t finished, std::size_t total, std::size_t running, const std::vector<CaseResult>& results,
                                 const std::vector<bool>& over) {
  std::size_t refused = 0, stopped = 0, failed = 0, interrupted = 0;
  for (std::size_t k = 0; k < results.size(); ++k)
    if (over[k]) {
      refused += results[k].status == "refused", stopped += results[k].status == "stopped";
      failed += results[k].status == "failed", interrupted += results[k].status == "interrupted";
    }
  return "case " + std::to_string(finished) + "/" + std::to_string(total) + " done, " + std::to_string(running) + " running, " +
         std::to_string(refused) + " refused, " + std::to_string(stopped) + " stopped, " + std::to_string(failed) + " failed" +
         (interrupted ? ", " + std::to_string(interrupted) + " interrupted" : "");
}

/// Runs `run_one` on every case with at most `jobs` at once; returns the results in the cases' order. The first
/// exception a case raises (an output that cannot be written) is raised again once the running cases have ended.
inline std::vector<CaseResult> run_cases(const std::vector<Case>& cases, unsigned jobs, const std::function<CaseResult(const Case&)>& run_one,
                                         std::ostream& err) {
  std::vector<CaseResult> results(cases.size());
  std::vector<bool> over(cases.size(), false);
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0, running = 0;
  std::exception_ptr failure;
  std::mutex lock;
  const bool terminal = &err == &std::cerr && ::isatty(2);
  auto work = [&] {
    for (std::size_t k; (k = next++) < cases.size();) {
      {
        std::lock_guard<std::mutex> hold(lock);
        if (failure || io::stop_signal != 0) return;  // after a stop signal, no case starts
        ++running;
      }
      CaseResult result;
      std::exception_ptr raised;
      try {
        result = run_one(cases[k]);
      } catch (...) {
        raised = std::current_exception();
      }
      std::lock_guard<std::mutex> hold(lock);
      results[k] = result, over[k] = true, --running, ++finished;
      if (raised && !failure) failure = raised;
      err << (terminal ? "\r" : "") << progress_line(finished, cases.size(), running, results, over) << (terminal ? "" : "\n") << std::flush;
    }
  };
  std::vector<std::thread> workers;
  for (unsigned k = 0; k < std::max(1u, jobs) && k < cases.size(); ++k) workers.emplace_back(work);
  for (auto& worker : workers) worker.join();
  if (terminal) err << "\n";
  if (failure) std::rethrow_exception(failure);
  return results;
}

TEST_CASE("study runner: every case once, in order, never more than `jobs` at once, progress per case") {
  std::vector<Case> cases(7);
  for (std::size_t k = 0; k < cases.size(); ++k) cases[k].index = k;
  std::atomic<int> now{0}, most{0};
  std::ostringstream err;
  const auto results = run_cases(
      cases, 3,
      [&](const Case& one) {
        const int running = ++now;
        for (int seen = most; running > seen && !most.compare_exchange_weak(seen, running);) {
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        --now;
        CaseResult result;
        result.status = one.index == 2 ? "refused" : "done";
        result.wall_s = static_cast<double>(one.index);
        return result;
      },
      err);
  REQUIRE(results.size() == 7);
  for (std::size_t k = 0; k < 7; ++k) CHECK(results[k].wall_s == static_cast<double>(k));
  CHECK(most <= 3);
  CHECK(err.str().find("case 7/7 done, 0 running, 1 refused, 0 stopped, 0 failed\n") != std::string::npos);
  std::vector<CaseResult> ended(2);
  ended[0].status = "interrupted", ended[1].status = "done";
  CHECK(progress_line(2, 4, 0, ended, {true, true}) == "case 2/4 done, 0 running, 0 refused, 0 stopped, 0 failed, 1 interrupted");
  CHECK_THROWS_AS(run_cases(cases, 2, [](const Case&) -> CaseResult { throw std::runtime_error("disk full"); }, err), std::runtime_error);
}

}  // namespace mpm::study
