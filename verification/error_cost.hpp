// The error-cost front of a set of runs, with timings a referee accepts: each run's CPU time is either the range of
// its repeats or one time widened by a measured relative spread, and a run is off the front only when another is
// more accurate beyond the two errors' bands (the one rule, mpm/analysis/verdict.hpp) and faster beyond that range;
// one more accurate or faster only within them is a tie, named, not a verdict.
#pragma once
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "mpm/analysis/verdict.hpp"

namespace verification {

/// How many more times each run of an error-cost front is run, interleaved with the others, for its CPU-time range.
constexpr int timing_repeats = 5;

/// One run of a front: its error and its CPU time, median and range over its repeats (one time: low = median,
/// high = median x (1 + spread)).
struct CostPoint {
  std::string label;
  double error = 0.0;
  double error_band = 0.0;  ///< the error's band (the one rule): two errors within their bands together are a tie
  bool stopped = false;
  bool failed = false;      ///< the run finished no better than a flat line: two failed runs are not compared
  double cpu = 0.0, cpu_low = 0.0, cpu_high = 0.0;  ///< seconds: median, fastest, slowest
  int repeats = 1;
  bool on_front = false;
  std::string dominated_by, ties;  ///< who beats it clearly; who would beat it but for the timing spread
};

/// A point from its CPU times: `times` holds its repeats (two or more), or one time widened by `spread`; `error` with
/// its band and the run's ending.
inline CostPoint cost_point(const std::string& label, double error, bool stopped, std::vector<double> times, double spread,
                            double error_band = 0.0, bool failed = false) {
  CostPoint point;
  point.label = label, point.error = error, point.stopped = stopped, point.error_band = error_band, point.failed = failed;
  std::sort(times.begin(), times.end());
  point.repeats = static_cast<int>(times.size());
  point.cpu = times[times.size() / 2], point.cpu_low = times.front();
  point.cpu_high = times.size() > 1 ? times.back() : times.front() * (1.0 + spread);
  return point;
}

/// The largest relative spread, slowest / fastest - 1, over sets of repeated times (0 if none is repeated).
inline double largest_spread(const std::vector<std::vector<double>>& repeats) {
  double spread = 0.0;
  for (const auto& times : repeats)
    if (times.size() > 1)
      spread = std::max(spread, *std::max_element(times.begin(), times.end()) / *std::min_element(times.begin(), times.end()) - 1.0);
  return spread;
}

/// Marks each finished point on or off the front: off when another finished one is more accurate beyond their bands
/// (mpm::judge) and clearly faster (repeated: its slowest repeat below this one's fastest; single: its time times
/// 1 + spread below this one's), and names in `ties` those faster and more accurate where one of the two is within its
/// band or spread only. Two failed runs are not compared (the one rule).
inline void mark_front(std::vector<CostPoint>& points, double spread) {
  for (auto& e : points) {
    e.dominated_by.clear(), e.ties.clear();
    for (const auto& o : points) {
      if (&o == &e || o.stopped || e.stopped || (o.failed && e.failed)) continue;
      const mpm::Outcome accurate = mpm::judge({o.error, o.error_band, mpm::Ending::done}, mpm::Side::below,
                                               {e.error, e.error_band, mpm::Ending::done});
      if (accurate == mpm::Outcome::fails) continue;
      const bool clearly = o.repeats > 1 ? o.cpu_high < e.cpu_low : o.cpu * (1.0 + spread) < e.cpu;
      std::string* list = clearly && accurate == mpm::Outcome::holds ? &e.dominated_by : o.cpu < e.cpu ? &e.ties : nullptr;
      if (list) *list += (list->empty() ? "" : ", ") + o.label;
    }
    e.on_front = !e.stopped && e.dominated_by.empty();
  }
}

}  // namespace verification

#ifndef DOCTEST_CONFIG_DISABLE
#include <doctest/doctest.h>

TEST_CASE("error-cost front: off it only when beaten beyond the timing spread, a tie otherwise") {
  using verification::cost_point;
  // repeated: B beats A by error and by its whole range of times; C is more accurate than B and faster by its
  // median only, its slowest repeat above B's fastest: a tie, and B stays on the front
  std::vector<verification::CostPoint> repeated{cost_point("A", 1.0, false, {1.1, 1.0, 1.05}, 0.0),
                                                cost_point("B", 0.5, false, {0.6, 0.5, 0.55}, 0.0),
                                                cost_point("C", 0.4, false, {0.5, 0.62, 0.54}, 0.0)};
  CHECK(repeated[0].cpu == 1.05);
  CHECK(repeated[0].cpu_low == 1.0);
  CHECK(repeated[0].cpu_high == 1.1);
  verification::mark_front(repeated, 0.0);
  CHECK(!repeated[0].on_front);
  CHECK(repeated[0].dominated_by == "B, C");
  CHECK(repeated[1].on_front);
  CHECK(repeated[1].ties == "C");
  CHECK(repeated[2].on_front);
  // single timings widened by a spread of 10 %: 1.9 x 1.1 is not below 2.0 (a tie), 1.5 x 1.1 is (dominated); a
  // stopped run is neither on the front nor beats any other
  std::vector<verification::CostPoint> single{cost_point("D", 2.0, false, {2.0}, 0.1), cost_point("E", 1.9, false, {1.9}, 0.1),
                                              cost_point("F", 1.8, false, {1.5}, 0.1), cost_point("G", 0.1, true, {0.1}, 0.1)};
  CHECK(single[0].cpu_high == doctest::Approx(2.2));
  verification::mark_front(single, 0.1);
  CHECK(single[0].dominated_by == "F");
  CHECK(single[0].ties == "E");
  CHECK(single[1].dominated_by == "F");
  CHECK(single[2].on_front);
  CHECK(!single[3].on_front);
  CHECK(verification::largest_spread({{1.0, 1.2}, {2.0}, {3.0, 3.3, 3.1}}) == doctest::Approx(0.2));
  // errors within their bands: H is faster beyond the spread but not more accurate beyond the bands, a tie; two
  // failed runs are not compared
  std::vector<verification::CostPoint> banded{cost_point("H", 1.00, false, {1.0}, 0.1, 0.02), cost_point("I", 1.03, false, {2.0}, 0.1, 0.02),
                                              cost_point("J", 0.5, false, {0.1}, 0.1, 0.0, true), cost_point("K", 0.9, false, {0.5}, 0.1, 0.0, true)};
  verification::mark_front(banded, 0.1);
  CHECK(banded[1].dominated_by == "J, K");  // J and K failed, I did not: compared, both more accurate and faster
  CHECK(banded[1].ties == "H");
  CHECK(banded[3].dominated_by.empty());  // K and J both failed: not compared
  CHECK(banded[3].on_front);
}
#endif
