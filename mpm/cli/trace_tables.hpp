/// \file
/// The tables `mpm trace` prints (mpm/cli/trace_command.hpp): a phase's nodes and particles, each a header and rows of
/// numbers already written, as CSV (one row per node or particle and phase, after the phase's name and equations) or
/// as aligned columns.
#pragma once
#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "mpm/core/step_phases.hpp"

namespace mpm::cli {

/// One table of a phase: a header and its rows, the numbers already written.
struct TraceTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// The printout of one phase.
struct TraceBlock {
  Phase phase;
  TraceTable nodes, particles;
};

/// A number as the trace writes it: 15 significant digits in CSV (0.1 + 0.2 is 0.3), 10 in a table.
inline std::string trace_number(double value, bool csv) {
  char text[40];
  std::snprintf(text, sizeof text, csv ? "%.15g" : "%.10g", value == 0.0 ? 0.0 : value);  // no -0
  return text;
}

/// The rows of `table`, each after the phase's name and equations and `at` (node or particle), as CSV.
inline void print_csv_table(const TraceTable& table, const PhaseInfo& info, std::ostream& out) {
  if (table.rows.empty()) return;
  out << "phase,equation,at";
  for (const auto& name : table.header) out << "," << (&name == &table.header[0] ? "index" : name);
  out << "\n";
  for (const auto& row : table.rows) {
    out << info.name << "," << info.equation << "," << table.header[0];
    for (const auto& cell : row) out << "," << cell;
    out << "\n";
  }
}

/// `table` with its columns aligned, right-justified, indented by two spaces.
inline void print_aligned_table(const TraceTable& table, std::ostream& out) {
  if (table.rows.empty()) return;
  std::vector<size_t> width(table.header.size());
  for (size_t k = 0; k < width.size(); ++k) {
    width[k] = table.header[k].size();
    for (const auto& row : table.rows) width[k] = std::max(width[k], row[k].size());
  }
  auto line = [&](const std::vector<std::string>& cells) {
    out << " ";
    for (size_t k = 0; k < cells.size(); ++k) out << " " << std::string(width[k] - cells[k].size(), ' ') << cells[k];
    out << "\n";
  };
  line(table.header);
  for (const auto& row : table.rows) line(row);
}

/// ", Eq. (30)", ", Eqs. (14)-(15)" or "" for a phase without an equation ("-").
inline std::string equations_text(const std::string& equation) {
  if (equation.empty() || equation[0] != '(') return "";
  return (equation.size() > 4 ? ", Eqs. " : ", Eq. ") + equation;
}

}  // namespace mpm::cli
