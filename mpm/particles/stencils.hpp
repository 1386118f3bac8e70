/// \file
/// Shape-function stencils: for every particle p, its nodes I, N_Ip and grad N_Ip.
///
/// Computed once per step at the particle positions x_p^k (paper/02_mpm_forward_euler.md) and reused by every
/// transfer of the step. Storage is flat with a fixed capacity per particle, set once per run by
/// the shape function, so computing the stencils allocates nothing.
#pragma once
#include <array>
#include <limits>
#include <mutex>
#include <optional>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/core/scatter.hpp"
#include "mpm/core/types.hpp"

namespace mpm {

/// One particle's stencil: its nodes I, N_Ip and grad N_Ip, as plain pointers and a count. The transfers
/// loop over it from a local copy: Eigen's vector stores may alias any memory, so a loop that reached the
/// stencils through their containers would reload every container's data pointer after each store to a node.
template <int Dim>
struct ParticleStencil {
  int count;                      ///< nodes of the particle
  const int* node;                ///< node number I
  const double* value;            ///< N_Ip
  const Vector<Dim>* gradient;    ///< grad N_Ip
};

/// \f$ \sum_k \mathrm{term}(k) \f$ over one particle's stencil, in the order of its nodes.
template <class Sum, int Dim, class Term>
Sum stencil_sum(const ParticleStencil<Dim>& stencil, Term term) {
  Sum sum = Sum::Zero();
  for (int k = 0; k < stencil.count; ++k) sum += term(k);
  return sum;
}

template <int Dim>
struct Stencils {
  int capacity = 0;                        ///< largest number of nodes a particle may have
  std::vector<int> count;                  ///< nodes of each particle
  std::vector<int> node;                   ///< [p * capacity + k]: node number I
  std::vector<double> value;               ///< [p * capacity + k]: N_Ip
  std::vector<Vector<Dim>> gradient;       ///< [p * capacity + k]: grad N_Ip
  /// For each chunk of the particles (mpm/core/parallel.hpp), the nodes [lowest, highest + 1) its
  /// stencils reach: a chunk's copy of a field in the scatters covers these nodes only (mpm/core/scatter.hpp).
  ChunkNodes chunk_nodes;

  void resize(int particle_count, int nodes_per_particle) {
    capacity = nodes_per_particle;
    count.assign(particle_count, 0);
    node.assign(static_cast<size_t>(particle_count) * capacity, 0);
    value.assign(static_cast<size_t>(particle_count) * capacity, 0.0);
    gradient.assign(static_cast<size_t>(particle_count) * capacity, Vector<Dim>::Zero());
    chunk_nodes.assign(chunks_of(particle_count), all_nodes);
  }
  int begin(int p) const { return p * capacity; }
  ParticleStencil<Dim> of(int p) const {
    const std::size_t first = static_cast<std::size_t>(p) * capacity;
    return {count[p], &node[first], &value[first], &gradient[first]};
  }
};

}  // namespace mpm

namespace mpm {

/// Evaluates the shape function at every particle position, once per step, on every core, and notes
/// the nodes each chunk of particles reaches; every transfer of the step then reads these stencils.
/// \throws ShapeFailure from the shape function: that of the first particle that failed, as a serial loop would.
template <int Dim, class Shape>
void compute_stencils(Shape& shape, const std::vector<Vector<Dim>>& positions, Stencils<Dim>& stencils) {
  const int count = static_cast<int>(positions.size());
  if (static_cast<int>(stencils.chunk_nodes.size()) != chunks_of(count))
    stencils.chunk_nodes.assign(chunks_of(count), all_nodes);
  std::mutex failing;  // guards the first failure: that of the failing chunk first in order
  int failed_chunk = chunks_of(count);
  std::optional<ShapeFailure> failure;
  for_each_chunk(count, static_cast<long>(count) * stencils.capacity, [&](int chunk, Range items) {
    Range reached{std::numeric_limits<int>::max(), 0};
    try {
      for (int p = items.begin; p < items.end; ++p) {
        const int first = stencils.begin(p);
        const int count = shape.evaluate(p, positions[p], &stencils.node[first], &stencils.value[first], &stencils.gradient[first]);
        stencils.count[p] = count;
        if constexpr (Shape::nodes_ascending) {  // a tensor product lists its nodes in ascending order
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
    } catch (const ShapeFailure& what) {
      reached = all_nodes;
      const std::lock_guard<std::mutex> guard(failing);
      if (chunk < failed_chunk) failed_chunk = chunk, failure = what;
    }
    stencils.chunk_nodes[chunk] = reached;
  });
  if (failure) throw *failure;
}

}  // namespace mpm
