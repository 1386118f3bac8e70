// The one verdict rule (mpm/analysis/verdict.hpp) on the constructed cases that verification/verdict_rule.py is
// tested on too (tests/verdict_rule.py): tests/data/verdict_rule_cases.csv, one comparison and its outcome per row.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/analysis/verdict.hpp"
#include "tests/support.hpp"

namespace {

mpm::Ending verdict_case_ending(const std::string& name) {
  if (name == "stopped") return mpm::Ending::stopped;
  if (name == "failed") return mpm::Ending::failed;
  REQUIRE(name == "done");
  return mpm::Ending::done;
}

std::vector<std::string> verdict_case_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  return fields;
}

}  // namespace

TEST_CASE("verdict rule: the shared constructed cases (tests/data/verdict_rule_cases.csv)") {
  std::ifstream in(mpm::testing::source_path("tests/data/verdict_rule_cases.csv"));
  REQUIRE(in);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "case,a,a_band,a_ending,side,b,b_band,b_ending,outcome");
  int cases = 0;
  while (std::getline(in, line)) {
    const auto f = verdict_case_fields(line);
    REQUIRE(f.size() == 9);
    CAPTURE(f[0]);
    const mpm::Measured a{std::stod(f[1]), std::stod(f[2]), verdict_case_ending(f[3])};
    const mpm::Measured b{std::stod(f[5]), std::stod(f[6]), verdict_case_ending(f[7])};
    REQUIRE((f[4] == "below" || f[4] == "above"));
    CHECK(mpm::outcome_name(mpm::judge(a, f[4] == "below" ? mpm::Side::below : mpm::Side::above, b)) == f[8]);
    ++cases;
  }
  CHECK(cases >= 14);
}
