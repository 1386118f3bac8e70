// The CFL limits of a 1D scene's own linearised step, on its body as it is (its free ends and held faces, its margins):
// at rest, and with every particle moved by 1e-6 h towards x = 0 (mpm::moved_body_cfl_limit), where a free end at
// x = 0 brings a node into the support of the quadratic B-spline with a vanishing mass (paper/08_test_cases.md, "In
// the stability map"). The stability map (verification/dyka_stability.sh) starts its scan below the smaller of the two.
//
//   build/bin/free_bar_limits SCENE [KEY=VALUE ...]    prints "cfl_limit_at_rest,cfl_limit_moved" (to 1e-4)
#include <cstdio>
#include <string>
#include <vector>

#include "mpm/stability.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: free_bar_limits SCENE [KEY=VALUE ...]\n");
    return 2;
  }
  const std::vector<std::string> overrides(argv + 2, argv + argc);
  try {
    const mpm::io::Scene scene = mpm::load_scene(argv[1], overrides);
    if (scene.dimension != 1) {
      std::fprintf(stderr, "free_bar_limits: %s: a 1D scene only\n", argv[1]);
      return 2;
    }
    std::printf("%.8g,%.8g\n", mpm::moved_body_cfl_limit<1>(scene, 0.0), mpm::moved_body_cfl_limit<1>(scene, -1e-6));
  } catch (const mpm::SceneError& error) {
    std::fprintf(stderr, "free_bar_limits: %s\n", error.message().c_str());
    return 2;
  }
  return 0;
}
