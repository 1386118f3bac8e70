/// \file
/// Shape-function stencils: for every particle p, its nodes I, N_Ip and grad N_Ip.
///
/// Computed once per step at the particle positions x_p^k (paper/02_mpm_forward_euler.md) and reused by every
/// transfer of the step. Storage is flat with a fixed capacity per particle, set once per run by
/// the shape function, so computing the stencils allocates nothing.
#pragma once
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/core/kernels.hpp"
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

  void resize(int particle_count, int nodes_per_particle) {
    capacity = nodes_per_particle;
    count.assign(particle_count, 0);
    node.assign(static_cast<size_t>(particle_count) * capacity, 0);
    value.assign(static_cast<size_t>(particle_count) * capacity, 0.0);
    gradient.assign(static_cast<size_t>(particle_count) * capacity, Vector<Dim>::Zero());
  }
  int begin(int p) const { return p * capacity; }
  ParticleStencil<Dim> of(int p) const {
    const std::size_t first = static_cast<std::size_t>(p) * capacity;
    return {count[p], &node[first], &value[first], &gradient[first]};
  }
};

}  // namespace mpm

namespace mpm {

/// The stencil phase, its reference form: the shape function evaluated at every particle position x_p^k, once per
/// step, in a plain loop over the particles; every transfer of the step then reads these stencils. (The fast layer's
/// form, on every core: fast::compute_stencils, mpm/fast/fast_stencils.hpp.)
/// \throws ShapeFailure from the shape function: that of the first particle that failed.
template <int Dim, class Shape>
void compute_stencils(Shape& shape, const std::vector<Vector<Dim>>& positions, Stencils<Dim>& stencils) {
  for (int p = 0; p < static_cast<int>(positions.size()); ++p) {
    const int first = stencils.begin(p);
    stencils.count[p] = shape.evaluate(p, positions[p], &stencils.node[first], &stencils.value[first],
                                       &stencils.gradient[first]);
  }
}

/// The stencil phase of the reference kernels (`solver.kernels = "reference"`): the plain loop above.
template <int Dim, class Shape>
void compute_stencils(ReferenceKernels, Shape& shape, const std::vector<Vector<Dim>>& positions,
                      Stencils<Dim>& stencils) {
  compute_stencils(shape, positions, stencils);
}

}  // namespace mpm
