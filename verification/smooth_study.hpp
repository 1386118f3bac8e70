// The smooth-data suite's studies as data: each study is a product of axes (methods, particles per cell,
// CFL, amplitude, meshes), expanded into cases, run in parallel and looked up by their axes. The
// analysis of each figure (smooth_claims.hpp, smooth_fig6_2ppc.hpp) reads the cases from here.
#pragma once
#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mpm/fast/lme_fast.hpp"
#include "verification/parallel.hpp"
#include "verification/smooth_case.hpp"

namespace verification::smooth {

/// A method by its shape and integrator, named as verification::method_settings reads them.
struct Method {
  std::string shape, integrator;
  std::string name() const { return shape + "/" + integrator; }
  bool paper() const { return (shape == "linear" || shape == "ugimp" || shape == "lme") && (integrator == "fe" || integrator == "npc"); }
  bool operator==(const Method& other) const { return shape == other.shape && integrator == other.integrator; }
};

inline const std::vector<std::string>& paper_shapes() {
  static const std::vector<std::string> shapes{"linear", "ugimp", "lme"};
  return shapes;
}
inline const std::vector<std::string>& paper_integrators() {
  static const std::vector<std::string> integrators{"fe", "npc"};
  return integrators;
}
inline std::vector<Method> paper_methods() {
  std::vector<Method> methods;
  for (const auto& shape : paper_shapes())
    for (const auto& integrator : paper_integrators()) methods.push_back({shape, integrator});
  return methods;
}
/// Today's baselines (paper/08_test_cases.md, "Today's baselines"): quadratic and cubic B-splines with both
/// integrators, linear shapes with forward Euler and the stress updated last (USL) or modified-last (MUSL).
inline std::vector<Method> bar_baselines() {
  return {{"bspline2", "fe"}, {"bspline2", "npc"}, {"bspline3", "fe"}, {"bspline3", "npc"}, {"linear", "usl"}, {"linear", "musl"}};
}
/// ... and, in the crossing studies (the onset and the Dyka bar at 2 ppc), LME at gamma 0.8 and 1.5.
inline std::vector<Method> crossing_baselines() {
  std::vector<Method> methods = bar_baselines();
  for (const std::string shape : {"lme0.8", "lme1.5"})
    for (const std::string integrator : {"fe", "npc"}) methods.push_back({shape, integrator});
  return methods;
}
inline std::vector<Method> with_paper(const std::vector<Method>& baselines) {
  std::vector<Method> methods = paper_methods();
  methods.insert(methods.end(), baselines.begin(), baselines.end());
  return methods;
}

enum class Group { bar, crossing, dyka, manufactured };
inline const char* group_name(Group group) {
  return group == Group::bar ? "bar" : group == Group::crossing ? "crossing" : group == Group::dyka ? "dyka" : "manufactured";
}

constexpr double small_amplitude = 1e-6, large_amplitude = 0.05;  // the bar's V / (omega L)
constexpr int reference_cells = 2048;                             // the finite-strain reference's mesh
constexpr int crossing_reference_cells = 1024;                    // ... in the crossing sweep, whose errors are larger
constexpr int crossing_cells = 32;
inline const std::vector<double>& crossing_ratios() {  // U / h
  static const std::vector<double> ratios{0.01, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.5, 2.0};
  return ratios;
}

/// One case: a point of a study's axes.
struct Case {
  Group group = Group::bar;
  bool large = false;  ///< bar and manufactured: the large amplitude
  Method method;
  int ppc = 1;
  double cfl = 0.5;
  double ratio = 0.0;  ///< crossing: U / h on crossing_cells cells
  int cells = 0;
  bool operator==(const Case& o) const {
    return group == o.group && large == o.large && method == o.method && ppc == o.ppc && cfl == o.cfl && ratio == o.ratio && cells == o.cells;
  }
  /// The bar's V / (omega L): set by the amplitude, or by U/h on the crossing mesh.
  double amplitude() const { return group == Group::crossing ? ratio / crossing_cells : large ? large_amplitude : small_amplitude; }
};

/// A study: the product of its axes.
struct Axes {
  Group group;
  bool large;
  std::vector<Method> methods;
  std::vector<int> ppc;
  std::vector<double> cfls;
  std::vector<int> cells;
  std::vector<double> ratios{0.0};
};

inline std::vector<Case> expand(const std::vector<Axes>& studies) {
  std::vector<Case> cases;
  for (const Axes& a : studies)
    for (const Method& method : a.methods)
      for (int ppc : a.ppc)
        for (double cfl : a.cfls)
          for (double ratio : a.ratios)
            for (int cells : a.cells) cases.push_back({a.group, a.large, method, ppc, cfl, ratio, cells});
  return cases;
}

/// Every study of the suite. The bar: the paper's methods at 1 and 2 ppc, CFL 0.5 (8-256 cells) and 0.1 (8-128),
/// large amplitude at CFL 0.5; today's baselines at CFL 0.5, 8-128 cells. The crossing onset on 32 cells, U/h swept.
/// The Dyka bar at 2 ppc (crossing from 1011 cells: 1280 and 2560 cross; see smooth_fig6_2ppc.hpp for the meshes
/// of each method). The 2D manufactured solutions: the paper's methods at 1x1 and 2x2 ppc, 8-32 cells per side,
/// today's baselines at 2x2, 12-32.
inline std::vector<Axes> studies() {
  const auto paper = paper_methods(), baselines = bar_baselines();
  const std::vector<int> bar_cells{8, 16, 32, 64, 128, 256}, bar_cells_01{8, 16, 32, 64, 128}, baseline_cells{8, 16, 32, 64, 128};
  std::vector<Method> dyka_short, dyka_long, lme_fe_baselines, other_baselines;
  for (const Method& m : paper) (m.integrator == "npc" && m.shape != "lme" ? dyka_short : dyka_long).push_back(m);
  for (const Method& m : crossing_baselines())
    (m.integrator == "fe" && m.shape.rfind("lme", 0) == 0 ? lme_fe_baselines : other_baselines).push_back(m);
  return {
      {Group::bar, false, paper, {1, 2}, {0.5}, bar_cells},
      {Group::bar, false, paper, {1, 2}, {0.1}, bar_cells_01},
      {Group::bar, true, paper, {1, 2}, {0.5}, bar_cells},
      {Group::bar, false, baselines, {1, 2}, {0.5}, baseline_cells},
      {Group::bar, true, baselines, {1, 2}, {0.5}, baseline_cells},
      {Group::crossing, false, with_paper(crossing_baselines()), {1, 2}, {0.5}, {crossing_cells}, crossing_ratios()},
      // 2560 cells at 2 ppc where the 1-ppc run drifts or stops there; 5120 not run (4x the 2560-cell set)
      {Group::dyka, false, dyka_short, {2}, {0.5}, {40, 160, 1280}},
      {Group::dyka, false, dyka_long, {2}, {0.5}, {40, 160, 1280, 2560}},
      {Group::dyka, false, lme_fe_baselines, {2}, {0.5}, {160}},
      {Group::dyka, false, other_baselines, {2}, {0.5}, {160, 1280}},
      {Group::manufactured, false, paper, {1, 2}, {0.5}, {8, 12, 16, 24, 32}},
      {Group::manufactured, true, paper, {1, 2}, {0.5}, {8, 12, 16, 24, 32}},
      {Group::manufactured, false, baselines, {2}, {0.5}, {12, 16, 24, 32}},
      {Group::manufactured, true, baselines, {2}, {0.5}, {12, 16, 24, 32}},
  };
}

/// Nodes a particle's shape function reaches along one axis, from the shapes' supports: linear 2, uGIMP and the
/// quadratic B-spline 3, the cubic 4, LME 2R/h + 1 with R/h = sqrt(-ln(support tolerance) / gamma) (mpm/shape/lme_options.hpp).
inline double stencil_width(const std::string& shape) {
  if (shape == "linear") return 2.0;
  if (shape == "ugimp" || shape == "bspline2") return 3.0;
  if (shape == "bspline3") return 4.0;
  const double gamma = shape.size() > 3 ? std::stod(shape.substr(3)) : 3.0;
  return 2.0 * std::sqrt(-std::log(mpm::LmeOptions{}.support_tolerance) / gamma) + 1.0;
}

/// The scenes' sizes a case's work is derived from.
struct SceneSizes {
  double dyka_end_over_wave_time = 0.0;  ///< the Dyka bar: end time over L / c
  double manufactured_end_over_wave_time = 0.0;
  static double wave_time(const mpm::io::Scene& s) { return s.length[0] / std::sqrt(s.young_modulus / s.density); }
  SceneSizes(const std::string& dyka, const std::string& manufactured) {
    const auto d = mpm::load_scene(dyka, {}), m = mpm::load_scene(manufactured, {});
    dyka_end_over_wave_time = d.control.end_time / wave_time(d);
    manufactured_end_over_wave_time = m.control.end_time / wave_time(m);
  }
};

/// A case's work, for the order of the queue (longest first): particles x steps x stencil nodes, the steps
/// (end time) / (CFL h / c) derived from its scene (the vibrating bar runs one period, 4 L / c).
inline double work(const Case& c, const SceneSizes& sizes) {
  const int dim = c.group == Group::manufactured ? 2 : 1;
  const double end_over_wave = c.group == Group::dyka ? sizes.dyka_end_over_wave_time
                               : c.group == Group::manufactured ? sizes.manufactured_end_over_wave_time : 4.0;
  const double steps = end_over_wave * c.cells / c.cfl;
  return std::pow(double(c.cells) * c.ppc * stencil_width(c.method.shape), dim) * steps;
}

}  // namespace verification::smooth
