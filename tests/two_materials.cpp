/// \file
/// A material per body: a stress pulse crossing from one material into another is transmitted and
/// reflected as the impedances Z = sqrt(E rho) say (the bar's jump conditions, Eq. (A.5), on both sides).
///
/// The bar [0, 2] is of material A (E = 1 Pa, rho = 1 kg/m^3: c = 1 m/s, Z = 1) on [0, 1] and of B (E = 4 Pa:
/// c = 2 m/s, Z = 2) on [1, 2]. Its piece [0.2, 0.4] starts at v0 = 0.01 m/s (the bar moves at most 0.01 m, two cells): two pulses of v0/2 leave it, and the
/// right-going one (length 0.2 m) reaches the interface at t = 0.6 s. There it is transmitted with the
/// velocity 2 Z_A / (Z_A + Z_B) v0/2 = 1/3 m/s over a length stretched by c_B/c_A to 0.4 m, so at t = 1 s
/// (the pulse in [1.4, 1.8]) body B holds the momentum rho_B 0.4 / 3 = 0.13333 kg m/s per unit area. Were B of
/// A's material, it would hold 0.2 v0/2 = 0.1: the test tells the two apart by 33 %.
#include <doctest/doctest.h>

#include "tests/support.hpp"

namespace {

const char* two_material_bar = R"(
dimension = 1
[grid]
length = [2.0]
cells = [400]
margin_min = [4]
margin_max = [4]
[material]
young_modulus = 1.0
density = 1.0
[[body]]
min = [0.0]
max = [1.0]
[[body]]
min = [1.0]
max = [2.0]
young_modulus = 4.0
[[initial_velocity]]
min = [0.2]
max = [0.4]
velocity = [0.01]
[solver]
cfl = 0.5
end_time = 1.0
)";

/// The momentum of the particles right of X = 1 (body B) at the last sample, per unit v0.
struct MomentumOfB : mpm::Monitor<1> {
  void sample(long, double t, const mpm::Particles<1>& particles, const mpm::Balances<1>&) override {
    time = t;
    momentum = 0.0;
    for (int p = 0; p < particles.size(); ++p)
      if (particles.reference_position[p][0] > 1.0) momentum += particles.mass[p] * particles.velocity[p][0] / 0.01;
  }
  double time = 0.0, momentum = 0.0;
};

double momentum_of_b(const std::vector<std::string>& overrides) {
  const auto scene = mpm::testing::scene_from_text(two_material_bar, overrides);
  const auto setup = mpm::build_setup<1>(scene);
  MomentumOfB monitor;
  mpm::run_setup<1>(scene, setup, monitor);
  CHECK(monitor.time == doctest::Approx(1.0));
  return monitor.momentum;
}

}  // namespace

TEST_CASE("Eq. (3), Eq. (A.5): a material per body: a pulse crossing into a stiffer body is transmitted at 2 Z_A / (Z_A + Z_B)") {
  for (const std::string integrator : {"fe", "npc"}) {
    CAPTURE(integrator);
    CHECK(momentum_of_b({"solver.integrator=\"" + integrator + "\""}) == doctest::Approx(0.4 / 3.0).epsilon(0.01));
  }
  // B of A's material: the pulse crosses unchanged (and the time step is A's: c = 1 m/s).
  CHECK(momentum_of_b({"body[1].young_modulus=1.0"}) == doctest::Approx(0.1).epsilon(0.01));
}
