/// \file
/// `mpm plot RUN_DIR`: draws a run's observers.csv (with exact.csv beside it) into observers.png and its
/// energy.csv into energy.png with gnuplot, keeping the script as RUN_DIR/plot.gp. Exit codes: 0 done; 2 a
/// folder or CSV it cannot draw; 3 a file cannot be written, gnuplot failed or left a picture incomplete.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

#include "mpm/cli/gnuplot.hpp"
#include "mpm/cli/options.hpp"
#include "mpm/cli/plot_profiles.hpp"
#include "mpm/cli/plot_table.hpp"
#include "mpm/io/csv_file.hpp"
#include "mpm/io/run_folder.hpp"

namespace mpm::cli {

/// "A.v_x" -> "v_x"; "t" -> "".
inline std::string quantity_of(const std::string& column) {
  const auto dot = column.find('.');
  return dot == std::string::npos ? "" : column.substr(dot + 1);
}

/// The quantities of observers.csv's columns NAME.QUANTITY, in order of first appearance: one panel each.
inline std::vector<std::string> observed_quantities(const std::vector<std::string>& observers) {
  std::vector<std::string> quantities;
  for (const auto& column : observers)
    if (!quantity_of(column).empty() && std::count(quantities.begin(), quantities.end(), quantity_of(column)) == 0)
      quantities.push_back(quantity_of(column));
  return quantities;
}

/// True if `name` is a column of energy.csv that energy.png draws in its panel `momentum` or the other.
inline bool energy_column(const std::string& name, bool momentum) {
  return momentum ? name.rfind("momentum", 0) == 0 : name == "kinetic" || name == "strain" || name == "total";
}

/// True if energy.csv's header `energy` has a column energy.png draws.
inline bool draws_energy(const std::vector<std::string>& energy) {
  return std::any_of(energy.begin(), energy.end(),
                     [](auto& name) { return energy_column(name, false) || energy_column(name, true); });
}

/// "A.v_x" -> "A"; "kinetic" -> "kinetic".
inline std::string curve_of(const std::string& column) { return column.substr(0, column.find('.')); }

/// A gnuplot `plot` of the columns of `file` (its table `names`) that `pick` takes, by number and titled by name,
/// each after the column of exact.csv (its table `exact`) of the same name, drawn under it in the exact solution's
/// style; `range` takes their values. Each curve's colour is its observer's (or energy's) place on the palette's
/// ramp, the same in every panel.
template <class Pick>
std::string plot_columns(const std::string& file, const PlotTable& names, Pick pick, ValueRange& range,
                         const PlotTable& exact = {}) {
  std::vector<std::string> curves;  // the observers (A, B...) or energies, in order of first appearance
  for (size_t k = 1; k < names.names.size(); ++k)
    if (std::count(curves.begin(), curves.end(), curve_of(names.names[k])) == 0)
      curves.push_back(curve_of(names.names[k]));
  std::string line;
  for (size_t k = 1; k < names.names.size(); ++k) {
    if (!pick(names.names[k])) continue;
    range.add(names, k);
    for (size_t j = 0; j < exact.names.size(); ++j)
      if (exact.names[j] == names.names[k]) {
        range.add(exact, j);
        line += (line.empty() ? "plot " : ", ") + std::string("'exact.csv' using 1:") + std::to_string(j + 1) +
                " with lines @exact_style title " + gnuplot_quoted(exact.names[j] + " exact");
      }
    const auto place = std::find(curves.begin(), curves.end(), curve_of(names.names[k])) - curves.begin();
    line += (line.empty() ? "plot '" : ", '") + file + "' using 1:" + std::to_string(k + 1) + " with lines " +
            gnuplot_curve_style(place, curves.size()) + " title " + gnuplot_quoted(names.names[k]);
  }
  return line + "\n";
}

/// A panel: its y label, its y range (axis_range of the values it draws) and its plot line.
template <class Pick>
std::string plot_panel(const std::string& label, const std::string& file, const PlotTable& names, Pick pick,
                       const PlotTable& exact = {}) {
  ValueRange range;
  const std::string plot = plot_columns(file, names, pick, range, exact);
  return "set ylabel " + gnuplot_quoted(label) + "\n" + axis_range("y", range.low, range.high) + plot;
}

/// The lines that give every panel the same time axis: the plot area's left and right edges fixed (the key's
/// width moves neither) and t from the first to the last time of observers.csv and energy.csv.
inline std::string shared_time_axis(const PlotTable& observers, const PlotTable& energy) {
  ValueRange t;
  t.add(observers, 0);
  t.add(energy, 0);
  std::string gp = "set lmargin at screen 0.1\nset rmargin at screen 0.78\n";
  if (!(t.low < t.high)) return gp + "set autoscale x\n";
  char line[96];
  std::snprintf(line, sizeof line, "set xrange [%.17g:%.17g]\n", t.low, t.high);
  return gp + line;
}

/// The gnuplot script drawing observers.png (one panel per quantity, if any) and energy.png (if energy.csv has a
/// column it draws) from observers.csv, exact.csv and energy.csv (each without a column: none).
inline std::string plot_script(const PlotTable& observers, const PlotTable& exact, const PlotTable& energy) {
  std::string gp = std::string("# written by `mpm plot`; run again with: gnuplot plot.gp (in this folder)\n") +
                   gnuplot_preamble + "set datafile missing 'nan'\n" + shared_time_axis(observers, energy);
  const std::vector<std::string> quantities = observed_quantities(observers.names);
  if (!quantities.empty()) gp += gnuplot_page("observers.png", quantities.size());
  for (const auto& quantity : quantities) {
    const auto same_quantity = [&](const std::string& name) { return quantity_of(name) == quantity; };
    gp += plot_panel(quantity_label(quantity), "observers.csv", observers, same_quantity, exact);
  }
  if (!quantities.empty()) gp += "unset multiplot\nunset output\n";
  if (!draws_energy(energy.names)) return gp;
  const bool two = energy.column("momentum_y") >= 0;  // per unit thickness in 2D, per unit area in 1D
  const std::string per = two ? ": per unit thickness)" : ": per unit cross-section area)";
  return gp + gnuplot_page("energy.png", 2) +
         plot_panel(std::string(two ? "energy (J/m" : "energy (J/m^2") + per, "energy.csv", energy,
                    [](auto& name) { return energy_column(name, false); }) +
         plot_panel(std::string(two ? "momentum (kg/s" : "momentum (kg/(m s)") + per, "energy.csv", energy,
                    [](auto& name) { return energy_column(name, true); }) +
         "unset multiplot\nunset output\n";
}

/// Draws the run in `folder` under the folder's lock (a run cannot start or end there meanwhile): its CSVs read and
/// checked, then plot.gp, the pictures (observers.png, energy.png, profile_NNNN.png of each snapshot, coloured by
/// `field` in 2D) and plot.log written.
/// \throws Refused, InputError (a busy folder), OutputFailure.
inline void plot_folder(const std::string& folder, const std::string& field, std::ostream& out) {
  std::error_code error;
  if (has_control_character(folder))
    throw Refused("plot: the folder's name holds a control character (a newline, a tab...); rename it");
  if (!std::filesystem::is_directory(folder, error))
    throw Refused(folder + ": no such folder (give the folder of an `mpm run`, e.g. runs/dyka_bar)");
  io::FolderLock lock(folder);  // no run or other plot writes here while the CSVs are read and the pictures drawn
  const std::string is_run = " (is " + folder + " the folder of an `mpm run`?)";
  const PlotTable observers = plot_table(folder + "/observers.csv"), energy = plot_table(folder + "/energy.csv");
  const PlotTable exact = plot_table(folder + "/exact.csv");
  if (observers.names.empty() && energy.names.empty())
    throw Refused(folder + ": holds neither observers.csv nor energy.csv" + is_run);
  for (const auto& [name, header] :
       {std::pair{"observers.csv", observers.names}, std::pair{"energy.csv", energy.names}})
    if (!header.empty() && header[0] != "t")
      throw Refused(folder + "/" + name + ": its header line does not start with t" + is_run);
  const std::size_t panels = observed_quantities(observers.names).size();
  std::vector<std::string> pictures;
  if (panels > 0) pictures.push_back(folder + "/observers.png");
  if (draws_energy(energy.names)) pictures.push_back(folder + "/energy.png");
  if (panels > 16 || pictures.empty())  // a picture much taller fails in cairo
    throw Refused(folder + "/observers.csv: " + std::to_string(panels) +
                  " quantities (columns NAME.QUANTITY) to draw; " +
                  (panels == 0 ? "none, and energy.csv has no energy or momentum column" : "at most 16"));
  const auto snapshots = snapshot_files(folder);
  const std::string script = plot_script(observers, exact, energy) + profile_script(folder, snapshots, field, pictures);
  write_fresh(folder + "/plot.gp", script);
  draw_with_gnuplot(folder, script, pictures, folder + "/plot.log");
  for (const auto& picture : pictures) out << "wrote " << picture << "\n";
  if (snapshots.size() > most_profiles)
    out << "drew the first " << most_profiles << " of " << snapshots.size() << " snapshots (profile_NNNN.png)\n";
}

/// `mpm plot`; returns the exit code.
inline int plot_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  std::string folder, field;
  CommandParser app(
      "plot",
      "Draws a run's observer histories (observers.csv, with exact.csv beside them when the scene names an\n"
      "exact solution) into RUN_DIR/observers.png, its energy balance (energy.csv) into RUN_DIR/energy.png and\n"
      "each snapshot into RUN_DIR/profile_NNNN.png: in 1D v_x(x) and sigma_xx(x) of the particles against the exact\n"
      "profile (exact_NNNN.csv), in 2D the particles coloured by --field over the grid lines (grid.csv), beside the\n"
      "exact field, with gnuplot. Either CSV may be missing (a folder of another code's observers.csv): what is\n"
      "there is drawn. A quantity spread over less than 1e-6 of its magnitude (round-off) is drawn flat.");
  app.add_option("RUN_DIR", folder, "the folder of an `mpm run` (or of another code's observers.csv)")->required();
  app.add_option("--field", field,
                 "the snapshot column that colours the particles in 2D (default sigma_yy), e.g. v_x, sigma_xy,\n"
                 "density; in 1D a panel drawn after v_x and sigma_xx")
      ->type_name("NAME");
  return run_parsed(app, arguments, out, err, [&] {
    plot_folder(folder, field, out);
    return 0;
  });
}

TEST_CASE("mpm plot: the script draws each observer's column beside the exact one of the same name") {
  const std::string script = plot_script({{"t", "A.x", "A.v_x", "A.sigma_xx", "A.u_x"}}, {{"t", "A.v_x", "A.sigma_xx"}},
                                         {{"t", "kinetic", "strain", "total", "momentum_x"}});
  CHECK(script.find("set multiplot layout 4,1") != std::string::npos);
  CHECK(script.find("plot 'exact.csv' using 1:2 with lines @exact_style title 'A.v_x exact', 'observers.csv' using "
                    "1:3 with lines lw 1.5 lc rgb ramp(1, 1) title 'A.v_x'\n") != std::string::npos);
  CHECK(script.find("plot 'exact.csv' using 1:3 with lines @exact_style title 'A.sigma_xx exact', 'observers.csv' "
                    "using 1:4 with lines lw 1.5 lc rgb ramp(1, 1) title 'A.sigma_xx'\n") != std::string::npos);
  CHECK(script.find("plot 'observers.csv' using 1:2 with lines lw 1.5 lc rgb ramp(1, 1) title 'A.x'\n") !=
        std::string::npos);  // no exact x
  CHECK(script.find(gnuplot_palette) < script.find("set terminal"));  // the figures' identity first
  CHECK(script.find("set ylabel 'stress sigma_xx (Pa, tension > 0)'\n") != std::string::npos);
  CHECK(script.find("'energy.csv' using 1:4 with lines lw 1.5 lc rgb ramp(3, 4) title 'total'") != std::string::npos);
  CHECK(script.find("'energy.csv' using 1:5 with lines lw 1.5 lc rgb ramp(4, 4) title 'momentum_x'") !=
        std::string::npos);
  CHECK(script.find("set ylabel 'displacement u_x since t = 0 (m)'\n") != std::string::npos);
  CHECK(script.find("set ylabel 'momentum (kg/(m s): per unit cross-section area)'\n") != std::string::npos);
  CHECK(plot_script({{"t"}}, {}, {{"t", "kinetic"}}).find("observers.png") == std::string::npos);
  CHECK(plot_script({{"t", "A.x"}}, {}, {}).find("energy.png") == std::string::npos);  // no energy.csv, no energy.png
  // the time axis is the same in every panel: t from the first to the last sample, the plot area's edges fixed
  const PlotTable flat{{"t", "A.v_x"}, {0.0, 4.5 - 1e-8}, {2e-4, 4.5 + 1e-8}};
  const std::string shared = plot_script(flat, {}, {{"t", "kinetic"}, {1e-5, 1.0}, {3e-4, 2.0}});
  CHECK(shared.find("set lmargin at screen 0.1\nset rmargin at screen 0.78\nset xrange [0:0.00029999999999999997]\n") !=
        std::string::npos);
  CHECK(shared.find("set yrange [4.49999549999999:4.50000450000001]") != std::string::npos);  // round-off: flat
  const std::string hostile =
      "A.x' . system('touch F') . '";  // a header name closing its string: doubled quotes keep it inside
  CHECK(plot_script({{"t", hostile}}, {}, {}).find("title 'A.x'' . system(''touch F'') . '''\n") != std::string::npos);
  CHECK(plot_script({{"t"}}, {}, {{"t", "momentum' . system('id') . '"}})
            .find("title 'momentum'' . system(''id'') . '''") != std::string::npos);
  const std::string path =
      (std::filesystem::temp_directory_path() / ("mpm_plot_header_" + std::to_string(::getpid()) + ".csv")).string();
  std::ofstream(path) << "\xEF\xBB\xBFt,A.x,B\tx\n0,1,2\n";
  CHECK_THROWS_WITH_AS(plot_header(path), (path + ":1: column 3: its name holds a control character").c_str(), Refused);
  std::ofstream(path) << "\xEF\xBB\xBFt,A.x\n0,1\n";
  CHECK(plot_header(path) == std::vector<std::string>{"t", "A.x"});  // the byte-order mark is not part of t
  std::ofstream(path) << "t,A.x\n0,fast\n";
  CHECK_THROWS_WITH_AS(plot_header(path), (path + ":2: A.x: 'fast' is not a number").c_str(), Refused);
  std::ofstream(path) << "t;A.x\n0;1\n";  // gnuplot would read one column
  CHECK_THROWS_WITH_AS(plot_header(path),
                       (path + ":1: its columns are not comma-separated, as a run writes them").c_str(), Refused);
  std::filesystem::remove(path);
  CHECK(plot_header(path).empty());  // no such file: no header, and no error (either CSV is optional)
  std::ostringstream out, err;
  CHECK(plot_command({}, out, err) == 2);
  CHECK(plot_command({"/nonexistent/run"}, out, err) == 2);
  CHECK(err.str().find("error: /nonexistent/run: no such folder") != std::string::npos);
}

}  // namespace mpm::cli
