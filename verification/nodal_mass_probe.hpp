// The total nodal mass a run's next step will see, for the mass check of the soil suite.
//
// The solver keeps m_p constant, so the sum of particle masses cannot change; what can go wrong is
// the transfer: Eq. (13) lumped gives sum_I m_I = sum_p m_p sum_I N_Ip, equal to the particle mass
// only if every particle's shape functions sum to one on the nodes the grid has. That fails when a
// support reaches past the grid, which is what the grid margins are for. The solver resets its nodal
// fields at the end of every step, so the probe recomputes them: its own copy of the run's shape
// function, evaluated at the particles' current positions x_p^k (where the next step evaluates it),
// and the solver's own kernel for Eq. (13).
#pragma once
#include <functional>
#include <memory>
#include <numeric>

#include "mpm/run.hpp"
#include "mpm/transfer/particle_to_grid.hpp"

namespace verification {

template <int Dim>
class NodalMassProbe {
 public:
  /// A probe with the scene's shape function on the setup's grid.
  NodalMassProbe(const mpm::io::Scene& scene, const mpm::Setup<Dim>& setup) {
    const mpm::Grid<Dim>& grid = setup.model.grid;
    if (scene.shape == "ugimp")
      total_ = make(mpm::UgimpShape<Dim>(grid), setup);
    else if (scene.shape == "lme")
      total_ = make(mpm::LmeShape<Dim>(grid, mpm::lme_options(scene)), setup);
    else
      total_ = make(mpm::LinearShape<Dim>(grid), setup);
  }

  /// \f$ \sum_I m_I = \sum_I \sum_p N_I(\mathbf x_p)\, m_p \f$ at the particles' current positions.
  /// \throws mpm::ShapeFailure if the shape function refuses a particle (e.g. off the grid).
  double total(const mpm::Particles<Dim>& particles) { return total_(particles); }

 private:
  std::function<double(const mpm::Particles<Dim>&)> total_;

  template <class Shape>
  static std::function<double(const mpm::Particles<Dim>&)> make(Shape shape, const mpm::Setup<Dim>& setup) {
    shape.initialise(setup.particles);
    auto stencils = std::make_shared<mpm::Stencils<Dim>>();
    stencils->resize(setup.particles.size(), shape.capacity());
    auto fields = std::make_shared<mpm::GridFields<Dim>>(setup.model.grid.node_count());
    return [shape, stencils, fields](const mpm::Particles<Dim>& particles) mutable {
      mpm::compute_stencils(shape, particles.position, *stencils);
      fields->reset();
      mpm::lumped_nodal_mass(particles, *stencils, *fields);
      return std::accumulate(fields->nodal_mass.begin(), fields->nodal_mass.end(), 0.0);
    };
  }
};

}  // namespace verification
