// The Dyka-bar part of `make figures`: runs every case, in parallel on the machine's cores, and
// writes the data of each figure as CSV into DATA_DIR, plus summary.csv with one line per case.
//
//   build/bin/dyka_suite DATA_DIR SCENE
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <thread>

#include "verification/dyka_case.hpp"

namespace {

struct CaseSpec {
  std::string name;
  std::vector<std::string> overrides;
};

std::vector<CaseSpec> all_cases() {
  std::vector<CaseSpec> cases;
  cases.push_back({"velocity_A_linear_fe_40", {"grid.cells=[40]"}});
  return cases;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: dyka_suite DATA_DIR SCENE\n");
    return 2;
  }
  const std::string folder = argv[1], scene = argv[2];
  const auto cases = all_cases();
  std::vector<verification::DykaResult> results(cases.size());
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t k; (k = next++) < cases.size();) {
      results[k] = verification::run_dyka(scene, cases[k].name, cases[k].overrides);
      verification::write_series(results[k], folder + "/" + cases[k].name + ".csv");
    }
  };
  std::vector<std::thread> threads;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  for (unsigned t = 0; t < cores; ++t) threads.emplace_back(worker);
  for (auto& thread : threads) thread.join();

  std::ofstream summary(folder + "/summary.csv");
  summary << std::setprecision(8) << "name,cells,rms,rms_over_v0,largest_speed,steps,wall_seconds,status\n";
  for (const auto& result : results)
    summary << result.name << "," << result.cells << "," << result.rms << "," << result.rms / 5.0 << ","
            << result.largest_speed << "," << result.steps << "," << result.wall_seconds << ","
            << (result.failed ? "failed" : "ok") << "\n";
  return 0;
}
