/// \file
/// Isotropic linear elasticity, Eq. (3): \f$ \boldsymbol\sigma = \mathbf D : \boldsymbol\varepsilon \f$.
///
/// 1D (a bar): \f$ \sigma = E \varepsilon \f$.
/// 2D plane strain (unit thickness, \f$ \varepsilon_{zz} = 0 \f$, as the authors run it):
/// \f$ \boldsymbol\sigma = \lambda\,\mathrm{tr}(\boldsymbol\varepsilon)\,\mathbf I + 2G\boldsymbol\varepsilon \f$ and
/// \f$ \sigma_{zz} = \lambda\,\mathrm{tr}(\boldsymbol\varepsilon) \f$, with \f$ G = E/(2(1+\nu)) \f$,
/// \f$ \lambda = \nu E/((1+\nu)(1-2\nu)) \f$. Small strain, total-strain form, no objective rate (paper/02_mpm_forward_euler.md).
#pragma once
#include <doctest/doctest.h>

#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm {

struct LinearElastic {
  double young_modulus = 0.0;  ///< E, Pa
  double poisson_ratio = 0.0;  ///< nu
  double density = 0.0;        ///< rho_0, kg/m^3 (initial)

  double shear_modulus() const { return young_modulus / (2.0 * (1.0 + poisson_ratio)); }
  double lame_lambda() const {
    return poisson_ratio * young_modulus / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
  }
  /// Constrained (P-wave) modulus M = lambda + 2G, the stiffness of a laterally confined column.
  double constrained_modulus() const { return lame_lambda() + 2.0 * shear_modulus(); }

  /// Eq. (3), in-plane stress from strain.
  template <int Dim>
  Matrix<Dim> stress(const Matrix<Dim>& strain) const {
    if constexpr (Dim == 1) {
      return young_modulus * strain;
    } else {
      return lame_lambda() * strain.trace() * Matrix<Dim>::Identity() + 2.0 * shear_modulus() * strain;
    }
  }

  /// Eq. (3) inverted: the strain of an in-plane stress, \f$ \varepsilon = \sigma / E \f$ in 1D and, in plane
  /// strain (\f$ \varepsilon_{zz} = 0 \f$), \f$ \boldsymbol\varepsilon = \frac{1+\nu}{E}\left(\boldsymbol\sigma - \nu\,\mathrm{tr}(\boldsymbol\sigma)\,\mathbf I\right) \f$.
  /// Used to start a particle from a given stress (loading/initial_fields.hpp).
  template <int Dim>
  Matrix<Dim> strain(const Matrix<Dim>& stress) const {
    if constexpr (Dim == 1) {
      return stress / young_modulus;
    } else {
      return (1.0 + poisson_ratio) / young_modulus * (stress - poisson_ratio * stress.trace() * Matrix<Dim>::Identity());
    }
  }

  /// Eq. (3), the out-of-plane stress of plane strain (0 in 1D).
  template <int Dim>
  double stress_zz(const Matrix<Dim>& strain) const {
    return Dim == 1 ? 0.0 : lame_lambda() * strain.trace();
  }
};

TEST_CASE("Eq. (3): Hooke's law: 1D, plane strain, and the constrained-column ratio nu/(1-nu)") {
  const LinearElastic steel{200e9, 0.0, 7833.0};
  CHECK(steel.stress<1>(Matrix<1>::Constant(1e-3))(0, 0) == doctest::Approx(2e8));

  const LinearElastic soil{5e6, 0.3, 6000.0};
  // Uniaxial strain eps_yy = -0.01 (a laterally confined column): sigma_yy = -M 0.01 with
  // M = E(1-nu)/((1+nu)(1-2nu)) = 5e6 * 0.7 / (1.3 * 0.4) = 6.730769e6 Pa; sigma_xx = sigma_zz = nu/(1-nu) sigma_yy.
  Matrix<2> strain = Matrix<2>::Zero();
  strain(1, 1) = -0.01;
  const Matrix<2> sigma = soil.stress<2>(strain);
  CHECK(sigma(1, 1) == doctest::Approx(-6.730769230769e4));
  CHECK(sigma(0, 0) / sigma(1, 1) == doctest::Approx(0.3 / 0.7));
  CHECK(soil.stress_zz<2>(strain) == doctest::Approx(sigma(0, 0)));
  CHECK(soil.constrained_modulus() == doctest::Approx(6.730769230769e6));
  // Pure shear eps_xy = 1e-3: sigma_xy = 2 G eps_xy with G = 5e6 / 2.6.
  strain.setZero();
  strain(0, 1) = strain(1, 0) = 1e-3;
  CHECK(soil.stress<2>(strain)(0, 1) == doctest::Approx(2.0 * 5e6 / 2.6 * 1e-3));
  // The inverse: the confined column's stress gives back eps_yy = -0.01, eps_xx = 0; any stress round-trips.
  const Matrix<2> column_strain = soil.strain<2>(sigma);
  CHECK(column_strain(1, 1) == doctest::Approx(-0.01));
  CHECK(column_strain(0, 0) == doctest::Approx(0.0).scale(1e-2));
  Matrix<2> stress;
  stress << 3e4, -1e4, -1e4, 7e4;
  CHECK((soil.stress<2>(soil.strain<2>(stress)) - stress).norm() < 1e-10 * stress.norm());
  CHECK(steel.strain<1>(Matrix<1>::Constant(2e8))(0, 0) == doctest::Approx(1e-3).epsilon(1e-12));  // Approx compares within 1e-5 of max(1, |x|)
}

TEST_CASE("Eq. (3): plane strain by hand for a strain with every component: sigma = lambda tr(eps) I + 2 G eps, sigma_zz = lambda tr(eps)") {
  // E = 5e6 Pa, nu = 0.3: lambda = 0.3 * 5e6 / (1.3 * 0.4) = 2884615.385 Pa, 2G = 5e6 / 1.3 = 3846153.846 Pa.
  // eps = [[1e-3, 2e-4], [2e-4, -3e-3]], tr = -2e-3: lambda tr = -5769.231 Pa, so sigma_xx = -5769.231 + 3846.154
  // = -1923.077, sigma_yy = -5769.231 - 11538.462 = -17307.692, sigma_xy = 769.231 and sigma_zz = -5769.231.
  const LinearElastic soil{5e6, 0.3, 6000.0};
  Matrix<2> strain;
  strain << 1e-3, 2e-4, 2e-4, -3e-3;
  const Matrix<2> sigma = soil.stress<2>(strain);
  CHECK(sigma(0, 0) == doctest::Approx(-1923.0769231));
  CHECK(sigma(1, 1) == doctest::Approx(-17307.692308));
  CHECK(sigma(0, 1) == doctest::Approx(769.23076923));
  CHECK(sigma(1, 0) == doctest::Approx(769.23076923));
  CHECK(soil.stress_zz<2>(strain) == doctest::Approx(-5769.2307692));
  CHECK(soil.stress_zz<1>(Matrix<1>::Constant(1e-3)) == 0.0);
}

}  // namespace mpm
