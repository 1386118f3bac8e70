// The CSV files of the soil-block figures (gnuplot reads them; verification/plots/soil_*.gp).
#pragma once
#include <algorithm>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

#include "verification/soil_measures.hpp"

namespace verification {

inline std::ofstream csv(const std::string& path, const std::string& header) {
  std::ofstream out(path);
  out << std::setprecision(10) << header << "\n";
  return out;
}

/// Fig. 11, from the scene itself: the scene's box (the block), the grid lines (x1,y1,x2,y2), the nodes
/// with in_box = 1 inside the box, the particles, every fixed degree of freedom (component 0 = x,
/// 1 = y) and the observed particle.
inline void write_geometry(const mpm::io::Scene& scene, const std::string& folder) {
  const mpm::Setup<2> setup = mpm::build_setup<2>(scene);
  const mpm::Grid<2>& grid = setup.model.grid;
  const double h = grid.spacing();
  const mpm::Vector<2> low = grid.origin(), high = low + h * mpm::Vector<2>(grid.cells(0), grid.cells(1));
  auto box = csv(folder + "/soil_geometry_box.csv", "xmin,ymin,xmax,ymax");
  box << scene.origin[0] << "," << scene.origin[1] << "," << scene.origin[0] + scene.length[0] << "," << scene.origin[1] + scene.length[1] << "\n";
  auto lines = csv(folder + "/soil_geometry_grid.csv", "x1,y1,x2,y2");
  for (int i = 0; i <= grid.cells(0); ++i) lines << low[0] + i * h << "," << low[1] << "," << low[0] + i * h << "," << high[1] << "\n";
  for (int j = 0; j <= grid.cells(1); ++j) lines << low[0] << "," << low[1] + j * h << "," << high[0] << "," << low[1] + j * h << "\n";
  auto nodes = csv(folder + "/soil_geometry_nodes.csv", "x,y,in_box");
  for (int node = 0; node < grid.node_count(); ++node) {
    const mpm::Vector<2> x = grid.node_position(node);
    bool inside = true;
    for (int axis = 0; axis < 2; ++axis)
      inside = inside && x[axis] >= scene.origin[axis] - 1e-9 && x[axis] <= scene.origin[axis] + scene.length[axis] + 1e-9;
    nodes << x[0] << "," << x[1] << "," << inside << "\n";
  }
  auto particles = csv(folder + "/soil_geometry_particles.csv", "x,y");
  for (const auto& x : setup.particles.position) particles << x[0] << "," << x[1] << "\n";
  auto fixed = csv(folder + "/soil_geometry_fixed.csv", "x,y,component");
  for (const auto& dof : setup.model.fixed) {
    const mpm::Vector<2> x = grid.node_position(dof.node);
    fixed << x[0] << "," << x[1] << "," << dof.component << "\n";
  }
  auto observer = csv(folder + "/soil_geometry_observer.csv", "x,y");
  observer << setup.particles.position[setup.observed.at(0)][0] << "," << setup.particles.position[setup.observed[0]][1] << "\n";
}

/// Fig. 13: t, u_y of the observed particle, u_exact at its reference height, and the static settlement there of the
/// finite-strain column (the model the solver discretises; constant).
inline void write_settlement(const SoilResult& result, const SettlementMeasures& measures, const std::string& path) {
  auto out = csv(path, "t,u,u_exact,u_finite_strain_static");
  for (size_t n = 0; n < result.time.size(); ++n)
    out << result.time[n] << "," << result.displacement[n] << "," << measures.exact[n] << "," << measures.static_log_strain << "\n";
}

/// Fig. 12, the maps: every particle at a snapshot, with the exact sigma_yy at its reference height.
inline void write_particle_stress(const SoilResult& result, const SoilSnapshot& snap, const std::string& path) {
  const auto column = exact_column(result.scene);
  auto out = csv(path, "x,y,X,Y,sigma_xx,sigma_yy,sigma_yy_exact");
  for (const auto& p : snap.particles)
    out << p.x << "," << p.y << "," << p.reference_x << "," << p.reference_y << "," << p.sigma_xx << "," << p.sigma_yy
        << "," << column.stress(p.reference_y, snap.time) << "\n";
}

/// Fig. 12, the profiles: the exact sigma_yy(Y, t) against the current height Y + u_exact(Y, t)
/// (small strain, paper/07_exact_column.md), and the static finite-strain column (stress, Y + u(Y)), 201 points.
inline void write_stress_profile(const mpm::io::Scene& scene, double time, const std::string& path) {
  const auto column = exact_column(scene);
  const auto log_strain = log_strain_column(scene);
  auto out = csv(path, "Y,y_exact,sigma_exact,y_log_strain_static,sigma_static");
  const double height = scene.length[1];
  for (int k = 0; k <= 200; ++k) {
    const double y = height * k / 200.0;
    out << y << "," << y + column.displacement(y, time) << "," << column.stress(y, time) << ","
        << y + log_strain.displacement(y) << "," << log_strain.stress(y) << "\n";
  }
}

/// The refinement figure: one row per cell size h of one shape function; completed = 0 marks a failed run. The gap to
/// the finite-strain column also signed, with its estimator's floor (SettlementMeasures::mean_floor).
inline void write_refinement(const std::vector<const SoilOutcome*>& sizes, const std::string& path) {
  auto out = csv(path, "h,rms_error,abs_final_error,abs_mean_minus_log_strain_static,model_gap,completed,"
                       "mean_minus_log_strain_static,mean_floor");
  for (const auto* o : sizes) {
    const auto& s = o->settlement;
    out << o->result.scene.spacing << "," << s.rms_error << "," << std::abs(s.final_error) << ","
        << std::abs(s.mean_settlement - s.static_log_strain) << "," << std::abs(s.static_log_strain - s.static_small_strain) << ","
        << !o->result.failed << "," << s.mean_settlement - s.static_log_strain << "," << s.mean_floor << "\n";
  }
}

/// One line per run: its settings, cost and measures; cpu_seconds is the first run's, cpu_fastest and cpu_slowest the
/// range of its timing repeats (the runs of the 2 m grid's error-cost fronts; else the first run's, repeats 0), then the
/// bands the verdicts use: the RMS's, the mean settlement's floor and the energy drift's.
inline void write_summary(const std::vector<SoilOutcome>& outcomes, const std::string& path) {
  auto out = csv(path,
                 "name,shape,lme_gamma,integrator,h,nu,X,Y,steps,wall_seconds,solver_seconds,u_final,u_exact_final,final_error,"
                 "rms_error,mean_settlement,swing,static_small_strain,static_log_strain,energy_drift,largest_mass_mismatch,status,"
                 "newton_mean,newton_max,neighbours_mean,stress_update,cpu_seconds,cpu_fastest,cpu_slowest,repeats,rms_band,mean_floor,"
                 "energy_drift_band");
  for (const auto& o : outcomes) {
    const auto& r = o.result;
    const auto& s = o.settlement;
    out << r.name << "," << mpm::io::name_of(r.scene.shape) << "," << r.scene.lme_gamma << "," << mpm::io::name_of(r.scene.integrator) << "," << r.scene.spacing << ","
        << r.scene.poisson_ratio << "," << r.reference_x << "," << r.reference_height << "," << r.steps << "," << r.wall_seconds << ","
        << r.solver_seconds << "," << s.final_displacement << "," << s.exact_final << "," << s.final_error << "," << s.rms_error << ","
        << s.mean_settlement << "," << s.swing << "," << s.static_small_strain << "," << s.static_log_strain << "," << s.energy_drift
        << "," << r.largest_mass_mismatch << "," << (r.failed ? "failed" : "ok") << "," << r.newton_mean << "," << r.newton_max << ","
        << r.neighbours_mean << "," << mpm::io::name_of(r.scene.stress_update) << "," << r.cpu_seconds << ",";
    const auto& t = o.cpu_repeats;
    if (t.empty())
      out << r.cpu_seconds << "," << r.cpu_seconds << ",0";
    else
      out << *std::min_element(t.begin(), t.end()) << "," << *std::max_element(t.begin(), t.end()) << "," << t.size();
    out << "," << s.rms_band << "," << s.mean_floor << "," << s.energy_drift_band << "\n";
  }
}

}  // namespace verification
