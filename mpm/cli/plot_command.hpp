/// \file
/// `mpm plot RUN_DIR`: draws a run with gnuplot (PNG), into the run's folder:
///   observers.png  one panel per observed quantity (x, v_x, sigma_xx, ...), every observer, and the
///                  exact solution (exact.csv, dashed black) wherever it has the same column
///   energy.png     kinetic, strain and total energy; momentum
/// The gnuplot script is kept as RUN_DIR/plot.gp, to be edited and rerun by hand.
/// Either CSV may be missing (a folder of another code's observers.csv, say): what is there is drawn.
/// The CSV files are read by io::CsvFile (regular files only, lines of at most 1 MiB); their column names reach
/// the script only as gnuplot single-quoted strings, and a name with a control character is refused. The
/// script, plot.log and the pictures are created afresh, never through a symbolic link (mpm/cli/gnuplot.hpp).
/// Exit codes: 0 done; 2 no such folder, neither CSV, a CSV that cannot be read or without its header, a name
/// with a control character; 3 a file cannot be written, gnuplot failed or left a picture incomplete.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mpm/cli/gnuplot.hpp"
#include "mpm/cli/options.hpp"
#include "mpm/io/csv_file.hpp"
#include "mpm/io/run_folder.hpp"

namespace mpm::cli {

/// The column names of the header of `path` (io::CsvFile), empty when there is no such file; false with
/// `error` set (`FILE:LINE: ...`) when it cannot be read, a name holds a control character (a name is
/// written into the gnuplot script), or it has no data row or a field that is not a number (nan and inf
/// are numbers here: a failed run writes them).
inline bool plot_header(const std::string& path, std::vector<std::string>& names, std::string& error) {
  io::CsvFile file(path);
  names.clear();
  if (file.missing()) return true;
  if (!file.read_header()) {
    error = file.error().empty() ? path + ": empty; a header line is needed" : file.error();
    return false;
  }
  for (size_t k = 0; k < file.header().size(); ++k)
    if (has_control_character(file.header()[k])) {
      error = file.where() + "column " + std::to_string(k + 1) + ": its name holds a control character";
      return false;
    }
  int rows = 0;
  for (std::vector<std::string> fields; file.next_row(fields); ++rows)
    for (size_t k = 0; k < fields.size(); ++k) {
      char* end = nullptr;
      std::strtod(fields[k].c_str(), &end);
      if (fields[k].empty() || *end != '\0') {
        error = file.where() + file.header()[k] + ": '" + fields[k].substr(0, 40) + "' is not a number";
        return false;
      }
    }
  error = file.error();
  if (error.empty() && rows == 0) error = path + ": has a header but no data row";
  names = file.header();
  return error.empty();
}

/// "A.v_x" -> "v_x"; "t" -> "".
inline std::string quantity_of(const std::string& column) {
  const auto dot = column.find('.');
  return dot == std::string::npos ? "" : column.substr(dot + 1);
}

inline std::string quantity_label(const std::string& quantity) {
  if (quantity.rfind("v_", 0) == 0) return "velocity " + quantity + " (m/s)";
  if (quantity.rfind("sigma_", 0) == 0) return "stress " + quantity + " (Pa, tension > 0)";
  return "position " + quantity + " (m)";
}

/// The quantities of observers.csv's columns NAME.QUANTITY, in order of first appearance: one panel each.
inline std::vector<std::string> observed_quantities(const std::vector<std::string>& observers) {
  std::vector<std::string> quantities;
  for (const auto& column : observers) {
    const std::string quantity = quantity_of(column);
    if (!quantity.empty() && std::find(quantities.begin(), quantities.end(), quantity) == quantities.end())
      quantities.push_back(quantity);
  }
  return quantities;
}

/// True if energy.csv's header has a column energy.png draws (kinetic, strain, total, momentum_*).
inline bool has_energy_column(const std::vector<std::string>& energy) {
  return std::any_of(energy.begin(), energy.end(), [](const std::string& name) {
    return name == "kinetic" || name == "strain" || name == "total" || name.rfind("momentum", 0) == 0;
  });
}

/// The most panels observers.png holds (one per quantity); a picture much taller fails in cairo.
inline constexpr std::size_t most_panels = 16;

/// The gnuplot script drawing observers.png (if any observer) and energy.png from the headers of
/// observers.csv, exact.csv (empty: none) and energy.csv; columns are addressed by number.
inline std::string plot_script(const std::vector<std::string>& observers, const std::vector<std::string>& exact,
                               const std::vector<std::string>& energy) {
  std::ostringstream gp;
  gp << "# written by `mpm plot`; run again with: gnuplot plot.gp (in this folder)\n"
        "set datafile separator ','\nset datafile missing 'nan'\nset grid lc rgb '#dddddd'\n"
        "set key outside right top\nset lmargin 14\nset xlabel 't (s)'\n";
  const std::vector<std::string> quantities = observed_quantities(observers);
  if (!quantities.empty()) {
    gp << "set terminal pngcairo noenhanced size 1000," << 260 * quantities.size() << " font ',10'\n"
       << "set output 'observers.png'\nset multiplot layout " << quantities.size() << ",1\n";
    for (const auto& quantity : quantities) {
      gp << "set ylabel " << gnuplot_quoted(quantity_label(quantity)) << "\nplot ";
      std::string separator;
      for (size_t k = 0; k < observers.size(); ++k) {
        if (quantity_of(observers[k]) != quantity) continue;
        gp << separator << "'observers.csv' using 1:" << k + 1 << " with lines lw 1.5 title " << gnuplot_quoted(observers[k]);
        separator = ", ";
        for (size_t j = 0; j < exact.size(); ++j)
          if (exact[j] == observers[k])
            gp << ", 'exact.csv' using 1:" << j + 1 << " with lines dt 2 lw 2 lc rgb 'black' title " << gnuplot_quoted(exact[j] + " exact");
      }
      gp << "\n";
    }
    gp << "unset multiplot\nunset output\n";
  }
  if (!has_energy_column(energy)) return gp.str();  // no energy.csv: observers.png only
  gp << "set terminal pngcairo noenhanced size 1000,520 font ',10'\nset output 'energy.png'\nset multiplot layout 2,1\n"
        "set ylabel 'energy (J; 1D per m^2, 2D per m)'\nplot ";
  std::string separator;
  for (size_t k = 1; k < energy.size(); ++k)
    if (energy[k] == "kinetic" || energy[k] == "strain" || energy[k] == "total") {
      gp << separator << "'energy.csv' using 1:" << k + 1 << " with lines lw 1.5 title " << gnuplot_quoted(energy[k]);
      separator = ", ";
    }
  gp << "\nset ylabel 'momentum'\nplot ";
  separator.clear();
  for (size_t k = 1; k < energy.size(); ++k)
    if (energy[k].rfind("momentum", 0) == 0) {
      gp << separator << "'energy.csv' using 1:" << k + 1 << " with lines lw 1.5 title " << gnuplot_quoted(energy[k]);
      separator = ", ";
    }
  gp << "\nunset multiplot\nunset output\n";
  return gp.str();
}

/// Reads the headers of `folder`'s observers.csv, energy.csv and exact.csv (plot_header); false, with a line
/// on `err`, when one cannot be read or neither observers.csv nor energy.csv is a run's.
inline bool plot_headers(const std::string& folder, std::vector<std::string>& observers, std::vector<std::string>& energy,
                         std::vector<std::string>& exact, std::ostream& err) {
  std::string problem;
  if (!plot_header(folder + "/observers.csv", observers, problem) || !plot_header(folder + "/energy.csv", energy, problem) ||
      !plot_header(folder + "/exact.csv", exact, problem)) {
    err << "error: " << problem << "\n";
    return false;
  }
  if (observers.empty() && energy.empty()) {  // either is optional, not both
    err << "error: " << folder << ": holds neither observers.csv nor energy.csv (is " << folder << " the folder of an `mpm run`?)\n";
    return false;
  }
  for (const auto& [name, header] : {std::pair{"observers.csv", observers}, std::pair{"energy.csv", energy}})
    if (!header.empty() && header[0] != "t") {
      err << "error: " << folder << "/" << name << ": its header line does not start with t (is " << folder
          << " the folder of an `mpm run`?)\n";
      return false;
    }
  return true;
}

/// `mpm plot`'s parser, its folder bound to `folder`.
inline std::unique_ptr<CommandParser> plot_parser(std::string& folder) {
  auto app = std::make_unique<CommandParser>(
      "plot",
      "Draws a run's observer histories (observers.csv, with exact.csv beside them when the scene names an\n"
      "exact solution) into RUN_DIR/observers.png and its energy balance (energy.csv) into RUN_DIR/energy.png,\n"
      "with gnuplot. Either CSV may be missing (a folder of another code's observers.csv): what is there is drawn.");
  app->add_option("RUN_DIR", folder, "the folder of an `mpm run` (or of another code's observers.csv)")->required();
  return app;
}

/// `mpm plot --help`: the parser's own help.
inline std::string plot_usage() {
  std::string folder;
  return plot_parser(folder)->help();
}

/// Draws the run in the folder the arguments name; returns the exit code.
inline int plot_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  namespace fs = std::filesystem;
  std::string folder;
  if (const auto code = parse_arguments(*plot_parser(folder), arguments, "plot", out, err)) return *code;
  if (has_control_character(folder)) {
    err << "error: plot: the folder's name holds a control character (a newline, a tab...); rename it\n";
    return 2;
  }
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    err << "error: " << folder << ": no such folder (give the folder of an `mpm run`, e.g. runs/dyka_bar)\n";
    return 2;
  }
  std::vector<std::string> observers, energy, exact;
  if (!plot_headers(folder, observers, energy, exact, err)) return 2;
  const std::size_t panels = observed_quantities(observers).size();
  if (panels > most_panels || (panels == 0 && !has_energy_column(energy))) {
    err << "error: " << folder << "/observers.csv: " << panels << " quantities (columns NAME.QUANTITY) to draw; "
        << (panels == 0 ? "none, and energy.csv has no energy or momentum column" : "at most 16") << "\n";
    return 2;
  }
  std::vector<std::string> pictures;
  if (panels > 0) pictures.push_back("observers.png");
  if (has_energy_column(energy)) pictures.push_back("energy.png");
  std::string reason;
  auto remove_pictures = [&] {  // made here, and not whole: no picture is left to be taken for a finished one
    for (const auto& picture : pictures) ::unlink((folder + "/" + picture).c_str());
  };
  std::unique_ptr<io::FolderLock> lock;  // no run or other plot writes here meanwhile
  try {
    lock = std::make_unique<io::FolderLock>(folder);
  } catch (const InputError& busy) {
    err << busy.message() << "\n";
    return 2;
  } catch (const OutputFailure& failure) {
    err << failure.message() << "\n";
    return 3;
  }
  if (!write_fresh(folder + "/plot.gp", plot_script(observers, exact, energy), reason)) {
    err << "error: " << folder << "/plot.gp: cannot write: " << reason << "\n";
    return 3;
  }
  for (const auto& picture : pictures) {  // each made afresh, so that gnuplot writes no symbolic link's target
    const int descriptor = create_fresh(folder + "/" + picture, reason);
    if (descriptor < 0) {
      err << "error: " << folder << "/" << picture << ": cannot write: " << reason << "\n";
      return remove_pictures(), 3;
    }
    ::close(descriptor);
  }
  const int log = create_fresh(folder + "/plot.log", reason);
  if (log < 0) {
    err << "error: " << folder << "/plot.log: cannot write: " << reason << "\n";
    return remove_pictures(), 3;
  }
  const int status = run_gnuplot(folder, "plot.gp", -1, log);
  ::close(log);
  if (status != 0) {
    err << "failure: gnuplot failed (status " << status << "; is gnuplot installed? make deps): see " << folder
        << "/plot.log and " << folder << "/plot.gp\n";
    return remove_pictures(), 3;
  }
  for (const auto& picture : pictures)
    if (!png_file_complete(folder + "/" + picture)) {
      err << "error: " << folder << "/" << picture << ": cannot write: gnuplot left it incomplete (no PNG end chunk): see " << folder
          << "/plot.log\n";
      return remove_pictures(), 3;
    }
  for (const auto& picture : pictures) out << "wrote " << folder << "/" << picture << "\n";
  return 0;
}

TEST_CASE("mpm plot: the script draws each observer's column beside the exact one of the same name") {
  const std::string script = plot_script({"t", "A.x", "A.v_x", "A.sigma_xx"}, {"t", "A.v_x", "A.sigma_xx"},
                                         {"t", "kinetic", "strain", "total", "momentum_x"});
  CHECK(script.find("set multiplot layout 3,1") != std::string::npos);
  CHECK(script.find("'observers.csv' using 1:3 with lines lw 1.5 title 'A.v_x', 'exact.csv' using 1:2 ") != std::string::npos);
  CHECK(script.find("'observers.csv' using 1:4 with lines lw 1.5 title 'A.sigma_xx', 'exact.csv' using 1:3 ") != std::string::npos);
  CHECK(script.find("'observers.csv' using 1:2 with lines lw 1.5 title 'A.x'\n") != std::string::npos);  // no exact x
  CHECK(script.find("'energy.csv' using 1:4 with lines lw 1.5 title 'total'") != std::string::npos);
  CHECK(script.find("'energy.csv' using 1:5 with lines lw 1.5 title 'momentum_x'") != std::string::npos);
  CHECK(plot_script({"t"}, {}, {"t", "kinetic"}).find("observers.png") == std::string::npos);
  CHECK(plot_script({"t", "A.x"}, {}, {}).find("energy.png") == std::string::npos);  // no energy.csv, no energy.png
  const std::string hostile = "A.x' . system('touch F') . '";  // a header name closing its string: doubled quotes keep it inside
  CHECK(plot_script({"t", hostile}, {}, {}).find("title 'A.x'' . system(''touch F'') . '''\n") != std::string::npos);
  CHECK(plot_script({"t"}, {}, {"t", "momentum' . system('id') . '"}).find("title 'momentum'' . system(''id'') . '''") != std::string::npos);
  const std::string path = (std::filesystem::temp_directory_path() / "mpm_plot_header_test.csv").string();
  std::ofstream(path) << "\xEF\xBB\xBFt,A.x,B\tx\n0,1,2\n";
  std::vector<std::string> names;
  std::string error;
  CHECK(!plot_header(path, names, error));
  CHECK(error == path + ":1: column 3: its name holds a control character");
  std::ofstream(path) << "\xEF\xBB\xBFt,A.x\n0,1\n";
  CHECK(plot_header(path, names, error));
  CHECK(names == std::vector<std::string>{"t", "A.x"});  // the byte-order mark is not part of t
  std::filesystem::remove(path);
  CHECK(plot_header(path, names, error));  // no such file: no header, and no error (either CSV is optional)
  CHECK(names.empty());
  std::ostringstream out, err;
  CHECK(plot_command({}, out, err) == 2);
  CHECK(plot_command({"/nonexistent/run"}, out, err) == 2);
  CHECK(err.str().find("error: /nonexistent/run: no such folder") != std::string::npos);
}

}  // namespace mpm::cli
