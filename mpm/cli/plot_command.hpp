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

#include "mpm/cli/gnuplot.hpp"
#include "mpm/cli/options.hpp"
#include "mpm/io/csv_file.hpp"
#include "mpm/io/run_folder.hpp"

namespace mpm::cli {

/// The column names of the header of the CSV file `path` (io::CsvFile), none when there is no such file. Each
/// name is written into the script: one with a control character is refused, and so is a file without a data row
/// or with a field that is not a number (nan and inf are numbers here: a failed run writes them).
/// \throws Refused (`FILE:LINE: ...`).
inline std::vector<std::string> plot_header(const std::string& path) {
  io::CsvFile file(path);
  if (file.missing()) return {};
  if (!file.read_header())
    throw Refused(file.error().empty() ? path + ": empty; a header line is needed" : file.error());
  const auto& names = file.header();
  if (file.separator() != ',' && names.size() > 1)  // gnuplot reads the file as a run writes it
    throw Refused(file.where() + "its columns are not comma-separated, as a run writes them");
  for (size_t k = 0; k < names.size(); ++k)
    if (has_control_character(names[k]))
      throw Refused(file.where() + "column " + std::to_string(k + 1) + ": its name holds a control character");
  int rows = 0;
  for (std::vector<std::string> fields; file.next_row(fields); ++rows)
    for (size_t k = 0; k < fields.size(); ++k) {
      char* end = nullptr;
      std::strtod(fields[k].c_str(), &end);
      if (fields[k].empty() || *end != '\0')
        throw Refused(file.where() + names[k] + ": '" + fields[k].substr(0, 40) + "' is not a number");
    }
  if (!file.error().empty()) throw Refused(file.error());
  if (rows == 0) throw Refused(path + ": has a header but no data row");
  return names;
}

/// "A.v_x" -> "v_x"; "t" -> "".
inline std::string quantity_of(const std::string& column) {
  const auto dot = column.find('.');
  return dot == std::string::npos ? "" : column.substr(dot + 1);
}

/// The y label of a quantity's panel: "velocity v_x (m/s)", "stress sigma_xx (Pa, tension > 0)", "position x (m)".
inline std::string quantity_label(const std::string& quantity) {
  if (quantity.rfind("v_", 0) == 0) return "velocity " + quantity + " (m/s)";
  if (quantity.rfind("sigma_", 0) == 0) return "stress " + quantity + " (Pa, tension > 0)";
  return "position " + quantity + " (m)";
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

/// A gnuplot `plot` of the columns of `file` (its header `names`) that `pick` takes, by number and titled by name,
/// each with the column of exact.csv (its header `exact`) of the same name beside it.
template <class Pick>
std::string plot_columns(const std::string& file, const std::vector<std::string>& names, Pick pick,
                         const std::vector<std::string>& exact = {}) {
  std::string line;
  for (size_t k = 1; k < names.size(); ++k) {
    if (!pick(names[k])) continue;
    line += (line.empty() ? "plot '" : ", '") + file + "' using 1:" + std::to_string(k + 1) +
            " with lines lw 1.5 title " + gnuplot_quoted(names[k]);
    for (size_t j = 0; j < exact.size(); ++j)
      if (exact[j] == names[k])
        line += ", 'exact.csv' using 1:" + std::to_string(j + 1) + " with lines dt 2 lw 2 lc rgb 'black' title " +
                gnuplot_quoted(exact[j] + " exact");
  }
  return line + "\n";
}

/// The gnuplot script drawing observers.png (one panel per quantity, if any) and energy.png (if energy.csv has a
/// column it draws) from the headers of observers.csv, exact.csv and energy.csv (each empty: none).
inline std::string plot_script(const std::vector<std::string>& observers, const std::vector<std::string>& exact,
                               const std::vector<std::string>& energy) {
  std::string gp = std::string("# written by `mpm plot`; run again with: gnuplot plot.gp (in this folder)\n") +
                   gnuplot_preamble + "set datafile missing 'nan'\n";
  const std::vector<std::string> quantities = observed_quantities(observers);
  if (!quantities.empty()) gp += gnuplot_page("observers.png", quantities.size());
  for (const auto& quantity : quantities) {
    const auto same_quantity = [&](const std::string& name) { return quantity_of(name) == quantity; };
    gp += "set ylabel " + gnuplot_quoted(quantity_label(quantity)) + "\n" +
          plot_columns("observers.csv", observers, same_quantity, exact);
  }
  if (!quantities.empty()) gp += "unset multiplot\nunset output\n";
  if (!draws_energy(energy)) return gp;
  return gp + gnuplot_page("energy.png", 2) + "set ylabel 'energy (J; 1D per m^2, 2D per m)'\n" +
         plot_columns("energy.csv", energy, [](auto& name) { return energy_column(name, false); }) +
         "set ylabel 'momentum'\n" +
         plot_columns("energy.csv", energy, [](auto& name) { return energy_column(name, true); }) +
         "unset multiplot\nunset output\n";
}

/// Draws the run in `folder`: its CSVs' headers read and checked, then plot.gp, the pictures and plot.log written
/// under the folder's lock. \throws Refused, InputError (a busy folder), OutputFailure.
inline void plot_folder(const std::string& folder, std::ostream& out) {
  std::error_code error;
  if (has_control_character(folder))
    throw Refused("plot: the folder's name holds a control character (a newline, a tab...); rename it");
  if (!std::filesystem::is_directory(folder, error))
    throw Refused(folder + ": no such folder (give the folder of an `mpm run`, e.g. runs/dyka_bar)");
  const std::string is_run = " (is " + folder + " the folder of an `mpm run`?)";
  const auto observers = plot_header(folder + "/observers.csv"), energy = plot_header(folder + "/energy.csv");
  const auto exact = plot_header(folder + "/exact.csv");
  if (observers.empty() && energy.empty())
    throw Refused(folder + ": holds neither observers.csv nor energy.csv" + is_run);
  for (const auto& [name, header] : {std::pair{"observers.csv", observers}, std::pair{"energy.csv", energy}})
    if (!header.empty() && header[0] != "t")
      throw Refused(folder + "/" + name + ": its header line does not start with t" + is_run);
  const std::size_t panels = observed_quantities(observers).size();
  std::vector<std::string> pictures;
  if (panels > 0) pictures.push_back(folder + "/observers.png");
  if (draws_energy(energy)) pictures.push_back(folder + "/energy.png");
  if (panels > 16 || pictures.empty())  // a picture much taller fails in cairo
    throw Refused(folder + "/observers.csv: " + std::to_string(panels) +
                  " quantities (columns NAME.QUANTITY) to draw; " +
                  (panels == 0 ? "none, and energy.csv has no energy or momentum column" : "at most 16"));
  io::FolderLock lock(folder);  // no run or other plot writes here meanwhile
  const std::string script = plot_script(observers, exact, energy);
  write_fresh(folder + "/plot.gp", script);
  draw_with_gnuplot(folder, script, pictures, folder + "/plot.log");
  for (const auto& picture : pictures) out << "wrote " << picture << "\n";
}

/// `mpm plot`; returns the exit code.
inline int plot_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  std::string folder;
  CommandParser app(
      "plot",
      "Draws a run's observer histories (observers.csv, with exact.csv beside them when the scene names an\n"
      "exact solution) into RUN_DIR/observers.png and its energy balance (energy.csv) into RUN_DIR/energy.png,\n"
      "with gnuplot. Either CSV may be missing (a folder of another code's observers.csv): what is there is drawn.");
  app.add_option("RUN_DIR", folder, "the folder of an `mpm run` (or of another code's observers.csv)")->required();
  return run_parsed(app, arguments, out, err, [&] {
    plot_folder(folder, out);
    return 0;
  });
}

TEST_CASE("mpm plot: the script draws each observer's column beside the exact one of the same name") {
  const std::string script = plot_script({"t", "A.x", "A.v_x", "A.sigma_xx"}, {"t", "A.v_x", "A.sigma_xx"},
                                         {"t", "kinetic", "strain", "total", "momentum_x"});
  CHECK(script.find("set multiplot layout 3,1") != std::string::npos);
  CHECK(script.find("'observers.csv' using 1:3 with lines lw 1.5 title 'A.v_x', 'exact.csv' using 1:2 ") !=
        std::string::npos);
  CHECK(script.find("'observers.csv' using 1:4 with lines lw 1.5 title 'A.sigma_xx', 'exact.csv' using 1:3 ") !=
        std::string::npos);
  CHECK(script.find("'observers.csv' using 1:2 with lines lw 1.5 title 'A.x'\n") != std::string::npos);  // no exact x
  CHECK(script.find("set ylabel 'stress sigma_xx (Pa, tension > 0)'\n") != std::string::npos);
  CHECK(script.find("'energy.csv' using 1:4 with lines lw 1.5 title 'total'") != std::string::npos);
  CHECK(script.find("'energy.csv' using 1:5 with lines lw 1.5 title 'momentum_x'") != std::string::npos);
  CHECK(plot_script({"t"}, {}, {"t", "kinetic"}).find("observers.png") == std::string::npos);
  CHECK(plot_script({"t", "A.x"}, {}, {}).find("energy.png") == std::string::npos);  // no energy.csv, no energy.png
  const std::string hostile =
      "A.x' . system('touch F') . '";  // a header name closing its string: doubled quotes keep it inside
  CHECK(plot_script({"t", hostile}, {}, {}).find("title 'A.x'' . system(''touch F'') . '''\n") != std::string::npos);
  CHECK(
      plot_script({"t"}, {}, {"t", "momentum' . system('id') . '"}).find("title 'momentum'' . system(''id'') . '''") !=
      std::string::npos);
  const std::string path = (std::filesystem::temp_directory_path() / "mpm_plot_header_test.csv").string();
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
