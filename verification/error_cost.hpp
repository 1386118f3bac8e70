// The error-cost front of a set of runs, with timings a referee accepts: each run's CPU time is either the range of
// its repeats or one time widened by a measured relative spread, and a run is off the front only when another is
// more accurate and faster beyond that range; one faster only within it is a tie, named, not a verdict.
#pragma once
#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace verification {

/// How many more times each run of an error-cost front is run, interleaved with the others, for its CPU-time range.
constexpr int timing_repeats = 5;

/// One run of a front: its error and its CPU time, median and range over its repeats (one time: low = median,
/// high = median x (1 + spread)).
struct CostPoint {
  std::string label;
  double error = 0.0;
  bool stopped = false;
  double cpu = 0.0, cpu_low = 0.0, cpu_high = 0.0;  ///< seconds: median, fastest, slowest
  int repeats = 1;
  bool on_front = false;
  std::string dominated_by, ties;  ///< who beats it clearly; who would beat it but for the timing spread
};

/// A point from its CPU times: `times` holds its repeats (two or more), or one time widened by `spread`.
inline CostPoint cost_point(const std::string& label, double error, bool stopped, std::vector<double> times, double spread) {
  CostPoint point;
  point.label = label, point.error = error, point.stopped = stopped;
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

/// Marks each finished point on or off the front: off when another finished one is more accurate and clearly faster
/// (repeated: its slowest repeat below this one's fastest; single: its time times 1 + spread below this one's), and
/// names in `ties` those more accurate and faster within the spread only.
inline void mark_front(std::vector<CostPoint>& points, double spread) {
  for (auto& e : points) {
    e.dominated_by.clear(), e.ties.clear();
    for (const auto& o : points)
      if (&o != &e && !o.stopped && !e.stopped && o.error < e.error) {
        const bool clearly = o.repeats > 1 ? o.cpu_high < e.cpu_low : o.cpu * (1.0 + spread) < e.cpu;
        std::string* list = clearly ? &e.dominated_by : o.cpu < e.cpu ? &e.ties : nullptr;
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
}
#endif
