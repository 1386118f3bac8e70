/// \file
/// The stability analysis as a program calls it, without the kernels: the uniform body of an analysis, its limits and
/// the declarations of stability_limits(), moved_body_cfl_limit() and stable_at(), which mpm/stability.hpp defines
/// and the library compiles once (mpm/run_1d.cpp, mpm/run_2d.cpp); `mpm run`'s warning limit.
#pragma once
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/io/scene_budget.hpp"
#include "mpm/io/scene_file.hpp"

namespace mpm {

/// What the body of a stability analysis is: a uniform grid of `cells` per axis, every face fixed
/// (a bar or square held at its walls), `ppc` particles per cell and axis at the centres of a uniform
/// subdivision, c = 1 m/s (E = rho = 1), h = 1 m, and the method of the scene options.
struct StabilityBody {
  int dimension = 1;
  int cells = 0;  ///< per axis; 0: 64 / ppc (at least 16) in 1D; in 2D 8 / ppc (at least 4), 3 at 3 ppc, 2 from 4
  int ppc = 1;
  double poisson_ratio = 0.0;
  std::vector<std::string> method;  ///< solver settings as scene overrides (`solver.shape="lme"`, ...)
};

inline int stability_cells(const StabilityBody& body) {
  if (body.cells > 0) return body.cells;
  if (body.dimension == 1) return std::max(16, 64 / body.ppc);
  return body.ppc <= 2 ? 8 / body.ppc : body.ppc == 3 ? 3 : 2;  // at most 1000 unknowns up to 5 ppc (700)
}

/// The unknowns of the body's linearised step (its matrix is dense: the cost grows as their cube).
inline long stability_unknowns(const StabilityBody& body) {
  const long per_axis = long(stability_cells(body)) * body.ppc;
  return (body.dimension == 1 ? per_axis : per_axis * per_axis) * (body.dimension == 1 ? 3 : 7);
}

/// The scene of a stability body (validated like any scene: a bad method setting throws SceneError naming its key).
inline io::Scene stability_scene(const StabilityBody& body) {
  const int cells = stability_cells(body);
  const bool two = body.dimension == 2;
  auto axes = [&](const std::string& value) { return "[" + value + (two ? ", " + value : "") + "]"; };
  std::ostringstream text;
  text << std::setprecision(17);  // the Poisson ratio as it is: 0.4999999 must not print as 0.5, outside [0, 0.5)
  text << "title = \"stability\"\ndimension = " << body.dimension << "\n"
       << "[grid]\norigin = " << axes("0.0") << "\nlength = " << axes(std::to_string(cells) + ".0")
       << "\ncells = " << axes(std::to_string(cells)) << "\n"
       << "[material]\nyoung_modulus = 1.0\ndensity = 1.0\npoisson_ratio = " << body.poisson_ratio << "\n"
       << "[[body]]\nmin = " << axes("0.0") << "\nmax = " << axes(std::to_string(cells) + ".0")
       << "\nparticles_per_cell = " << axes(std::to_string(body.ppc)) << "\n";
  for (const char* face : {"xmin", "xmax", "ymin", "ymax"}) {
    if (!two && face[0] == 'y') continue;
    text << "[[fixed]]\nface = \"" << face << "\"\ncomponents = " << (two ? "[\"x\", \"y\"]" : "[\"x\"]") << "\n";
  }
  text << "[solver]\nend_time = 1.0\n";
  io::SceneFile file = io::parse_scene_text(text.str(), "stability");
  for (size_t k = 0; k < body.method.size(); ++k) io::apply_override(file, body.method[k], static_cast<int>(k) + 1);
  return io::read_scene(file);
}

struct StabilityLimits {
  int particles = 0, unknowns = 0;
  double highest_mode = 0.0;          ///< \f$ \omega_{max} h / c \f$ of the semi-discrete body
  double cfl_limit = 0.0;             ///< the largest CFL with \f$ \rho(\mathbf S) \le 1 \f$, by bisection
  double cfl_limit_from_modes = 0.0;  ///< mode_stability_limit() / highest_mode (NaN where no analysis: a PIC/FLIP blend)
};

/// The limits of the scene's method on the scene's body (built by stability_scene()); the CFL limit by
/// bisection to `relative_tolerance` (mpm/stability.hpp).
template <int Dim>
StabilityLimits stability_limits(const io::Scene& scene, double relative_tolerance = 1e-6);
extern template StabilityLimits stability_limits<1>(const io::Scene&, double);
extern template StabilityLimits stability_limits<2>(const io::Scene&, double);

/// The CFL limit of a scene's own linearised step about rest with every particle moved by `shift` h along x
/// (mpm/stability.hpp).
template <int Dim>
double moved_body_cfl_limit(const io::Scene& scene, double shift, double relative_tolerance = 1e-4);
extern template double moved_body_cfl_limit<1>(const io::Scene&, double, double);

/// Whether the scene's method is stable on the scene's body at `cfl` (mpm/stability.hpp).
template <int Dim>
bool stable_at(const io::Scene& scene, double cfl);
extern template bool stable_at<1>(const io::Scene&, double);
extern template bool stable_at<2>(const io::Scene&, double);

/// The small uniform body on which `mpm run`'s warning judges a scene's method: its shape function, integrator and
/// options, its largest particles per cell and its bodies' largest Poisson ratio, 16 cells in 1D; in 2D 6 x 6 cells
/// at 1 particle per cell, 4 x 4 at 2 and 2 x 2 from 3 (at most 448 unknowns). A small body has fewer modes than
/// the scene, so its limit can lie a little above the scene's (2D linear NPC: 1.447 on 8 x 8 cells against 1.414 in 1D).
inline io::Scene warning_body(const io::Scene& scene) {
  StabilityBody body;
  body.dimension = scene.dimension;
  body.ppc = io::warning_body_ppc(scene);  // as the memory estimate counts it (mpm/io/scene_budget.hpp)
  body.cells = io::warning_body_cells(scene.dimension, body.ppc);
  for (const auto& settings : scene.bodies)  // the largest Poisson ratio: the fastest P-wave for its E, the lowest limit
    body.poisson_ratio = std::max(body.poisson_ratio, settings.material.poisson_ratio);
  io::Scene uniform = stability_scene(body);
  uniform.shape = scene.shape;
  uniform.integrator = scene.integrator;
  uniform.npc_velocity = scene.npc_velocity;
  uniform.newmark_gamma = scene.newmark_gamma;
  uniform.flip_fraction = scene.flip_fraction;
  uniform.stress_update = scene.stress_update;
  uniform.lme_gamma = scene.lme_gamma;
  uniform.lme_tol = scene.lme_tol;
  uniform.lme_beta = scene.lme_beta;
  return uniform;
}

/// The CFL limit of a uniform stability body's method, to 1e-3.
inline double body_cfl_limit(const io::Scene& uniform) {
  return (uniform.dimension == 1 ? stability_limits<1>(uniform, 1e-3) : stability_limits<2>(uniform, 1e-3)).cfl_limit;
}

/// The CFL limit of a scene's method on its warning_body(), to 1e-3.
inline double scene_cfl_limit(const io::Scene& scene) { return body_cfl_limit(warning_body(scene)); }

/// `mpm run`'s warning limit at the cost of one spectral radius when the scene's CFL is stable: NaN (no warning) when the
/// step at the scene's CFL (a fixed step's at t = 0) is stable on warning_body(), scene_cfl_limit() otherwise. A 2D
/// scene's limit takes about ten
/// eigenvalue problems (0.3 s); a run that needs no warning pays for one.
inline double scene_cfl_limit_if_exceeded(const io::Scene& scene) {
  const io::Scene uniform = warning_body(scene);
  const double cfl = io::initial_cfl(scene);  // solver.cfl, or a fixed step's CFL at t = 0
  const bool stable = scene.dimension == 1 ? stable_at<1>(uniform, cfl) : stable_at<2>(uniform, cfl);
  return stable ? std::numeric_limits<double>::quiet_NaN() : body_cfl_limit(uniform);
}

}  // namespace mpm
