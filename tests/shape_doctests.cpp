/// \file
/// Compiles the doctests of the shape functions (shape/, and the fast LME form of fast/) into the test program.
#include "mpm/fast/lme_fast.hpp"
#include "mpm/shape/bspline.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/lme_reference.hpp"
#include "mpm/shape/ugimp.hpp"

#include <random>

#include "mpm/fast/fast_stencils.hpp"
#include "mpm/particles/stencils.hpp"

TEST_CASE("Tensor-product shapes and LME's neighbours list their nodes in ascending order, so fast::compute_stencils bounds the nodes a chunk reaches by the first and last") {
  const mpm::Grid<2> grid(mpm::Vector<2>(-1.0, 0.5), 0.25, {9, 7});
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> along_x(-1.0, 1.25), along_y(0.5, 2.25);
  std::vector<mpm::Vector<2>> positions;
  for (int p = 0; p < 2000; ++p) positions.emplace_back(along_x(generator), along_y(generator));
  positions.emplace_back(-1.0, 0.5), positions.emplace_back(1.25, 2.25), positions.emplace_back(-1.0, 2.25);  // corners
  auto check = [&](auto shape) {
    static_assert(mpm::fast::lists_nodes_ascending<decltype(shape)>);
    mpm::Particles<2> particles;
    for (const auto& x : positions) particles.add(x, 1.0, 1.0, mpm::Vector<2>::Zero(), mpm::Vector<2>::Constant(0.125));
    shape.initialise(particles);
    mpm::Stencils<2> stencils;
    stencils.resize(particles.size(), shape.capacity());
    const mpm::FastKernels kernels;
    mpm::fast::compute_stencils(kernels, shape, particles.position, stencils);
    REQUIRE(kernels.scratch.noted_for == &stencils);
    for (int chunk = 0; chunk < mpm::chunks_of(particles.size()); ++chunk) {
      const mpm::Range items = mpm::chunk_of(particles.size(), chunk);
      int lowest = grid.node_count(), highest = -1;
      for (int p = items.begin; p < items.end; ++p) {
        const auto stencil = stencils.of(p);
        REQUIRE(stencil.count > 0);
        for (int k = 0; k + 1 < stencil.count; ++k) REQUIRE(stencil.node[k] < stencil.node[k + 1]);
        for (int k = 0; k < stencil.count; ++k) lowest = std::min(lowest, stencil.node[k]), highest = std::max(highest, stencil.node[k]);
      }
      CHECK(kernels.scratch.reached[chunk].begin == lowest);  // the nodes each chunk reaches, as a search finds them
      CHECK(kernels.scratch.reached[chunk].end == highest + 1);
    }
  };
  check(mpm::LinearShape<2>(grid));
  check(mpm::UgimpShape<2>(grid));
  check(mpm::BsplineShape<2, 2>(grid));
  check(mpm::BsplineShape<2, 3>(grid));
  check(mpm::fast::LmeShape<2>(grid));  // gamma 3, the default
  mpm::LmeOptions wide;
  wide.gamma = 0.8;  // a wider support: more neighbours, more of them cut by the edges
  check(mpm::fast::LmeShape<2>(grid, wide));
}
