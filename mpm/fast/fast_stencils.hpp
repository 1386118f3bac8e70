/// \file
/// The fast layer's stencil phase and its scatter over the stencils' particles: the stencils computed on every core,
/// and, while they are, the nodes each chunk of particles reaches noted in the layer's workspace (FastKernels'
/// ScatterScratch), which the scatters of the step then read (mpm/fast/scatter.hpp). The reference stencil phase,
/// the plain loop, is mpm::compute_stencils (mpm/particles/stencils.hpp).
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <limits>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/core/kernels.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/core/types.hpp"
#include "mpm/fast/fast_kernels.hpp"
#include "mpm/fast/random_state.hpp"
#include "mpm/fast/scatter.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/fast/lme_fast.hpp"
#include "mpm/shape/bspline.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/ugimp.hpp"

namespace mpm::fast {

/// Whether a shape is a tensor product of 1D factors (mpm/shape/tensor_product.hpp): linear, uGIMP, the B-splines.
template <class Shape>
inline constexpr bool is_tensor_product = false;
template <int Dim>
inline constexpr bool is_tensor_product<LinearShape<Dim>> = true;
template <int Dim>
inline constexpr bool is_tensor_product<UgimpShape<Dim>> = true;
template <int Dim, int Degree>
inline constexpr bool is_tensor_product<BsplineShape<Dim, Degree>> = true;

/// Whether a shape function lists the nodes of each stencil in ascending order, so that the nodes a chunk of
/// particles reaches are bounded by each stencil's first and last node instead of a search over all of them. True
/// for the tensor products (x fastest, mpm/shape/tensor_product.hpp) and for LME's neighbours (lme_neighbours
/// walks the lattice box x fastest), each checked in tests/shape_doctests.cpp, at the grid's edges too; false (the
/// search) for any other shape.
template <class Shape>
inline constexpr bool lists_nodes_ascending = is_tensor_product<Shape>;
template <int Dim>
inline constexpr bool lists_nodes_ascending<LmeShape<Dim>> = true;

/// Widens `reached` to the nodes of particle p's stencil: its first and last node when they are listed in ascending
/// order, else every node.
template <bool ascending, int Dim>
void widen_to_stencil(const Stencils<Dim>& stencils, int p, Range& reached) {
  const int first = stencils.begin(p), count = stencils.count[p];
  if constexpr (ascending) {
    if (count > 0) {
      reached.begin = std::min(reached.begin, stencils.node[first]);
      reached.end = std::max(reached.end, stencils.node[first + count - 1] + 1);
    }
  } else {
    for (int k = first; k < first + count; ++k) {
      reached.begin = std::min(reached.begin, stencils.node[k]);
      reached.end = std::max(reached.end, stencils.node[k] + 1);
    }
  }
}

/// The stencils of the particles `items`: N_Ip and grad N_Ip at each position, and the nodes [lowest, highest + 1)
/// they reach. Flattened (every call inside compiled into the loop) for the tensor products, whose evaluate() GCC
/// otherwise may leave out of line; not for LME, whose evaluation is a call (benchmarks/README.md, "Optimisations
/// tried").
template <int Dim, class Shape>
Range evaluate_stencils(Shape& shape, const std::vector<Vector<Dim>>& positions, Range items, Stencils<Dim>& stencils) {
  Range reached{std::numeric_limits<int>::max(), 0};
  for (int p = items.begin; p < items.end; ++p) {
    const int first = stencils.begin(p);
    stencils.count[p] =
        shape.evaluate(p, positions[p], &stencils.node[first], &stencils.value[first], &stencils.gradient[first]);
    widen_to_stencil<lists_nodes_ascending<Shape>>(stencils, p, reached);
  }
  return reached;
}
template <int Dim, class Shape>
[[gnu::flatten]] Range evaluate_tensor_product_stencils(Shape& shape, const std::vector<Vector<Dim>>& positions,
                                                        Range items, Stencils<Dim>& stencils) {
  return evaluate_stencils(shape, positions, items, stencils);
}

/// The stencil phase on every core: N_Ip and grad N_Ip at every particle position, as mpm::compute_stencils
/// computes them, and for each chunk of particles the nodes [lowest, highest + 1) its stencils reach, noted in
/// kernels.scratch for these stencils (the scatters of the step read them there instead of searching the stencils).
/// \throws ShapeFailure from the shape function: that of the first particle that failed, as a serial loop would.
template <int Dim, class Shape>
void compute_stencils(const FastKernels& kernels, Shape& shape, const std::vector<Vector<Dim>>& positions,
                      Stencils<Dim>& stencils) {
  const int count = static_cast<int>(positions.size());
  ScatterScratch& scratch = kernels.scratch;
  scratch.noted_for = nullptr;  // until every chunk is noted
  scratch.reached.assign(chunks_of(count), all_nodes);
  std::mutex failing;  // guards the first failure: that of the failing chunk first in order
  int failed_chunk = chunks_of(count);
  std::optional<ShapeFailure> failure;
  for_each_chunk(count, static_cast<long>(count) * stencils.capacity, [&](int chunk, Range items) {
    Range reached;
    try {
      if constexpr (is_tensor_product<Shape>)
        reached = evaluate_tensor_product_stencils(shape, positions, items, stencils);
      else
        reached = evaluate_stencils(shape, positions, items, stencils);
    } catch (const ShapeFailure& what) {
      reached = all_nodes;
      const std::lock_guard<std::mutex> guard(failing);
      if (chunk < failed_chunk) failed_chunk = chunk, failure = what;
    }
    scratch.reached[chunk] = reached;
  });
  if (failure) throw *failure;
  scratch.noted_for = &stencils;
}

/// For each chunk of the stencils' particles, the nodes its stencils reach: those that compute_stencils noted in
/// `scratch` for these stencils, else (stencils computed otherwise: the doctests, tests/integrator_modes.cpp
/// and the linearised step of the stability analysis) found by a search over every node of
/// every stencil, the same windows.
template <int Dim>
const ChunkNodes& chunk_windows(ScatterScratch& scratch, const Stencils<Dim>& stencils) {
  const int count = static_cast<int>(stencils.count.size()), chunks = chunks_of(count);
  if (scratch.noted_for == &stencils && static_cast<int>(scratch.reached.size()) == chunks) return scratch.reached;
  scratch.noted_for = nullptr;
  scratch.reached.assign(chunks, all_nodes);
  if (chunks == 1) return scratch.reached;  // one part: it adds into the fields themselves
  for_each_chunk(count, static_cast<long>(count) * stencils.capacity, [&](int chunk, Range items) {
    Range reached{std::numeric_limits<int>::max(), 0};
    for (int p = items.begin; p < items.end; ++p) widen_to_stencil<false>(stencils, p, reached);
    scratch.reached[chunk] = reached;
  });
  return scratch.reached;
}

/// scatter_to_nodes below, with field number i's copies in buffer i of its type in `scratch`.
template <int Dim, class Body, std::size_t... index, class... T>
void scatter_with_copies(ScatterScratch& scratch, const Stencils<Dim>& stencils, Body body,
                         std::index_sequence<index...>, std::vector<T>&... fields) {
  const int count = static_cast<int>(stencils.count.size());
  const int nodes = static_cast<int>(std::get<0>(std::forward_as_tuple(fields...)).size());
  const ChunkNodes& reached = chunk_windows(scratch, stencils);
  const long room = copy_room(count, nodes);
  scatter_to_nodes(count, stencils.capacity, reached, scratch.plan, body,
                   ScatterTarget<T>{fields, scratch.copies<T>(index, room)}...);
}

/// Scatter into the nodes (P2G) over the stencils' particles, on every core: body(p, field...) adds particle p's
/// share into field[I] of each of `fields` for the nodes I of its stencil; the chunks' copies of the fields are
/// kernels.scratch's (the scatter and its guarantee: mpm/fast/scatter.hpp).
template <int Dim, class Body, class... T>
void scatter_to_nodes(const FastKernels& kernels, const Stencils<Dim>& stencils, Body body, std::vector<T>&... fields) {
  scatter_with_copies(kernels.scratch, stencils, body, std::index_sequence_for<T...>{}, fields...);
}

}  // namespace mpm::fast

namespace mpm::testing {

/// For each chunk of the stencils' particles, the nodes [lowest, highest + 1) of their stencils, by a search.
template <int Dim>
fast::ChunkNodes searched_windows(const Stencils<Dim>& stencils) {
  const int count = static_cast<int>(stencils.count.size());
  fast::ChunkNodes windows(chunks_of(count), Range{std::numeric_limits<int>::max(), 0});
  for (int chunk = 0; chunk < chunks_of(count); ++chunk)
    for (int p = chunk_of(count, chunk).begin; p < chunk_of(count, chunk).end; ++p)
      for (int k = 0; k < stencils.count[p]; ++k) {
        windows[chunk].begin = std::min(windows[chunk].begin, stencils.of(p).node[k]);
        windows[chunk].end = std::max(windows[chunk].end, stencils.of(p).node[k] + 1);
      }
  return windows;
}

inline bool same_windows(const fast::ChunkNodes& a, const fast::ChunkNodes& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](Range x, Range y) {
           return x.begin == y.begin && x.end == y.end;
         });
}

/// fast::compute_stencils on a random state (its stencils from the plain loop) on 1 and 3 threads: the same stencils,
/// and the nodes each chunk reaches as a search finds them, whether noted or searched by the scatters.
template <int Dim, class Shape>
void check_fast_stencils(unsigned seed) {
  const RandomState<Dim> state = random_state<Dim, Shape>(seed);
  for (const int threads : {1, 3}) {
    const TeamAlways on_the_team;
    use_threads(threads);
    Shape shape(state.grid);
    shape.initialise(state.particles);
    Stencils<Dim> stencils;
    stencils.resize(state.particles.size(), shape.capacity());
    const FastKernels kernels;
    fast::compute_stencils(kernels, shape, state.particles.position, stencils);
    use_threads(1);
    CHECK(stencils.count == state.stencils.count);  // bit for bit
    CHECK(stencils.node == state.stencils.node);
    CHECK(stencils.value == state.stencils.value);
    CHECK(stencils.gradient == state.stencils.gradient);
    CHECK(kernels.scratch.noted_for == &stencils);
    CHECK(same_windows(kernels.scratch.reached, searched_windows(stencils)));
    fast::ScatterScratch other;  // the scatters' own search, where nothing was noted for these stencils
    CHECK(same_windows(fast::chunk_windows(other, stencils), searched_windows(stencils)));
  }
}

}  // namespace mpm::testing

namespace mpm::fast {

TEST_CASE("The fast stencil phase: the plain loop's stencils on 1 and 3 threads, each chunk's nodes noted as a search finds them, 1D and 2D, four shapes") {
  testing::check_fast_stencils<1, LinearShape<1>>(1);
  testing::check_fast_stencils<1, UgimpShape<1>>(2);
  testing::check_fast_stencils<1, BsplineShape<1, 2>>(3);
  testing::check_fast_stencils<1, BsplineShape<1, 3>>(4);
  testing::check_fast_stencils<2, LinearShape<2>>(5);
  testing::check_fast_stencils<2, UgimpShape<2>>(6);
  testing::check_fast_stencils<2, BsplineShape<2, 2>>(7);
  testing::check_fast_stencils<2, BsplineShape<2, 3>>(8);
}

TEST_CASE("The fast stencil phase throws the failure of the first particle that fails, on any number of threads") {
  Grid<1> grid(Vector<1>(0.0), 1.0, {10});
  std::vector<Vector<1>> positions(2000, Vector<1>(5.0));
  positions[1500] = Vector<1>(11.0);  // off the grid: in chunk 6 of 8, and in chunk 2:
  positions[600] = Vector<1>(-1.0);
  for (const int threads : {1, 3}) {
    const TeamAlways on_the_team;
    use_threads(threads);
    LinearShape<1> shape(grid);
    Stencils<1> stencils;
    stencils.resize(static_cast<int>(positions.size()), shape.capacity());
    const FastKernels kernels;
    int failed = -1;
    try {
      compute_stencils(kernels, shape, positions, stencils);
    } catch (const ShapeFailure& failure) {
      failed = failure.particle;
    }
    use_threads(1);
    CHECK(failed == 600);
    CHECK(kernels.scratch.noted_for == nullptr);  // nothing noted for stencils left half computed
  }
}

}  // namespace mpm::fast
