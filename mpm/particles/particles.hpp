/// \file
/// Material points, stored as structure-of-arrays: every field is one contiguous array over the
/// particles, so each kernel streams through exactly the fields it reads and writes.
///
/// A particle p carries m_p (constant), rho_p (V_p = m_p / rho_p), x_p, v_p, a_p, epsilon_p and
/// sigma_p (paper/02_mpm_forward_euler.md, 'What a particle carries'). In 2D (plane strain) sigma_zz is kept in its own array.
#pragma once
#include <vector>

#include "mpm/core/types.hpp"

namespace mpm {

template <int Dim>
struct Particles {
  std::vector<int> id;                             ///< stable number, 0-based, in seeding order
  std::vector<double> mass;                        ///< m_p, constant
  std::vector<double> density;                     ///< rho_p, Eq. (17)
  std::vector<Vector<Dim>> reference_position;     ///< X_p, the position at t = 0
  std::vector<Vector<Dim>> position;               ///< x_p
  std::vector<Vector<Dim>> velocity;               ///< v_p
  std::vector<Vector<Dim>> acceleration;           ///< a_p (used by the predictor-corrector)
  std::vector<Matrix<Dim>> strain;                 ///< epsilon_p, small strain
  std::vector<Matrix<Dim>> stress;                 ///< sigma_p, in-plane components
  std::vector<double> stress_zz;                   ///< sigma_zz of plane strain (0 in 1D)
  std::vector<Vector<Dim>> half_length;            ///< l_p per axis: half the initial particle spacing (uGIMP)
  std::vector<int> material;                       ///< the particle's material: an index into Model::materials

  int size() const { return static_cast<int>(mass.size()); }
  double volume(int p) const { return mass[p] / density[p]; }  ///< V_p = m_p / rho_p

  void add(const Vector<Dim>& x, double particle_mass, double particle_density, const Vector<Dim>& v,
           const Vector<Dim>& particle_half_length, int material_index = 0) {
    id.push_back(size());
    mass.push_back(particle_mass);
    density.push_back(particle_density);
    reference_position.push_back(x);
    position.push_back(x);
    velocity.push_back(v);
    acceleration.push_back(Vector<Dim>::Zero());
    strain.push_back(Matrix<Dim>::Zero());
    stress.push_back(Matrix<Dim>::Zero());
    stress_zz.push_back(0.0);
    half_length.push_back(particle_half_length);
    material.push_back(material_index);
  }
};

}  // namespace mpm
