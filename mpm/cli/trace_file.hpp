/// \file
/// A trace read back: the CSV that `mpm trace ... --format csv` writes (its title, each phase's line, and the tables of
/// nodes and particles under their headers), parsed and checked line by line for `mpm trace --diff`
/// (mpm/cli/trace_diff.hpp). Anything else is refused, naming the file and the line; only regular files are read, so a
/// FIFO never waits.
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "mpm/cli/options.hpp"
#include "mpm/io/csv_file.hpp"

namespace mpm::cli {

/// The most fields (in headers and rows together) a trace may hold: 10 million, some 150 MB of CSV.
inline constexpr std::size_t most_trace_fields = 10000000;

/// One table of a phase read back: its columns (after `phase,equation,at,index`) and its rows, each a node's or a
/// particle's, in the file's order.
struct TraceRows {
  std::vector<std::string> columns;
  std::vector<long> index;                       ///< the node or particle of each row
  std::vector<double> values;                    ///< row after row, columns.size() each (NaN in the column `fixed`)
  int text_column = -1;                          ///< the column `fixed`, whose cells are words: -, x, y, xy
  std::vector<std::string> texts;                ///< its cell of each row
  std::unordered_map<long, std::size_t> row_of;  ///< the row of each index
};

/// One phase read back: its name, its label as the comparison names it, its nodes' and its particles' tables.
struct TracePhase {
  std::string name;   ///< "forces"
  std::string label;  ///< "phase 5 (forces, Eqs. (14)-(15))", from its line `# phase 5 of 7: forces, Eqs. ...: what`
  TraceRows nodes, particles;
};

/// A trace read back: its title's step, t_k, dt, dimension and integrator, and its phases in order.
struct ReadTrace {
  long step = 0;
  double time = 0.0, dt = 0.0;
  int dimension = 0;
  std::string integrator;  ///< "forward Euler (fe), update stress first (usf), ..."
  std::vector<TracePhase> phases;
  std::unordered_map<std::string, std::size_t> phase_of;  ///< the phase of each name
  const TracePhase* find(const std::string& name) const {
    const auto found = phase_of.find(name);
    return found == phase_of.end() ? nullptr : &phases[found->second];
  }
};

/// Splits a trace line at its commas (a trace quotes nothing).
inline std::vector<std::string> trace_fields(const std::string& line) {
  std::vector<std::string> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

/// True when `text` is not empty and each of its characters is in `allowed` or, when `words`, a letter, digit or _.
inline bool made_of(const std::string& text, const char* allowed, bool words = true) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [&](char c) {
           return (words && (std::isalnum(static_cast<unsigned char>(c)) || c == '_')) ||
                  (c != '\0' && std::strchr(allowed, c));
         });
}

/// True when every character of `text` is printable ASCII (a label printed back to a terminal).
inline bool printable(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return c >= ' ' && c <= '~'; });
}

/// Reads a trace (`mpm trace ... --format csv`) line by line, checking each line; refuses what is not one with
/// `NAME:LINE: why` (Refused).
class TraceReader {
 public:
  TraceReader(const std::string& text, std::string name) : text_(text), name_(std::move(name)) {}

  /// The whole trace: its title, then phases' lines, headers and rows (other # lines and blank lines skipped).
  ReadTrace read() {
    std::string line;
    if (!next_line(line)) throw Refused(name_ + ": empty, not a trace of mpm trace");
    title(line);
    while (next_line(line)) {
      if (line.rfind("# phase ", 0) == 0) {
        phase(line);
      } else if (line.empty() || line[0] == '#') {
        continue;
      } else {
        const std::vector<std::string> fields = trace_fields(line);
        if ((fields_ += fields.size()) > most_trace_fields) refuse("more than 10 million fields: too large a trace");
        fields[0] == "phase" ? header(fields) : row(fields);
      }
    }
    if (trace_.phases.empty()) refuse("no line '# phase N of M: ...': not a whole trace");
    return std::move(trace_);
  }

 private:
  [[noreturn]] void refuse(const std::string& why) const {
    throw Refused(name_ + ":" + std::to_string(line_) + ": " + why);
  }

  /// The next line without its end (LF or CR LF) and, on line 1, without a byte-order mark; false at the end.
  bool next_line(std::string& line) {
    if (start_ >= text_.size()) return false;
    ++line_;
    const std::size_t end = std::min(text_.find('\n', start_), text_.size());
    if (end - start_ > io::longest_line) refuse("a line longer than 1 MiB: not a trace");
    line.assign(text_, start_, end - start_);
    start_ = end + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    return true;
  }

  /// Line 1: `# mpm trace SCENE: step N from t_k = T s to t_k + dt, dt = DT s; 1D; INTEGRATOR` (SCENE left out).
  void title(const std::string& line) {
    const std::string hint = " (write one with mpm trace SCENE.toml --step N --format csv)";
    if (line.rfind("# mpm trace ", 0) != 0)
      refuse("not a CSV trace of mpm trace: its first line is not '# mpm trace ...'" + hint);
    const std::size_t at = line.rfind(": step ");
    int end = 0;
    const bool read = at != std::string::npos &&
                      std::sscanf(line.c_str() + at, ": step %ld from t_k = %lf s to t_k + dt, dt = %lf s; %dD; %n",
                                  &trace_.step, &trace_.time, &trace_.dt, &trace_.dimension, &end) == 4 && end > 0;
    if (!read || trace_.step < 1 || !std::isfinite(trace_.time) || !std::isfinite(trace_.dt) ||
        (trace_.dimension != 1 && trace_.dimension != 2) || !printable(trace_.integrator = line.substr(at + end)))
      refuse("not the title of mpm trace: '# mpm trace SCENE: step N from t_k = T s to t_k + dt, dt = DT s; 1D; ...'" +
             hint);
  }

  /// `# phase N of M: NAME, Eqs. (..): what it does` (or `NAME: what`): a new phase, its name not seen before.
  void phase(const std::string& line) {
    const std::string wrong = "not a phase's line of mpm trace: '# phase N of M: NAME, Eq. (..): what it does'";
    const std::size_t of = line.find(" of "), colon = line.find(": ", 8);
    if (of == std::string::npos || colon == std::string::npos || of > colon) refuse(wrong);
    const std::size_t end = line.find(": ", colon + 2);
    const std::string number = line.substr(8, of - 8), count = line.substr(of + 4, colon - of - 4);
    const std::string label = end == std::string::npos ? "" : line.substr(colon + 2, end - colon - 2);
    TracePhase phase;
    phase.name = label.substr(0, label.find(','));
    phase.label = "phase " + number + " (" + label + ")";
    const char* digits = "0123456789";
    if (!made_of(number, digits, false) || !made_of(count, digits, false) || number.size() > 6 || count.size() > 6 ||
        !made_of(phase.name, "") || !printable(label))
      refuse(wrong);
    if (trace_.find(phase.name)) refuse("phase " + phase.name + " a second time");
    trace_.phase_of[phase.name] = trace_.phases.size();
    trace_.phases.push_back(std::move(phase));
    columns_.clear();
    table_ = nullptr;
  }

  /// `phase,equation,at,index,NAME,...`: the columns of the rows that follow.
  void header(const std::vector<std::string>& fields) {
    if (trace_.phases.empty()) refuse("a header before the first phase's line '# phase N of M: ...'");
    if (fields.size() < 5 || fields[1] != "equation" || fields[2] != "at" || fields[3] != "index")
      refuse("not a header of mpm trace: 'phase,equation,at,index,' and the names of the columns");
    columns_.assign(fields.begin() + 4, fields.end());
    std::unordered_set<std::string> seen;
    for (std::size_t k = 0; k < columns_.size(); ++k) {
      if (!made_of(columns_[k], ""))
        refuse("column " + std::to_string(k + 5) + ": not a name of letters, digits and _");
      if (!seen.insert(columns_[k]).second) refuse("column " + columns_[k] + " twice in the header");
    }
    table_ = nullptr;
  }

  /// A node's or a particle's row under the last header: the current phase's name, its index once in its table,
  /// a finite number in each column but `fixed` (-, x, y or xy).
  void row(const std::vector<std::string>& fields) {
    if (columns_.empty()) refuse("a row before its header 'phase,equation,at,index,...'");
    if (fields.size() != columns_.size() + 4)
      refuse(std::to_string(fields.size()) + " fields; the header has " + std::to_string(columns_.size() + 4));
    TracePhase& phase = trace_.phases.back();
    if (fields[0] != phase.name) refuse("a row of phase '" + fields[0].substr(0, 64) + "' in phase " + phase.name);
    if (fields[2] != "node" && fields[2] != "particle")
      refuse("at: '" + fields[2].substr(0, 64) + "', not node or particle");
    TraceRows& table = fields[2] == "node" ? phase.nodes : phase.particles;
    if (table_ != &table && !table.columns.empty()) refuse("a second " + fields[2] + " table in phase " + phase.name);
    if (table_ != &table) start_table(table);
    if (!made_of(fields[3], "0123456789", false) || fields[3].size() > 9)
      refuse("index: '" + fields[3].substr(0, 64) + "' is not a node's or a particle's number");
    const long index = std::stol(fields[3]);
    if (!table.row_of.emplace(index, table.index.size()).second)
      refuse(fields[2] + " " + fields[3] + " a second time in phase " + phase.name);
    table.index.push_back(index);
    for (std::size_t k = 0; k < columns_.size(); ++k) {
      const std::string& cell = fields[k + 4];
      double value = std::numeric_limits<double>::quiet_NaN();
      const bool word = static_cast<int>(k) == table.text_column;
      if (word && cell != "-" && cell != "x" && cell != "y" && cell != "xy")
        refuse("fixed: '" + cell.substr(0, 64) + "' is not -, x, y or xy");
      if (!word && cell.size() > 64) refuse(columns_[k] + ": '" + cell.substr(0, 64) + "...': not a number of a trace");
      if (const std::string why = word ? "" : io::read_finite_number(cell, value); !why.empty())
        refuse(columns_[k] + ": " + why);
      table.values.push_back(value);
      if (word) table.texts.push_back(cell);
    }
  }

  /// The first row of `table`: its columns are the last header's.
  void start_table(TraceRows& table) {
    table.columns = columns_;
    const auto fixed = std::find(columns_.begin(), columns_.end(), "fixed");
    table.text_column = fixed == columns_.end() ? -1 : static_cast<int>(fixed - columns_.begin());
    table_ = &table;
  }

  const std::string& text_;
  std::size_t start_ = 0;  ///< where the next line starts
  std::string name_;
  int line_ = 0;
  std::size_t fields_ = 0;
  ReadTrace trace_;
  std::vector<std::string> columns_;  ///< the last header's, for the rows below it
  TraceRows* table_ = nullptr;        ///< the table the rows below the last header go to, once one has
};

/// A trace in `text` (a run's, in this process), named `name` in what is refused.
inline ReadTrace read_trace_text(const std::string& text, const std::string& name) {
  return TraceReader(text, name).read();
}

/// The most bytes a trace file may hold: 256 MiB.
inline constexpr std::size_t most_trace_bytes = std::size_t(1) << 28;

/// The trace file `path`, a regular file (io::open_regular_file: a FIFO or a device refused at once, never waited on).
/// \throws Refused (`FILE: why`, `FILE:LINE: why`).
inline ReadTrace read_trace_file(const std::string& path) {
  std::string error, text;
  bool missing = false;
  const int descriptor = io::open_regular_file(path, error, missing);
  if (descriptor < 0) throw Refused(error);
  char buffer[1 << 16];
  ssize_t count = 1;
  while (count != 0 && text.size() <= most_trace_bytes) {
    count = ::read(descriptor, buffer, sizeof buffer);
    if (count < 0 && errno != EINTR) break;
    text.append(buffer, static_cast<std::size_t>(std::max<ssize_t>(count, 0)));
  }
  const int why = errno;
  ::close(descriptor);
  if (count < 0) throw Refused(path + ": cannot be read: " + std::strerror(why));
  if (text.size() > most_trace_bytes) throw Refused(path + ": over 256 MiB: too large a trace");
  return read_trace_text(text, path);
}

TEST_CASE("mpm trace --diff: what is not a trace is refused, naming the file and the line") {
  const std::string start = "# mpm trace s.toml: step 1 from t_k = 0 s to t_k + dt, dt = 0.1 s; 2D; fe\n"
                            "# phase 0 of 1: reset: zero\n";
  const std::string header = "phase,equation,at,index,m_p,x_p_k\n", row = "reset,-,particle,0,1,0.5\n";
  CHECK(read_trace_text(start + header + row, "t.csv").phases[0].particles.values == std::vector<double>{1.0, 0.5});
  const std::vector<std::pair<std::string, std::string>> refused{  // a text, and what its refusal says
      {"", "t.csv: empty, not a trace of mpm trace"},
      {"mpm trace s.toml: step 1\n", "t.csv:1: not a CSV trace of mpm trace"},  // a --format table trace
      {"# mpm trace s.toml: step one\n", "t.csv:1: not the title of mpm trace"},
      {start.substr(0, start.find('\n') + 1), "t.csv:1: no line '# phase N of M: ...'"},
      {start + "# phase x of 1: forces: f\n", "t.csv:3: not a phase's line"},
      {start + "# phase 1 of 1: reset: zero\n", "t.csv:3: phase reset a second time"},
      {start.substr(0, start.find('\n') + 1) + header, "t.csv:2: a header before the first phase's line"},
      {start + "phase,equation,at,m_p\n", "t.csv:3: not a header of mpm trace"},
      {start + "phase,equation,at,index,m_p,m_p\n", "t.csv:3: column m_p twice in the header"},
      {start + row, "t.csv:3: a row before its header"},
      {start + header + "reset,-,particle,0,1\n", "t.csv:4: 5 fields; the header has 6"},
      {start + header + "reset,-,particle,0,1,0.5x\n", "t.csv:4: x_p_k: '0.5x' is not a finite number"},
      {start + header + "reset,-,particle,0,1,nan\n", "t.csv:4: x_p_k: 'nan' is not a finite number"},
      {start + header + "reset,-,particle,-1,1,0\n", "t.csv:4: index: '-1' is not a node's or a particle's number"},
      {start + header + row + row, "t.csv:5: particle 0 a second time in phase reset"},
      {start + header + "forces,-,particle,0,1,0\n", "t.csv:4: a row of phase 'forces' in phase reset"},
      {start + header + "reset,-,grid,0,1,0\n", "t.csv:4: at: 'grid', not node or particle"},
      {start + "phase,equation,at,index,fixed\nreset,-,node,0,z\n", "t.csv:4: fixed: 'z' is not -, x, y or xy"},
      {start + std::string(io::longest_line + 1, 'x'), "t.csv:3: a line longer than 1 MiB: not a trace"}};
  for (const auto& [text, message] : refused)
    CHECK_THROWS_WITH_AS(read_trace_text(text, "t.csv"), doctest::Contains(message.c_str()), Refused);
  // Files: a regular file read, a FIFO refused at once (no writer waited for).
  namespace fs = std::filesystem;
  const std::string path = (fs::temp_directory_path() / ("mpm_trace_diff_" + std::to_string(::getpid()))).string();
  std::ofstream(path) << start << header << "reset,-,particle,0,1,0.5\r\nreset,-,particle,1,1,x\n";
  CHECK_THROWS_WITH_AS(read_trace_file(path), (path + ":5: x_p_k: 'x' is not a finite number").c_str(), Refused);
  fs::remove(path);
  REQUIRE(::mkfifo(path.c_str(), 0600) == 0);
  CHECK_THROWS_WITH_AS(read_trace_file(path), (path + ": not a regular file (a FIFO)").c_str(), Refused);
  fs::remove(path);
}

}  // namespace mpm::cli
