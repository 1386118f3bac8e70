/// \file
/// The CSV files `mpm plot` draws, read and checked (PlotTable), the ranges of their values, the y range that keeps
/// round-off flat (axis_range) and the label of each quantity with its unit.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "mpm/cli/gnuplot.hpp"
#include "mpm/cli/options.hpp"
#include "mpm/io/csv_file.hpp"

namespace mpm::cli {

/// A CSV file as `mpm plot` reads it: its column names and, per column, the least and greatest finite value
/// (low > high where a column has none).
struct PlotTable {
  std::vector<std::string> names;
  std::vector<double> low, high;

  PlotTable() = default;
  /// A table of these columns (with no values when `low` and `high` are not given).
  PlotTable(std::vector<std::string> columns, std::vector<double> least = {}, std::vector<double> greatest = {})
      : names(std::move(columns)), low(std::move(least)), high(std::move(greatest)) {}

  /// The number of the column `name` (0 for the first), -1 if there is none.
  int column(const std::string& name) const {
    const auto found = std::find(names.begin(), names.end(), name);
    return found == names.end() ? -1 : static_cast<int>(found - names.begin());
  }
};

/// The CSV file `path` (io::CsvFile) read for plotting, no column when there is no such file. Each name is
/// written into the script: one with a control character is refused, and so is a file without a data row or
/// with a field that is not a number (nan and inf are numbers here: a failed run writes them).
/// \throws Refused (`FILE:LINE: ...`).
inline PlotTable plot_table(const std::string& path) {
  io::CsvFile file(path);
  PlotTable table;
  if (file.missing()) return table;
  if (!file.read_header())
    throw Refused(file.error().empty() ? path + ": empty; a header line is needed" : file.error());
  const auto& names = file.header();
  if (file.separator() != ',' && names.size() > 1)  // gnuplot reads the file as a run writes it
    throw Refused(file.where() + "its columns are not comma-separated, as a run writes them");
  for (size_t k = 0; k < names.size(); ++k)
    if (has_control_character(names[k]))
      throw Refused(file.where() + "column " + std::to_string(k + 1) + ": its name holds a control character");
  table.names = names;
  table.low.assign(names.size(), std::numeric_limits<double>::infinity());
  table.high.assign(names.size(), -std::numeric_limits<double>::infinity());
  int rows = 0;
  for (std::vector<std::string> fields; file.next_row(fields); ++rows)
    for (size_t k = 0; k < fields.size(); ++k) {
      char* end = nullptr;
      const double value = std::strtod(fields[k].c_str(), &end);
      if (fields[k].empty() || *end != '\0')
        throw Refused(file.where() + names[k] + ": '" + fields[k].substr(0, 40) + "' is not a number");
      if (std::isfinite(value) && k < names.size()) {
        table.low[k] = std::min(table.low[k], value);
        table.high[k] = std::max(table.high[k], value);
      }
    }
  if (!file.error().empty()) throw Refused(file.error());
  if (rows == 0) throw Refused(path + ": has a header but no data row");
  return table;
}

/// The column names of the CSV file `path` (plot_table), none when there is no such file. \throws Refused.
inline std::vector<std::string> plot_header(const std::string& path) { return plot_table(path).names; }

/// The smallest span of an axis relative to the magnitude of its values: a narrower spread (round-off around
/// 4.5, say) is drawn flat in the middle of a range this wide, not magnified into what looks like a signal.
constexpr double least_relative_span = 1e-6;

/// The gnuplot lines setting `axis` (y, cb) for values in [low, high]: autoscaled, or, when they spread over less
/// than least_relative_span of their magnitude, a range of twice that around their middle, with ticks of enough
/// digits. Autoscaled when there is no finite value or every one is 0.
inline std::string axis_range(const std::string& axis, double low, double high) {
  const double magnitude = std::max(std::abs(low), std::abs(high)), least = least_relative_span * magnitude;
  if (!(low <= high) || magnitude == 0.0 || high - low >= least)
    return "set autoscale " + axis + "\nset format " + axis + "\n";
  char line[160];
  std::snprintf(line, sizeof line, "set %srange [%.17g:%.17g]\nset format %s '%%.10g'\n", axis.c_str(),
                0.5 * (low + high) - least, 0.5 * (low + high) + least, axis.c_str());
  return line;
}

/// The axis label of a quantity: "velocity v_x (m/s)", "stress sigma_xx (Pa, tension > 0)", "position x (m)",
/// "displacement u_x (m)" (since t = 0), "density (kg/m^3)"; another code's column says its unit is not known.
inline std::string quantity_label(const std::string& quantity) {
  if (quantity.rfind("v_", 0) == 0) return "velocity " + quantity + " (m/s)";
  if (quantity.rfind("sigma_", 0) == 0) return "stress " + quantity + " (Pa, tension > 0)";
  if (quantity.rfind("u_", 0) == 0) return "displacement " + quantity + " since t = 0 (m)";
  if (quantity == "x" || quantity == "y") return "position " + quantity + " (m)";
  if (quantity == "density") return "density (kg/m^3)";
  return quantity + " (unit not known)";
}

/// The least and greatest finite value seen so far (low > high: none), widened by a column of a PlotTable.
struct ValueRange {
  double low = std::numeric_limits<double>::infinity(), high = -std::numeric_limits<double>::infinity();
  void add(const PlotTable& table, size_t k) {
    if (k < table.low.size()) low = std::min(low, table.low[k]), high = std::max(high, table.high[k]);
  }
};

}  // namespace mpm::cli
