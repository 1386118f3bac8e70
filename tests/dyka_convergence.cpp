/// \file
/// The Dyka bar of scenes/dyka_bar.toml against its exact solution (appendix A, mpm/exact/bar.hpp).
///
/// The error measure is Eq. (43): the RMS over every time sample (every step, t = 0 included) of
/// v_A - v_exact(X_A, t), with X_A the reference position of particle A (paper/05_time_step_error_gravity.md, Eq. (43)).
#include <doctest/doctest.h>

#include <cmath>

#include "mpm/analysis/rms_error.hpp"
#include "mpm/exact/bar.hpp"
#include "tests/support.hpp"

namespace mpm::testing {

/// RMS of v_A (Eq. 43) of the Dyka bar for the given overrides of scenes/dyka_bar.toml, in m/s.
inline double dyka_rms(const std::vector<std::string>& overrides) {
  const io::Scene scene = load_scene(source_path("scenes/dyka_bar.toml"), overrides);
  const Setup<1> setup = build_setup<1>(scene);
  Recorder<1> recorder(setup.observed.at(0));
  run_setup<1>(scene, setup, recorder);
  const double length = 0.1333;
  const exact::ElasticBar bar(length, scene.young_modulus, scene.density, {{0.0, length / 4, -5.0, 0.0}});
  const double reference_position = setup.particles.reference_position[setup.observed[0]][0];
  std::vector<double> computed, expected;
  for (size_t n = 0; n < recorder.time.size(); ++n) {
    computed.push_back(recorder.velocity[n][0]);
    expected.push_back(bar.velocity(reference_position, recorder.time[n]));
  }
  return rms_error(computed, expected);
}

}  // namespace mpm::testing

TEST_CASE("Eq. (43): Dyka bar, linear + forward Euler: the RMS of v_A falls from 40 to 80 to 160 cells") {
  const double rms40 = mpm::testing::dyka_rms({"grid.cells=[40]"});
  const double rms80 = mpm::testing::dyka_rms({"grid.cells=[80]"});
  const double rms160 = mpm::testing::dyka_rms({"grid.cells=[160]"});
  MESSAGE("RMS/v0 at 40, 80, 160 cells: ", rms40 / 5, ", ", rms80 / 5, ", ", rms160 / 5);
  CHECK(rms80 < rms40);
  CHECK(rms160 < rms80);
  // An independent implementation of the same algorithm (paper/08_test_cases.md) found 0.1718 and 0.1212 v0.
  CHECK(rms40 / 5.0 == doctest::Approx(0.1718).epsilon(0.05));
  CHECK(rms160 / 5.0 == doctest::Approx(0.1212).epsilon(0.05));
}
