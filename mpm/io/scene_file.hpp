/// \file
/// Reading a scene: a TOML file plus `--set KEY=VALUE` overrides, with every error pointing at
/// the file and line of the offending key.
///
/// A SceneFile holds the parsed table; a SceneReader reads typed values out of it and turns
/// every problem into a SceneError (`error: FILE:LINE: KEY: what is wrong and what is allowed`).
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <iomanip>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#define TOML_EXCEPTIONS 1
#define TOML_HEADER_ONLY 0  // the parser is compiled once, in mpm/io/toml_parser.cpp
#include <toml++/toml.h>

#include "mpm/core/errors.hpp"
#include "mpm/io/csv_file.hpp"

namespace mpm::io {

inline int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

/// Splits "a.b[2].c" into {"a", "b", "[2]", "c"}.
inline std::vector<std::string> split_key_path(const std::string& path) {
  std::vector<std::string> parts;
  std::string current;
  for (char character : path) {
    if (character == '.' || character == '[') {
      if (!current.empty()) parts.push_back(current);
      current = character == '[' ? "[" : "";
    } else if (character == ']') {
      parts.push_back(current + "]");
      current.clear();
    } else {
      current += character;
    }
  }
  if (!current.empty()) parts.push_back(current);
  return parts;
}

struct SceneFile {
  std::string path;
  toml::table table;
  /// keys set by `--set`, as full paths ("solver.cfl", "body[0].max"), with their origin "--set(n)"
  std::map<std::string, std::string> overridden;
};

/// The largest scene file read (scenes are a few kB; the bound keeps a hostile file from
/// exhausting memory inside the TOML parser).
inline constexpr std::size_t max_scene_bytes = 1 << 20;
/// The deepest nesting accepted: dotted-key levels (`a.b.c`) and open brackets (`[[`, `{`).
/// The TOML parser recurses on both, so a key of 200 000 levels would overflow the stack.
inline constexpr int max_scene_nesting = 64;

/// Refuses TOML text that nests deeper than max_scene_nesting, before the parser sees it. A
/// lexical scan: strings and comments are skipped, dots are counted between delimiters
/// (`=`, `,`, brackets, end of line), open brackets are counted until closed.
inline void check_nesting(std::string_view text, const std::string& name) {
  int line = 1, depth = 0, dots = 0;
  auto refuse = [&](const std::string& what) {
    throw SceneError(name, line, "(syntax)", what + " nest deeper than " + std::to_string(max_scene_nesting) + " levels");
  };
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char character = text[k];
    if (character == '\n') {
      ++line, dots = 0;
    } else if (character == '#') {
      while (k + 1 < text.size() && text[k + 1] != '\n') ++k;
    } else if (character == '"' || character == '\'') {
      const bool multiline = text.substr(k, 3) == std::string(3, character);
      const std::string close = multiline ? std::string(3, character) : std::string(1, character);
      for (k += close.size(); k < text.size(); ++k) {
        if (text[k] == '\n') {
          ++line;
          if (!multiline) break;
        }
        if (character == '"' && text[k] == '\\') { ++k; continue; }
        if (text.substr(k, close.size()) == close) { k += close.size() - 1; break; }
      }
    } else if (character == '[' || character == '{') {
      if (++depth > max_scene_nesting) refuse("brackets");
      dots = 0;
    } else if (character == ']' || character == '}') {
      depth = depth > 0 ? depth - 1 : 0, dots = 0;
    } else if (character == '=' || character == ',') {
      dots = 0;
    } else if (character == '.' && ++dots > max_scene_nesting) {
      refuse("dotted keys");
    }
  }
}

/// Refuses a table header that does not start with a key (`[[[1]]]`, `[[=`, `[ ]`), before the
/// parser sees it: the Debian TOML parser (toml++ 3.3) assumes a key starts there and, given anything
/// else, trips an internal assertion (debug builds) or reads on in undefined behaviour (release),
/// instead of reporting a syntax error. A line whose first non-blank character is `[` is a header
/// (or a nested array on its own line, which no scene key takes): after `[` or `[[` and blanks, a
/// bare-key character or a quote must follow.
inline void check_table_headers(std::string_view text, const std::string& name) {
  int line = 1;
  for (std::size_t start = 0; start < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::size_t k = text.find_first_not_of(" \t", start);
    if (k < end && text[k] == '[') {
      ++k;
      if (k < end && text[k] == '[') ++k;
      while (k < end && (text[k] == ' ' || text[k] == '\t')) ++k;
      const char first = k < end ? text[k] : '\n';
      const bool starts_key = std::isalnum(static_cast<unsigned char>(first)) || first == '_' || first == '-' ||
                              first == '"' || first == '\'';
      if (!starts_key)
        throw SceneError(name, line, "(syntax)", "a table header must start with a key: write [name] or [[name]]");
    }
    start = end + 1;
  }
}

/// The text of the scene file `path`, read with read(2) once it is known to be a regular file (a FIFO,
/// a device, a folder or a file of /proc is refused at once, never waited on or read). \throws SceneError
/// for the file as a whole (`error: FILE: why`) if it cannot be read or is larger than max_scene_bytes.
inline std::string read_scene_text(const std::string& path) {
  std::string why;
  bool missing = false;
  const int descriptor = open_regular_file(path, why, missing);
  if (descriptor < 0) throw SceneError(path, 0, "", why.substr(path.size() + 2));
  std::string text(max_scene_bytes + 1, '\0');
  std::size_t size = 0;
  while (size < text.size()) {
    const ssize_t count = ::read(descriptor, &text[size], text.size() - size);
    if (count < 0 && errno == EINTR) continue;
    if (count < 0) why = std::strerror(errno);
    if (count <= 0) break;
    size += static_cast<std::size_t>(count);
  }
  ::close(descriptor);
  if (!why.empty()) throw SceneError(path, 0, "", "cannot be read: " + why);
  if (size > max_scene_bytes)
    throw SceneError(path, 0, "", "is larger than " + std::to_string(max_scene_bytes) + " bytes; a scene is a few kB");
  text.resize(size);
  return text;
}

/// Parses the scene file. \throws SceneError if it cannot be read (see read_scene_text) or on a syntax
/// error, with its line.
inline SceneFile parse_scene_file(const std::string& path) {
  const std::string text = read_scene_text(path);
  check_nesting(text, path);
  check_table_headers(text, path);
  try {
    return SceneFile{path, toml::parse(std::string_view(text), std::string_view(path)), {}};
  } catch (const toml::parse_error& error) {
    throw SceneError(path, static_cast<int>(error.source().begin.line), "(syntax)", std::string(error.description()));
  }
}

/// Parses a scene given as text (tests, tools). \throws SceneError on a syntax error.
inline SceneFile parse_scene_text(const std::string& text, const std::string& name) {
  check_nesting(text, name);
  check_table_headers(text, name);
  try {
    return SceneFile{name, toml::parse(std::string_view(text), std::string_view(name)), {}};
  } catch (const toml::parse_error& error) {
    throw SceneError(name, static_cast<int>(error.source().begin.line), "(syntax)", std::string(error.description()));
  }
}

/// True if `key` is a path of bare TOML keys joined by dots, each optionally followed by one
/// index `[n]` (n of at most 6 digits), the last without an index: `solver.cfl`, `body[0].max`.
inline bool is_key_path(const std::string& key) {
  std::size_t k = 0, segments = 0;
  auto bare = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; };
  while (true) {
    const std::size_t start = k;
    while (k < key.size() && bare(key[k])) ++k;
    if (k == start || ++segments > static_cast<std::size_t>(max_scene_nesting)) return false;
    if (k == key.size()) return true;
    if (key[k] == '[') {
      const std::size_t digits = ++k;
      while (k < key.size() && std::isdigit(static_cast<unsigned char>(key[k]))) ++k;
      if (k == digits || k - digits > 6 || k >= key.size() || key[k] != ']') return false;
      if (++k == key.size()) return false;  // the last segment names a key, not a table of an array
    }
    if (key[k] != '.') return false;
    ++k;
  }
}

/// Applies one `--set KEY=VALUE`: VALUE is any TOML value (`0.2`, `[160]`, `"lme"`); KEY is a dotted
/// path, with [n] for the n-th entry of an array of tables (`body[0].max`). Missing tables are created.
inline void apply_override(SceneFile& scene, const std::string& assignment, int argument_number) {
  const std::string origin = "--set(" + std::to_string(argument_number) + ")";
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw SceneError(origin, 1, assignment.substr(0, 64), "expected KEY=VALUE, e.g. --set solver.cfl=0.2");
  const std::string key = assignment.substr(0, equals);
  if (!is_key_path(key))
    throw SceneError(origin, 1, key.substr(0, 64), "not a key: write a dotted path of letters, digits, _ and -, with [n] "
                                                   "for the n-th [[table]], e.g. solver.cfl or body[0].max (at most " +
                                                   std::to_string(max_scene_nesting) + " levels)");
  const std::string value_text = "value = " + assignment.substr(equals + 1);
  toml::table parsed;
  try {
    check_nesting(value_text, origin);
    check_table_headers(value_text, origin);
    parsed = toml::parse(std::string_view(value_text), std::string_view(origin));
  } catch (const toml::parse_error& error) {
    throw SceneError(origin, 1, key, "the value is not TOML (" + std::string(error.description()) +
                                         "); write strings in quotes, arrays in brackets");
  } catch (const SceneError& error) {
    throw SceneError(origin, 1, key, std::string("the value is not TOML: ") + error.what());
  }
  if (parsed.size() != 1) throw SceneError(origin, 1, key, "give one value only (no newline followed by other keys)");
  const auto parts = split_key_path(key);
  toml::table* table = &scene.table;
  std::string path;  // the full path of `table`, normalised like the keys of `overridden`
  for (size_t k = 0; k + 1 < parts.size(); ++k) {
    const std::string& part = parts[k];
    path += (path.empty() ? "" : ".") + part;
    if (parts[k + 1][0] == '[') {
      toml::array* array = (*table)[part].as_array();
      const int index = std::stoi(parts[k + 1].substr(1));
      if (!array || index >= static_cast<int>(array->size()) || !(*array)[index].is_table())
        throw SceneError(origin, 1, key, "no table " + part + "[" + std::to_string(index) + "] in the scene");
      table = (*array)[index].as_table();
      path += parts[++k];
      continue;
    }
    if (!table->contains(part)) {
      table->insert(part, toml::table{});
      scene.overridden.emplace(path, origin);  // a table created here is located at this --set
    }
    if ((*table)[part].is_array_of_tables())
      throw SceneError(origin, 1, key, "'" + part + "' is an array of tables; write " + part + "[0]." + parts[k + 1]);
    table = (*table)[part].as_table();
    if (!table) throw SceneError(origin, 1, key, "'" + part + "' is not a table");
  }
  table->insert_or_assign(parts.back(), *parsed["value"].node());
  std::string full_key;  // normalised: "body[0].max"
  for (const auto& part : parts) full_key += (full_key.empty() || part[0] == '[' ? "" : ".") + part;
  scene.overridden[full_key] = origin;
}

/// Reads typed values from one table of the scene, remembering which keys it was asked for so
/// that unknown keys (usually typos) can be reported.
class SceneReader {
 public:
  SceneReader(const SceneFile& scene, const toml::table& table, std::string prefix)
      : file_(scene.path), overridden_(&scene.overridden), table_(table), prefix_(std::move(prefix)) {}

  bool has(const std::string& key) { known_.insert(key); return table_.contains(key); }
  /// The key's node (nullptr when absent), for keys of a shape the typed readers below do not read.
  const toml::node* node(const std::string& key) { known_.insert(key); return table_.get(key); }

  /// Where `key` lies: the --set that gave it or created its table, else its line, else its table's (line 1
  /// for a table the scene does not have: its required keys are refused there, by name).
  std::pair<std::string, int> location(const std::string& key) const {
    if (auto override = overridden_->find(full(key)); override != overridden_->end()) return {override->second, 1};
    for (std::string path = prefix_; !path.empty();) {
      if (auto created = overridden_->find(path); created != overridden_->end()) return {created->second, 1};
      const auto cut = path.find_last_of(".[");
      path = cut == std::string::npos ? "" : path.substr(0, cut);
    }
    const toml::node* node = table_.get(key);
    return {file_, std::max(1, node ? line_of(*node) : line_of(table_))};
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    const auto [file, line] = location(key);
    throw SceneError(file, line, full(key), what);
  }

  /// Fails on the first key of the table that no one asked for.
  void reject_unknown_keys() const {
    for (const auto& [key, node] : table_) {
      const std::string name(key.str());
      if (!known_.count(name)) {
        std::vector<std::string> allowed(known_.begin(), known_.end());
        fail(name, "unknown key; allowed here: " + join(allowed));
      }
    }
  }

  std::string full(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }

  /// A number as the messages show it ("3e+09", "0.5", "inf", "nan").
  static std::string describe(double value) {
    std::ostringstream out;
    out << std::setprecision(6) << value;
    return out.str();
  }

 private:
  static std::string join(const std::vector<std::string>& words) {
    std::string joined;
    for (const auto& word : words) joined += (joined.empty() ? "" : " | ") + word;
    return joined;
  }

  std::string file_;
  const std::map<std::string, std::string>* overridden_;
  const toml::table& table_;
  std::string prefix_;
  std::set<std::string> known_;
};

TEST_CASE("Scene file: overrides land in nested tables and arrays of tables, errors carry file and line") {
  SceneFile scene = parse_scene_text("dimension = 1\n[solver]\ncfl = 0.5\n[[body]]\nmin = [0.0]\n", "test.toml");
  apply_override(scene, "solver.cfl=0.2", 1);
  apply_override(scene, "grid.cells=[160]", 2);
  apply_override(scene, "body[0].min=[1.5]", 3);
  CHECK(scene.table["solver"]["cfl"].value<double>() == 0.2);
  CHECK(scene.table["grid"]["cells"][0].value<int>() == 160);
  CHECK(scene.table["body"][0]["min"][0].value<double>() == 1.5);
  CHECK_THROWS_AS(apply_override(scene, "solver.cfl", 4), SceneError);
  CHECK_THROWS_AS(apply_override(scene, "solver.shape=lme", 5), SceneError);  // unquoted string

  using Where [[maybe_unused]] = std::pair<std::string, int>;
  SceneReader solver(scene, *scene.table["solver"].as_table(), "solver");
  CHECK(scene.overridden.at("body[0].min") == "--set(3)");
  CHECK(solver.location("cfl") == Where{"--set(1)", 1});
  CHECK(solver.location("shape_of_things") == Where{"test.toml", 2});  // absent: its table's line
  const toml::table none;  // a table the scene lacks: its keys are located at line 1, never 0
  CHECK(SceneReader(scene, none, "output").location("every") == Where{"test.toml", 1});
  try {
    SceneReader root(scene, scene.table, "");
    root.has("dimension");
    root.reject_unknown_keys();  // solver, grid and body were not asked for
    FAIL("unknown keys must be rejected");
  } catch (const SceneError& error) {
    CHECK(error.message().rfind("error: test.toml:", 0) == 0);
  }
  SceneFile bad = parse_scene_text("[solver]\ncfl = -1\n", "bad.toml");
  CHECK(SceneReader(bad, *bad.table["solver"].as_table(), "solver").location("cfl") == Where{"bad.toml", 2});
}

TEST_CASE("Scene file: a table header that does not start with a key is a syntax error, never the parser's assertion") {
  auto message_of = [](const std::string& text) {
    try {
      parse_scene_text(text, "h.toml");
    } catch (const SceneError& error) {
      return error.message();
    }
    return std::string("accepted");
  };
  const std::string refused = "error: h.toml:2: (syntax): a table header must start with a key: write [name] or [[name]]";
  for (const std::string header : {"[[[1]]]", "[[[a]]]", "[[[]]", "[[=", "  [ ]", "[\t]"}) {
    CAPTURE(header);
    CHECK(message_of("title = \"t\"\n" + header + "\n") == refused);
  }
  CHECK(message_of("[grid]\n[[body]]\n[ \"quoted key\" ]\n[[ 'also' ]]\nx = [\n  [1.0],\n]\n") == "accepted");
  SceneFile file = parse_scene_text("[solver]\ncfl = 0.5\n", "o.toml");
  CHECK_THROWS_AS(apply_override(file, "solver.cfl=0.5\n[[[1]]]", 1), SceneError);
}

TEST_CASE("Scene file: hostile input is refused with its key: nesting, key paths, overrides") {
  auto message_of = [](auto action) -> std::string {
    try {
      action();
    } catch (const SceneError& error) {
      return error.message();
    }
    return "no error";
  };
  // 200 000 dotted levels would overflow the TOML parser's stack: refused before it runs
  std::string deep = "x = 1\n";
  for (int k = 0; k < 200000; ++k) deep += "a.";
  deep += "b = 1\n";
  CHECK(message_of([&] { parse_scene_text(deep, "d.toml"); }) == "error: d.toml:2: (syntax): dotted keys nest deeper than 64 levels");
  CHECK(message_of([&] { parse_scene_text("x = " + std::string(1000, '['), "d.toml"); }) ==
        "error: d.toml:1: (syntax): brackets nest deeper than 64 levels");
  // dots and brackets inside strings and comments do not count; 64 levels are allowed
  std::string fine = "s = \"" + std::string(100, '.') + "[[[\" # " + std::string(100, '.') + "\n";
  for (int k = 0; k < 63; ++k) fine += "a.";
  CHECK(message_of([&] { parse_scene_text(fine + "b = 1\n", "f.toml"); }) == "no error");

  CHECK(is_key_path("solver.cfl"));
  CHECK(is_key_path("body[0].max"));
  CHECK(is_key_path("a-b_c.d9"));
  for (const char* bad : {"", ".", "a..b", ".a", "a.", "body[x].max", "body[0]", "body[].max", "body[-1].max", "body[1234567].max",
                          "a b", "a[0][1].b", "\"q\".a"})
    CHECK_MESSAGE(!is_key_path(bad), bad);

  SceneFile scene = parse_scene_text("[t]\nk = 1\n", "h.toml");
  // overrides: keys are checked, and keys inside tables a --set created are located at that --set
  CHECK(message_of([&] { apply_override(scene, ".=1", 2); }).rfind("error: --set(2):1: .: not a key", 0) == 0);
  CHECK(message_of([&] { apply_override(scene, "t[x].k=1", 2); }).rfind("error: --set(2):1: t[x].k: not a key", 0) == 0);
  CHECK(message_of([&] { apply_override(scene, "t.k=1\nz=2", 2); }).rfind("error: --set(2):1: t.k: give one value only", 0) == 0);
  CHECK(message_of([&] { apply_override(scene, "t.k=" + std::string(100, '['), 2); }).rfind("error: --set(2):1: t.k: the value is not TOML", 0) == 0);
  apply_override(scene, "made.deeper.key=1", 3);
  SceneReader made(scene, *scene.table["made"].as_table(), "made");
  CHECK(message_of([&] { made.fail("other", "missing"); }) == "error: --set(3):1: made.other: missing");
  CHECK(message_of([&] { made.reject_unknown_keys(); }).rfind("error: --set(3):1: made.deeper: unknown key", 0) == 0);
}

TEST_CASE("Scene file: a scene that is not a regular file is refused at once, as `error: FILE: why`") {
  namespace fs = std::filesystem;
  auto message_of = [](const std::string& path) {
    try {
      parse_scene_file(path);
    } catch (const SceneError& error) {
      return error.message();
    }
    return std::string("accepted");
  };
  const std::string fifo = (fs::temp_directory_path() / "mpm_scene_file_fifo.toml").string();
  fs::remove(fifo);
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(message_of(fifo) == "error: " + fifo + ": not a regular file (a FIFO)");  // no writer waited for
  fs::remove(fifo);
  CHECK(message_of("/dev/zero") == "error: /dev/zero: not a regular file (a device)");
  const std::string folder = fs::temp_directory_path().string();
  CHECK(message_of(folder) == "error: " + folder + ": is a folder, not a regular file; give a file");
  CHECK(message_of(fifo) == "error: " + fifo + ": cannot be read: no such file, or no permission");
  const std::string large = (fs::temp_directory_path() / "mpm_scene_file_large.toml").string();
  std::ofstream(large) << "# " << std::string(max_scene_bytes, 'x') << "\n";
  CHECK(message_of(large) == "error: " + large + ": is larger than 1048576 bytes; a scene is a few kB");
  std::ofstream(large) << "dimension = 1\n";
  CHECK(message_of(large) == "accepted");
  fs::remove(large);
}

}  // namespace mpm::io
