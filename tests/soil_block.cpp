/// \file
/// The soil block of scenes/soil_block.toml (paper section 3.2) against the exact column of paper/07_exact_column.md
/// (mpm/exact/column.hpp): the fast subset of the soil verification (verification/soil_suite.cpp).
/// One run is about 2900 steps of 100 particles, a fraction of a second.
///
/// The tolerances are the suite's (verification/soil_report.hpp), where they are derived:
///   settlement: 5 % = the finite-strain gap aH/3 = 3.8 % (mpm/exact/column_log_strain.hpp) + ~1 % of grid;
///   stress: RMS 7.5 % of rho g H, of which h/(4H) = 5 % is the staircase of a cell-wise constant strain;
///   sigma_xx/sigma_yy: nu/(1-nu) within 1e-3 (exact wherever the walls hold v_x = 0).
#include <doctest/doctest.h>

#include <cmath>

#include "mpm/exact/column_log_strain.hpp"
#include "tests/support.hpp"
#include "verification/soil_domain.hpp"
#include "verification/soil_report.hpp"

namespace {

verification::SoilResult soil_block(const std::vector<std::string>& overrides) {
  return verification::run_soil_case(mpm::testing::source_path("scenes/soil_block.toml"), "test", overrides);
}

}  // namespace

TEST_CASE("Soil block, LME gamma = 3, NPC, 2 m cells: settlement, stress and mass at t = 20 s against the exact column") {
  const auto result = soil_block({});
  REQUIRE_FALSE(result.failed);
  REQUIRE(result.snapshots.size() == 3);
  CHECK(result.reference_height == 9.5);  // the top row of a 2 x 2 split of 2 m cells
  const auto settlement = verification::measure_settlement(result);
  MESSAGE("u(20 s) = ", settlement.final_displacement, " m, exact ", settlement.exact_final, " m");
  // paper/07_exact_column.md: after the ramp u oscillates by about +-2.3 mm about the static -(rho g/E)(H Y - Y^2/2) = -0.58713 m.
  CHECK(std::abs(settlement.exact_final + 0.58713) <= 0.0025);
  CHECK(std::abs(settlement.final_error) <= verification::settlement_tolerance * std::abs(settlement.exact_final));
  // The stress at t = 20 s: the whole profile, and the bottom row (Y = 0.5 m, exact -558 kPa) against
  // the same bound, rho g h/4 = 29 kPa being the staircase alone.
  const auto stress = verification::measure_stress(result, result.snapshots.back());
  const double rho_g_h = 6000.0 * 9.81 * 10.0;
  MESSAGE("stress RMS ", stress.rms_relative, " of rho g H; bottom row ", stress.bottom_row_stress, " Pa, exact ", stress.bottom_row_exact);
  CHECK(stress.rms_relative <= verification::stress_tolerance);
  CHECK(stress.bottom_row_height == 0.5);
  CHECK(std::abs(stress.bottom_row_stress - stress.bottom_row_exact) <= verification::stress_tolerance * rho_g_h);
  CHECK(result.largest_mass_mismatch <= verification::mass_tolerance);
}

TEST_CASE("Soil block, nu = 0.3, lateral rollers: sigma_xx / sigma_yy = nu/(1-nu) and the settlement with M") {
  const auto result = soil_block({"material.poisson_ratio=0.3"});
  REQUIRE_FALSE(result.failed);
  REQUIRE(result.snapshots.size() == 3);
  const auto ratio = verification::measure_stress_ratio(result, result.snapshots.back());
  MESSAGE("sigma_xx/sigma_yy: mean ", ratio.mean, ", largest deviation ", ratio.largest_deviation);
  CHECK(ratio.expected == doctest::Approx(3.0 / 7.0));
  CHECK(ratio.particles == 80);  // the top cell's 20 particles, where sigma_yy ~ 0, are left out
  CHECK(ratio.largest_deviation <= verification::ratio_tolerance);
  // M = 5e6 * 0.7 / (1.3 * 0.4) = 6.73 MPa: the static top settlement 0.5886 * 5 / 6.73 = 0.4373 m.
  const auto settlement = verification::measure_settlement(result);
  CHECK(settlement.static_small_strain == doctest::Approx(-0.4361526).epsilon(1e-6));  // at Y = 9.5
  CHECK(std::abs(settlement.final_error) <= verification::settlement_tolerance * std::abs(settlement.exact_final));
}
