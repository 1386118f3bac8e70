// The smooth-data suite's report: the orders (with standard errors) as CSV and tables, the Dyka runs at 2 ppc as CSV,
// and the report fragments (the suite's and Fig. 6 at 2 ppc).
#pragma once
#include <fstream>
#include <ostream>

#include "verification/smooth_claims.hpp"
#include "verification/smooth_fig6_2ppc.hpp"

namespace verification::smooth {

/// smooth_bar_orders.csv: every series of the bar, velocity and stress orders from 16 cells with their standard errors.
inline void write_bar_orders(const std::string& folder, const Runs& runs) {
  std::ofstream out(folder + "/smooth_bar_orders.csv");
  out << "amplitude,shape,integrator,ppc,cfl,velocity_order,stress_order,failed_runs,velocity_order_own_time,"
         "velocity_order_error,stress_order_error,velocity_order_own_time_error,score_failed_runs\n";
  for (bool large : {false, true})
    for (const Case& p : [&] {
           auto paper = cases_of(runs, Group::bar, large, true, false, true), baselines = cases_of(runs, Group::bar, large, false, true, true);
           paper.insert(paper.end(), baselines.begin(), baselines.end());
           return paper;
         }()) {
      const OrderFit v = order(runs, p, &SmoothResult::velocity_error, 16), s = order(runs, p, &SmoothResult::stress_error, 16),
                     own = order(runs, p, &SmoothResult::velocity_error_own_time, 16);
      CsvRow row;
      row << (large ? "large" : "small") << p.method.shape << p.method.integrator << p.ppc << number(p.cfl, "%.1f") << v.order << s.order
          << series(runs, p, &SmoothResult::velocity_error).stopped.size() << own.order << v.error << s.error << own.error << v.failed;
      out << row.text.str() << "\n";
    }
}

/// smooth_manufactured_orders.csv: every series of the 2D manufactured solutions, orders from 12 cells with standard errors.
inline void write_manufactured_orders(const std::string& folder, const Runs& runs) {
  std::ofstream out(folder + "/smooth_manufactured_orders.csv");
  out << "amplitude,shape,integrator,ppc,velocity_order,stress_order,failed_runs,velocity_order_error,stress_order_error,score_failed_runs\n";
  for (bool large : {false, true})
    for (const Method& m : with_paper(bar_baselines()))
      for (int ppc : {1, 2}) {
        const Case p = manufactured_case(large, m, ppc);
        if (runs.meshes(p).empty()) continue;
        const OrderFit v = order(runs, p, &SmoothResult::velocity_error, 12), s = order(runs, p, &SmoothResult::stress_error, 12);
        CsvRow row;
        row << (large ? "large" : "small") << m.shape << m.integrator << ppc << v.order << s.order
            << series(runs, p, &SmoothResult::velocity_error).stopped.size() << v.error << s.error << v.failed;
        out << row.text.str() << "\n";
      }
}

/// dyka_2ppc.csv: the Dyka bar at 2 ppc, every method and mesh of its study.
inline void write_dyka_runs(const std::string& folder, const std::vector<Axes>& all, const Runs& runs) {
  std::ofstream out(folder + "/dyka_2ppc.csv");
  out << "shape,integrator,cells,crossing_ratio,rms_over_v0,largest_speed_over_v0,wall_seconds,status,rms_own_time_over_v0,failure,cpu_seconds,rms_band_over_v0,ending,"
         "space_time_over_v0,space_time_band_over_v0\n";
  for (const Case& c : expand(all)) {
    if (c.group != Group::dyka) continue;
    const auto k = runs.index(c);
    const DykaResult& r = runs.dyka[k];
    std::string failure = r.failure;
    std::replace(failure.begin(), failure.end(), ',', ';');
    std::replace(failure.begin(), failure.end(), '\n', ' ');
    CsvRow row;
    row << c.method.shape << c.method.integrator << c.cells << dyka_crossing_ratio(c.cells, c.ppc) << (r.failed ? std::nan("") : r.rms / dyka_speed)
        << r.largest_speed / dyka_speed << r.wall_seconds << (r.failed ? "failed" : "ok") << (r.failed ? std::nan("") : r.rms_own_time / dyka_speed)
        << failure << runs.results[k].cpu_seconds
        << (r.failed ? std::nan("") : mpm::band_of_halves(r.rms, r.even.rms, r.odd.rms) / dyka_speed)
        << (r.failed ? "stopped" : mpm::score_ending(r.rms, r.flat_rms) == mpm::Ending::failed ? "failed" : "done")
        << (r.failed ? std::nan("") : r.space_time / dyka_speed)
        << (r.failed ? std::nan("") : mpm::band_of_halves(r.space_time, r.space_time_even, r.space_time_odd) / dyka_speed);
    out << row.text.str() << "\n";
  }
}

/// A table of orders: one row per series pattern of `rows`, one column per (ppc, CFL) of `columns`, "v ± se | σ ± se".
inline void write_order_table(std::ostream& out, const Runs& runs, const std::vector<Case>& rows, const std::vector<std::pair<int, double>>& columns,
                              int from, bool own_time) {
  for (const Case& row : rows) {
    out << "| " << (row.large ? "large" : "small") << " | " << row.method.shape << " | " << row.method.integrator;
    for (const auto& [ppc, cfl] : columns) {
      Case p = row;
      p.ppc = ppc, p.cfl = cfl;
      if (runs.meshes(p).empty()) {
        out << " | not run";
        continue;
      }
      const OrderFit v = order(runs, p, own_time ? &SmoothResult::velocity_error_own_time : &SmoothResult::velocity_error, from);
      out << " | " << v.text();
      if (!own_time) out << " \\| " << order(runs, p, &SmoothResult::stress_error, from).text();
    }
    out << " |\n";
  }
  out << "\n";
}

/// The rows of an order table: one pattern per method and amplitude (ppc and CFL set by the columns).
inline std::vector<Case> order_rows(Group group, const std::vector<bool>& amplitudes, const std::vector<Method>& methods) {
  std::vector<Case> rows;
  for (bool large : amplitudes)
    for (const Method& m : methods) rows.push_back({group, large, m, 1, 0.5, 0.0, 0});
  return rows;
}

/// The orders of the bar and of the 2D manufactured solutions, as Markdown tables.
inline void write_orders(std::ostream& out, const Runs& runs) {
  const std::vector<std::pair<int, double>> bar_columns{{1, 0.5}, {1, 0.1}, {2, 0.5}, {2, 0.1}}, square_columns{{1, 0.5}, {2, 0.5}};
  out << "### Observed orders of the vibrating bar\n\nVelocity \\| stress: GSL least squares of log error against log cells from 16 "
         "cells, ± its standard error (sqrt of c11); — where a run of the series stopped (a stopped run is its own outcome, not a point "
         "of a fit) or fewer than 3 meshes are left.\n\n"
      << "| amplitude | shape | integrator | 1 ppc, CFL 0.5 | 1 ppc, CFL 0.1 | 2 ppc, CFL 0.5 | 2 ppc, CFL 0.1 |\n|---|---|---|---|---|---|---|\n";
  write_order_table(out, runs, order_rows(Group::bar, {false, true}, with_paper(bar_baselines())), bar_columns, 16, false);
  out << "The velocity orders again with forward Euler's velocity compared at t + dt/2, the time it approximates (the bar starts "
         "unstressed: a consistent start), the predictor-corrector's at t (first order at any shift); small amplitude (the "
         "finite-strain reference of the large amplitude exists only at the sample times):\n\n"
      << "| amplitude | shape | integrator | 1 ppc, CFL 0.5 | 1 ppc, CFL 0.1 | 2 ppc, CFL 0.5 | 2 ppc, CFL 0.1 |\n|---|---|---|---|---|---|---|\n";
  write_order_table(out, runs, order_rows(Group::bar, {false}, with_paper(bar_baselines())), bar_columns, 16, true);
  out << "### Observed orders of the 2D manufactured solutions\n\nVelocity \\| stress, fitted over 12-32 cells per side (CFL 0.5, to half "
         "a period, errors at 1/8, 1/4, 3/8, 1/2 of it), ± standard error; — where a run stopped.\n\n"
      << "| amplitude | shape | integrator | 1x1 ppc | 2x2 ppc |\n|---|---|---|---|---|\n";
  write_order_table(out, runs, order_rows(Group::manufactured, {false, true}, with_paper(bar_baselines())), square_columns, 12, false);
  out << "The 2D velocity orders with forward Euler's velocity compared at t + dt/2 (the predictor-corrector's unchanged):\n\n"
      << "| amplitude | shape | integrator | 1x1 ppc | 2x2 ppc |\n|---|---|---|---|---|\n";
  std::vector<Method> fe;
  for (const auto& shape : paper_shapes()) fe.push_back({shape, "fe"});
  write_order_table(out, runs, order_rows(Group::manufactured, {false, true}, fe), square_columns, 12, true);
}

}  // namespace verification::smooth
