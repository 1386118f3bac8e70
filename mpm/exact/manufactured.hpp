/// \file
/// Manufactured solutions of 2D plane-strain elastodynamics on the square [0, L]^2: a smooth
/// motion chosen in advance and the body force per unit mass that makes it exact, so the 2D
/// kernels can be verified at an observed order of convergence. They share no code with the solver.
///
/// The momentum balance the solver discretises is \f$ \rho\,\dot{\mathbf v} = \nabla_x\cdot\boldsymbol\sigma + \rho\,\mathbf b \f$
/// (Eq. 2), so \f$ \mathbf b = \dot{\mathbf v} - \rho^{-1}\nabla_x\cdot\boldsymbol\sigma \f$ for the chosen motion.
/// Which stress? The solver integrates the rate of deformation, \f$ \boldsymbol\varepsilon \mathrel{+}= \Delta t\,
/// \mathrm{sym}\,\nabla_x\mathbf v \f$ (Eq. 16), applies Hooke's law (Eq. 3) to that strain and updates the
/// density by Eq. (17). Two cases are exact for it:
///
/// - **Small amplitude** (ManufacturedSmall): any smooth field, here
///   \f$ u_x = A\sin\omega t\,\sin\kappa X\sin\kappa Y \f$, \f$ u_y = A\sin\omega t\,\sin 2\kappa X\sin\kappa Y \f$,
///   \f$ \kappa = \pi/L \f$, with shear and both Lamé constants at work. Linear elasticity:
///   \f$ \mathbf b = \ddot{\mathbf u} - \rho_0^{-1}\left[(\lambda + G)\nabla(\nabla\cdot\mathbf u) + G\,\Delta\mathbf u\right] \f$.
///   The solver's strain, density and configuration differ from the linear ones by
///   \f$ O(|\nabla\mathbf u|^2) \f$, a relative \f$ O(\kappa A) \f$ (1e-6 in the suite), far below its
///   discretisation error; b may be evaluated at X or at x alike (they differ by \f$ O(A^2) \f$).
///   u = 0 on the whole boundary: every face is fixed in both components.
/// - **Large amplitude** (ManufacturedLarge): the integrated rate of deformation is a strain of
///   F only when the principal axes of stretch stay fixed in the body and in space, so this case is
///   restricted to motions whose deformation gradient is diagonal, each axis stretched on its own:
///   \f$ x = x(X, t) \f$, \f$ y = y(Y, t) \f$. Then \f$ \mathbf L = \mathrm{diag}(\dot\lambda_1/\lambda_1, \dot\lambda_2/\lambda_2) \f$,
///   the solver's strain is exactly \f$ \mathrm{diag}(\ln\lambda_1, \ln\lambda_2) \f$ (Hencky), its density
///   \f$ \rho_0/(\lambda_1\lambda_2) \f$, and its Cauchy stress \f$ \sigma_{xx} = \lambda\ln(\lambda_1\lambda_2) + 2G\ln\lambda_1 \f$,
///   \f$ \sigma_{yy} = \lambda\ln(\lambda_1\lambda_2) + 2G\ln\lambda_2 \f$, \f$ \sigma_{xy} = 0 \f$. The
///   two axes couple through \f$ \lambda\ln(\lambda_1\lambda_2) \f$ and the density. A general motion
///   (with rotation of the principal axes) would make the solver's stress path-dependent, with
///   no closed form; we do not manufacture it. The motion is given by its inverse, so that the body
///   force is a closed form of the current position x (where the solver evaluates it):
///   \f$ X = x - a_x s(t)\sin\kappa x \f$, \f$ Y = y - a_y s(t)\sin 2\kappa y \f$, \f$ s = \sin\omega t \f$. With
///   \f$ f_1 = \partial X/\partial x = 1 - a_x s\,\kappa\cos\kappa x = 1/\lambda_1 \f$ (likewise \f$ f_2 \f$):
///   \f$ v_x = a_x\dot s\sin\kappa x / f_1 \f$, \f$ \dot v_x = \partial_t v_x + v_x\partial_x v_x \f$,
///   \f$ \partial_x\sigma_{xx} = -(\lambda + 2G)\,\partial_x f_1/f_1 \f$ and
///   \f$ b_x = \dot v_x - \partial_x\sigma_{xx}/(\rho_0 f_1 f_2) \f$. The normal displacement vanishes on
///   every face and \f$ \sigma_{xy} = 0 \f$ everywhere, so every face is a roller (fixed normal
///   component, free tangential one).
///
/// Both start undeformed and unstressed, with the velocity \f$ \mathbf v(\mathbf X, 0) \f$ given by
/// initial_velocity(). Stresses are Cauchy stresses, tension positive; \f$ \lambda, G \f$ are the
/// Lamé constants of (E, nu).
#pragma once
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace mpm::exact {

/// A 2D vector (x, y).
using Pair = std::array<double, 2>;

/// In-plane Cauchy stress and the out-of-plane one of plane strain.
struct PlaneStress {
  double xx = 0.0, yy = 0.0, xy = 0.0, zz = 0.0;
};

/// The material and the frequency shared by both manufactured motions.
struct ManufacturedMaterial {
  double length;         ///< L, m: the square [0, L]^2
  double young_modulus;  ///< E, Pa
  double poisson_ratio;  ///< nu
  double density;        ///< rho_0, kg/m^3

  double shear_modulus() const { return young_modulus / (2.0 * (1.0 + poisson_ratio)); }
  double lame_lambda() const { return poisson_ratio * young_modulus / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio)); }
  /// \f$ c_p = \sqrt{(\lambda + 2G)/\rho_0} \f$
  double pressure_wave_speed() const { return std::sqrt((lame_lambda() + 2.0 * shear_modulus()) / density); }
  /// \f$ \kappa = \pi / L \f$
  double wave_number() const { return pi / length; }
  /// The frequency of both motions, \f$ \omega = c_p\kappa \f$ (a choice: any would do).
  double angular_frequency() const { return pressure_wave_speed() * wave_number(); }
  void validate() const {
    if (!(length > 0.0) || !(young_modulus > 0.0) || !(density > 0.0) || !(poisson_ratio >= 0.0 && poisson_ratio < 0.5))
      throw std::invalid_argument("manufactured solution: L, E, rho must be positive and nu in [0, 0.5)");
  }
  static constexpr double pi = 3.14159265358979323846;
};

/// Small amplitude, linear elasticity, any direction of motion; u = 0 on the boundary.
class ManufacturedSmall {
 public:
  ManufacturedSmall(ManufacturedMaterial material, double amplitude) : m_(material), a_(amplitude) { m_.validate(); }

  const ManufacturedMaterial& material() const { return m_; }
  double amplitude() const { return a_; }
  /// \f$ A\omega \f$, the scale of the velocity.
  double velocity_scale() const { return a_ * m_.angular_frequency(); }
  /// \f$ (\lambda + 2G)\kappa A \f$, the scale of the stress.
  double stress_scale() const { return (m_.lame_lambda() + 2.0 * m_.shear_modulus()) * m_.wave_number() * a_; }

  Pair displacement(const Pair& X, double t) const {
    const double s = std::sin(m_.angular_frequency() * t);
    return {a_ * s * shape_x(X), a_ * s * shape_y(X)};
  }
  Pair velocity(const Pair& X, double t) const {
    const double w = m_.angular_frequency(), ds = w * std::cos(w * t);
    return {a_ * ds * shape_x(X), a_ * ds * shape_y(X)};
  }
  Pair initial_velocity(const Pair& X) const { return velocity(X, 0.0); }
  PlaneStress stress(const Pair& X, double t) const {
    const double k = m_.wave_number(), s = a_ * std::sin(m_.angular_frequency() * t);
    const double sx = std::sin(k * X[0]), cx = std::cos(k * X[0]), sy = std::sin(k * X[1]), cy = std::cos(k * X[1]);
    const double s2x = std::sin(2.0 * k * X[0]), c2x = std::cos(2.0 * k * X[0]);
    const double exx = s * k * cx * sy, eyy = s * k * s2x * cy;
    const double exy = 0.5 * s * (k * sx * cy + 2.0 * k * c2x * sy);
    const double lambda = m_.lame_lambda(), G = m_.shear_modulus(), trace = exx + eyy;
    return {lambda * trace + 2.0 * G * exx, lambda * trace + 2.0 * G * eyy, 2.0 * G * exy, lambda * trace};
  }
  /// b at the point x (= X up to O(A)) and time t, m/s^2.
  Pair body_force(const Pair& x, double t) const {
    const double k = m_.wave_number(), w = m_.angular_frequency(), s = a_ * std::sin(w * t);
    const double sx = std::sin(k * x[0]), cx = std::cos(k * x[0]), sy = std::sin(k * x[1]), cy = std::cos(k * x[1]);
    const double s2x = std::sin(2.0 * k * x[0]), c2x = std::cos(2.0 * k * x[0]);
    const double lambda = m_.lame_lambda(), G = m_.shear_modulus(), rho = m_.density;
    // grad(div u) and the Laplacian of u, by hand from the closed form of u
    const double grad_div_x = s * k * k * (-sx * sy + 2.0 * c2x * cy), grad_div_y = s * k * k * (cx * cy - s2x * sy);
    const double laplacian_x = -2.0 * k * k * s * sx * sy, laplacian_y = -5.0 * k * k * s * s2x * sy;
    const double div_sigma_x = (lambda + G) * grad_div_x + G * laplacian_x, div_sigma_y = (lambda + G) * grad_div_y + G * laplacian_y;
    return {-w * w * s * sx * sy - div_sigma_x / rho, -w * w * s * s2x * sy - div_sigma_y / rho};
  }

 private:
  ManufacturedMaterial m_;
  double a_;
  double shape_x(const Pair& X) const { return std::sin(m_.wave_number() * X[0]) * std::sin(m_.wave_number() * X[1]); }
  double shape_y(const Pair& X) const { return std::sin(2.0 * m_.wave_number() * X[0]) * std::sin(m_.wave_number() * X[1]); }
};

/// Large amplitude, finite strain as the solver integrates it: each axis stretched on its own
/// (diagonal deformation gradient); every face a roller.
class ManufacturedLarge {
 public:
  /// amplitude_x = a_x, amplitude_y = a_y (m); the stretches stay positive when \f$ \kappa a_x < 1 \f$, \f$ 2\kappa a_y < 1 \f$.
  ManufacturedLarge(ManufacturedMaterial material, double amplitude_x, double amplitude_y)
      : m_(material), a_{amplitude_x, amplitude_y} {
    m_.validate();
    if (!(std::abs(a_[0]) * m_.wave_number() < 0.9 && 2.0 * std::abs(a_[1]) * m_.wave_number() < 0.9))
      throw std::invalid_argument("ManufacturedLarge: kappa a_x and 2 kappa a_y must stay below 0.9");
  }

  const ManufacturedMaterial& material() const { return m_; }
  /// \f$ \omega \max(a_x, a_y) \f$, the scale of the velocity.
  double velocity_scale() const { return m_.angular_frequency() * std::max(std::abs(a_[0]), std::abs(a_[1])); }
  /// \f$ (\lambda + 2G)\kappa \max(a_x, 2a_y) \f$, the scale of the stress.
  double stress_scale() const {
    return (m_.lame_lambda() + 2.0 * m_.shear_modulus()) * m_.wave_number() * std::max(std::abs(a_[0]), 2.0 * std::abs(a_[1]));
  }

  /// The current position x(X, t): the root of \f$ X = x - a s(t) \sin(m\kappa x) \f$ on each axis (Newton).
  Pair position(const Pair& X, double t) const {
    Pair x{};
    for (int axis = 0; axis < 2; ++axis) {
      double guess = X[axis];
      for (int iteration = 0; iteration < 50; ++iteration) {
        const double residual = guess - a_[axis] * s(t) * g(axis, guess) - X[axis];
        const double step = residual / f(axis, guess, t);
        guess -= step;
        if (std::abs(step) <= 1e-15 * m_.length) break;
      }
      x[axis] = guess;
    }
    return x;
  }
  /// Velocity of the material point X at time t, m/s.
  Pair velocity(const Pair& X, double t) const { return velocity_at(position(X, t), t); }
  Pair initial_velocity(const Pair& X) const { return velocity_at(X, 0.0); }
  /// Cauchy stress of the material point X at time t (the solver's: Hooke's law of the Hencky strain).
  PlaneStress stress(const Pair& X, double t) const {
    const Pair x = position(X, t);
    const double log1 = -std::log(f(0, x[0], t)), log2 = -std::log(f(1, x[1], t));  // ln lambda_1, ln lambda_2
    const double lambda = m_.lame_lambda(), G = m_.shear_modulus();
    return {lambda * (log1 + log2) + 2.0 * G * log1, lambda * (log1 + log2) + 2.0 * G * log2, 0.0, lambda * (log1 + log2)};
  }
  /// b at the current position x and time t, m/s^2.
  Pair body_force(const Pair& x, double t) const {
    const double M = m_.lame_lambda() + 2.0 * m_.shear_modulus();
    const double density = m_.density * f(0, x[0], t) * f(1, x[1], t);  // rho_0 / (lambda_1 lambda_2)
    Pair b{};
    for (int axis = 0; axis < 2; ++axis) {
      const double xi = x[axis], fa = f(axis, xi, t), f_x = -a_[axis] * s(t) * g_xx(axis, xi), f_t = -a_[axis] * s_t(t) * g_x(axis, xi);
      const double v = a_[axis] * s_t(t) * g(axis, xi) / fa;
      const double v_t = a_[axis] * (s_tt(t) * g(axis, xi) / fa - s_t(t) * g(axis, xi) * f_t / (fa * fa));
      const double v_x = a_[axis] * s_t(t) * (g_x(axis, xi) / fa - g(axis, xi) * f_x / (fa * fa));
      const double div_sigma = -M * f_x / fa;
      b[axis] = v_t + v * v_x - div_sigma / density;
    }
    return b;
  }

 private:
  ManufacturedMaterial m_;
  Pair a_;

  double s(double t) const { return std::sin(m_.angular_frequency() * t); }
  double s_t(double t) const { return m_.angular_frequency() * std::cos(m_.angular_frequency() * t); }
  double s_tt(double t) const { return -m_.angular_frequency() * m_.angular_frequency() * s(t); }
  double k(int axis) const { return (axis == 0 ? 1.0 : 2.0) * m_.wave_number(); }
  double g(int axis, double x) const { return std::sin(k(axis) * x); }
  double g_x(int axis, double x) const { return k(axis) * std::cos(k(axis) * x); }
  double g_xx(int axis, double x) const { return -k(axis) * k(axis) * std::sin(k(axis) * x); }
  /// \f$ f = \partial X/\partial x = 1 - a s g'(x) = 1/\lambda \f$
  double f(int axis, double x, double t) const { return 1.0 - a_[axis] * s(t) * g_x(axis, x); }
  Pair velocity_at(const Pair& x, double t) const {
    return {a_[0] * s_t(t) * g(0, x[0]) / f(0, x[0], t), a_[1] * s_t(t) * g(1, x[1]) / f(1, x[1], t)};
  }
};

// The checks below rebuild sigma, div sigma and the acceleration by finite differences of the
// motion alone (displacement or position map), never from the closed-form stress or body force.
// Soil-like material: L = 1 m, E = 10 MPa, nu = 0.3, rho = 2000 kg/m^3.

TEST_CASE("exact::ManufacturedSmall: b = u_tt - div sigma / rho by finite differences of u, u = 0 on the boundary") {
  const ManufacturedMaterial material{1.0, 10e6, 0.3, 2000.0};
  const ManufacturedSmall mms(material, 1e-3);
  const double lambda = material.lame_lambda(), G = material.shear_modulus(), T = 2.0 * ManufacturedMaterial::pi / material.angular_frequency();
  CHECK(lambda == doctest::Approx(10e6 * 0.3 / (1.3 * 0.4)).epsilon(1e-14));
  CHECK(G == doctest::Approx(10e6 / 2.6).epsilon(1e-14));
  const double d = 1e-4, dt = 1e-4 * T;
  auto u = [&](double x, double y, double t) { return mms.displacement({x, y}, t); };
  // Stress from finite-difference strains of u (central differences).
  auto stress_fd = [&](double x, double y, double t) {
    const double exx = (u(x + d, y, t)[0] - u(x - d, y, t)[0]) / (2 * d), eyy = (u(x, y + d, t)[1] - u(x, y - d, t)[1]) / (2 * d);
    const double exy = 0.5 * ((u(x, y + d, t)[0] - u(x, y - d, t)[0]) / (2 * d) + (u(x + d, y, t)[1] - u(x - d, y, t)[1]) / (2 * d));
    return PlaneStress{lambda * (exx + eyy) + 2 * G * exx, lambda * (exx + eyy) + 2 * G * eyy, 2 * G * exy, lambda * (exx + eyy)};
  };
  for (const Pair X : {Pair{0.2, 0.3}, Pair{0.55, 0.9}, Pair{0.81, 0.47}})
    for (double t : {0.1 * T, 0.37 * T}) {
      const PlaneStress exact = mms.stress(X, t), fd = stress_fd(X[0], X[1], t);
      const double scale = mms.stress_scale();
      CHECK(std::abs(exact.xx - fd.xx) <= 1e-6 * scale);
      CHECK(std::abs(exact.yy - fd.yy) <= 1e-6 * scale);
      CHECK(std::abs(exact.xy - fd.xy) <= 1e-6 * scale);
      CHECK(std::abs(exact.zz - fd.zz) <= 1e-6 * scale);
      // div sigma by central differences of the finite-difference stress, acceleration by u_tt
      const double D = 1e-3;
      const double div_x = (stress_fd(X[0] + D, X[1], t).xx - stress_fd(X[0] - D, X[1], t).xx) / (2 * D) +
                           (stress_fd(X[0], X[1] + D, t).xy - stress_fd(X[0], X[1] - D, t).xy) / (2 * D);
      const double div_y = (stress_fd(X[0] + D, X[1], t).xy - stress_fd(X[0] - D, X[1], t).xy) / (2 * D) +
                           (stress_fd(X[0], X[1] + D, t).yy - stress_fd(X[0], X[1] - D, t).yy) / (2 * D);
      const Pair a{(u(X[0], X[1], t + dt)[0] - 2 * u(X[0], X[1], t)[0] + u(X[0], X[1], t - dt)[0]) / (dt * dt),
                   (u(X[0], X[1], t + dt)[1] - 2 * u(X[0], X[1], t)[1] + u(X[0], X[1], t - dt)[1]) / (dt * dt)};
      const Pair b = mms.body_force(X, t);
      const double b_scale = material.angular_frequency() * material.angular_frequency() * mms.amplitude();
      CHECK(std::abs(b[0] - (a[0] - div_x / material.density)) <= 1e-5 * b_scale);
      CHECK(std::abs(b[1] - (a[1] - div_y / material.density)) <= 1e-5 * b_scale);
      // v = u_t
      const Pair v = mms.velocity(X, t);
      CHECK(std::abs(v[0] - (u(X[0], X[1], t + dt)[0] - u(X[0], X[1], t - dt)[0]) / (2 * dt)) <= 1e-6 * mms.velocity_scale());
      CHECK(std::abs(v[1] - (u(X[0], X[1], t + dt)[1] - u(X[0], X[1], t - dt)[1]) / (2 * dt)) <= 1e-6 * mms.velocity_scale());
    }
  for (double along : {0.0, 0.3, 0.71, 1.0})
    for (const Pair X : {Pair{0.0, along}, Pair{1.0, along}, Pair{along, 0.0}, Pair{along, 1.0}}) {
      const Pair boundary = mms.displacement(X, 0.3 * T);
      CHECK(std::abs(boundary[0]) <= 1e-15);
      CHECK(std::abs(boundary[1]) <= 1e-15);
    }
  // By hand: at X = (1/2, 1/2), t = T/4: u = (A, 0), v = 0; the stress has only
  // exy = (A/2)(kappa sin(pi/2) cos(pi/2) + 2 kappa cos(pi) sin(pi/2)) = -A kappa, so sigma_xy = -2 G A kappa.
  CHECK(mms.displacement({0.5, 0.5}, 0.25 * T)[0] == doctest::Approx(1e-3).epsilon(1e-12));
  CHECK(mms.stress({0.5, 0.5}, 0.25 * T).xy == doctest::Approx(-2.0 * G * 1e-3 * ManufacturedMaterial::pi).epsilon(1e-12));
  CHECK(mms.initial_velocity({0.5, 0.5})[0] == doctest::Approx(1e-3 * material.angular_frequency()).epsilon(1e-12));
}

TEST_CASE("exact::ManufacturedLarge: b = dv/dt - div sigma / rho from the position map alone, with Hencky strain and rho_0/J") {
  const ManufacturedMaterial material{1.0, 10e6, 0.3, 2000.0};
  const ManufacturedLarge mms(material, 0.06, 0.03);  // stretches 1 -+ 0.19
  const double lambda = material.lame_lambda(), G = material.shear_modulus(), T = 2.0 * ManufacturedMaterial::pi / material.angular_frequency();
  const double dX = 1e-5, dt = 1e-5 * T;
  for (const Pair X : {Pair{0.2, 0.3}, Pair{0.55, 0.9}, Pair{0.81, 0.47}})
    for (double t : {0.1 * T, 0.25 * T, 0.37 * T}) {
      const Pair x = mms.position(X, t);
      // The inverse map holds: X = x - a s sin(m kappa x).
      const double s = std::sin(material.angular_frequency() * t);
      CHECK(x[0] - 0.06 * s * std::sin(ManufacturedMaterial::pi * x[0]) == doctest::Approx(X[0]).epsilon(1e-13));
      CHECK(x[1] - 0.03 * s * std::sin(2.0 * ManufacturedMaterial::pi * x[1]) == doctest::Approx(X[1]).epsilon(1e-13));
      // Stretches by finite differences of x(X, t); Hencky strain; Hooke's law.
      auto stretches = [&](const Pair& P, double time) {
        return Pair{(mms.position({P[0] + dX, P[1]}, time)[0] - mms.position({P[0] - dX, P[1]}, time)[0]) / (2 * dX),
                    (mms.position({P[0], P[1] + dX}, time)[1] - mms.position({P[0], P[1] - dX}, time)[1]) / (2 * dX)};
      };
      auto sigma = [&](const Pair& P, double time) {
        const Pair l = stretches(P, time);
        return Pair{lambda * std::log(l[0] * l[1]) + 2 * G * std::log(l[0]), lambda * std::log(l[0] * l[1]) + 2 * G * std::log(l[1])};
      };
      const Pair l = stretches(X, t), closed_sigma = {mms.stress(X, t).xx, mms.stress(X, t).yy};
      CHECK(std::abs(closed_sigma[0] - sigma(X, t)[0]) <= 1e-7 * mms.stress_scale());
      CHECK(std::abs(closed_sigma[1] - sigma(X, t)[1]) <= 1e-7 * mms.stress_scale());
      CHECK(mms.stress(X, t).xy == 0.0);
      // div_x sigma = (d sigma_xx / dX) / lambda_1 (sigma_xy = 0), by differences in X
      const double D = 1e-4;
      const double div_x = (sigma({X[0] + D, X[1]}, t)[0] - sigma({X[0] - D, X[1]}, t)[0]) / (2 * D) / l[0];
      const double div_y = (sigma({X[0], X[1] + D}, t)[1] - sigma({X[0], X[1] - D}, t)[1]) / (2 * D) / l[1];
      const double density = material.density / (l[0] * l[1]);
      // acceleration of the material point: second difference of x(X, t) in t
      const Pair before = mms.position(X, t - dt), after = mms.position(X, t + dt);
      const Pair a{(after[0] - 2 * x[0] + before[0]) / (dt * dt), (after[1] - 2 * x[1] + before[1]) / (dt * dt)};
      const Pair v = mms.velocity(X, t), b = mms.body_force(x, t);
      const double b_scale = material.angular_frequency() * material.angular_frequency() * 0.06;
      CHECK(std::abs(b[0] - (a[0] - div_x / density)) <= 1e-4 * b_scale);
      CHECK(std::abs(b[1] - (a[1] - div_y / density)) <= 1e-4 * b_scale);
      CHECK(std::abs(v[0] - (after[0] - before[0]) / (2 * dt)) <= 1e-7 * mms.velocity_scale());
      CHECK(std::abs(v[1] - (after[1] - before[1]) / (2 * dt)) <= 1e-7 * mms.velocity_scale());
    }
  // Rollers: the normal component of the motion vanishes on every face.
  for (double along : {0.0, 0.4, 1.0}) {
    CHECK(std::abs(mms.position({0.0, along}, 0.3 * T)[0]) <= 1e-15);
    CHECK(std::abs(mms.position({1.0, along}, 0.3 * T)[0] - 1.0) <= 1e-14);
    CHECK(std::abs(mms.position({along, 0.0}, 0.3 * T)[1]) <= 1e-15);
    CHECK(std::abs(mms.position({along, 1.0}, 0.3 * T)[1] - 1.0) <= 1e-14);
  }
  // By hand at t = T/4 (s = 1), X = 0: f_1 = 1 - 0.06 pi, so lambda_1 = 1/(1 - 0.06 pi) = 1.2324;
  // Y = 0.25: x = 0.25 + 0.03 sin(2 pi x) is solved near y = 0.28; the initial velocity at
  // (1/2, 1/4) is (0.06 omega, 0.03 omega).
  CHECK(mms.initial_velocity({0.5, 0.25})[0] == doctest::Approx(0.06 * material.angular_frequency()).epsilon(1e-12));
  CHECK(mms.initial_velocity({0.5, 0.25})[1] == doctest::Approx(0.03 * material.angular_frequency()).epsilon(1e-12));
  const double log_stretch = -std::log(1.0 - 0.06 * ManufacturedMaterial::pi);
  CHECK(log_stretch == doctest::Approx(std::log(1.2324)).epsilon(1e-4));
  CHECK(mms.stress({0.0, 0.5}, 0.25 * T).xx - mms.stress({0.0, 0.5}, 0.25 * T).zz ==
        doctest::Approx(2.0 * G * log_stretch).epsilon(1e-12));
  CHECK_THROWS_AS(ManufacturedLarge(material, 0.3, 0.0), std::invalid_argument);
}

}  // namespace mpm::exact
