/// \file
/// Reading a scene: a TOML file plus `--set KEY=VALUE` overrides. A SceneReader reads one table of it and
/// turns every problem into a SceneError at the key's file and line (`error: FILE:LINE: KEY: what`).
#pragma once
#include <doctest/doctest.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#define TOML_EXCEPTIONS 1
#define TOML_HEADER_ONLY 0  // the parser is compiled once, in mpm/io/toml_parser.cpp
#include <toml++/toml.h>
#include <unistd.h>

#include "mpm/core/errors.hpp"
#include "mpm/io/csv_file.hpp"

namespace mpm::io {

/// The line of a node in its file.
inline int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

/// Words as the messages list them: "a | b | c".
inline std::string join(const std::vector<std::string>& words) {
  std::string joined;
  for (const auto& word : words) joined += (joined.empty() ? "" : " | ") + word;
  return joined;
}

struct SceneFile {
  std::string path;
  toml::table table;
  /// keys set by `--set`, as full paths ("solver.cfl", "body[0].max"), with their origin "--set(n)"
  std::map<std::string, std::string> overridden;
};

/// The largest scene file read: a few kB is usual; the bound keeps a hostile file from exhausting memory.
inline constexpr std::size_t max_scene_bytes = 1 << 20;
/// The deepest nesting accepted: dotted-key levels (`a.b.c`) and open brackets (`[[`, `{`).
inline constexpr int max_scene_nesting = 64;

/// Refuses, before toml++ 3.3 sees it, text it would fail on: nesting beyond max_scene_nesting (its parser
/// recurses: the stack overflows) and a table header not starting with a key (`[[[1]]]`, `[ ]`: it asserts
/// or reads on in undefined behaviour). A lexical scan that skips strings and comments.
inline void check_scene_text(std::string_view text, const std::string& name) {
  int line = 1, depth = 0, dots = 0;
  bool line_start = true;  // only blanks so far on this line
  auto refuse = [&](const std::string& what) { throw SceneError(name, line, "(syntax)", what); };
  auto starts_key = [&](std::size_t k) {  // after `[`: another `[`, blanks, then a bare key's character or a quote
    if (k < text.size() && text[k] == '[') ++k;
    while (k < text.size() && (text[k] == ' ' || text[k] == '\t')) ++k;
    const char first = k < text.size() ? text[k] : '\n';
    return std::isalnum(static_cast<unsigned char>(first)) || std::strchr("_-\"'", first) != nullptr;
  };
  const std::string deeper = " nest deeper than " + std::to_string(max_scene_nesting) + " levels";
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char character = text[k];
    const bool first_on_line = line_start;
    line_start = character == '\n' || (line_start && (character == ' ' || character == '\t'));
    if (character == '\n') {
      ++line;
      dots = 0;
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
        if (character == '"' && text[k] == '\\') {
          ++k;
          continue;
        }
        if (text.substr(k, close.size()) == close) {
          k += close.size() - 1;
          break;
        }
      }
    } else if (character == '[' || character == '{') {
      if (character == '[' && first_on_line && !starts_key(k + 1))
        refuse("a table header must start with a key: write [name] or [[name]]");
      if (++depth > max_scene_nesting) refuse("brackets" + deeper);
      dots = 0;
    } else if (character == ']' || character == '}') {
      depth = std::max(depth - 1, 0);
      dots = 0;
    } else if (character == '=' || character == ',') {
      dots = 0;
    } else if (character == '.' && ++dots > max_scene_nesting) {
      refuse("dotted keys" + deeper);
    }
  }
}

/// The text of the scene file `path`, read once it is known to be a regular file (a FIFO, a device, a folder
/// or a file of /proc is refused at once). \throws SceneError for the file as a whole (`error: FILE: why`)
/// if it cannot be read or is larger than max_scene_bytes.
inline std::string read_scene_text(const std::string& path) {
  std::string why;
  bool missing = false;
  const int descriptor = open_regular_file(path, why, missing);
  if (descriptor < 0) throw SceneError(path, 0, "", why.substr(path.size() + 2));
  std::FILE* file = ::fdopen(descriptor, "rb");
  std::string text(max_scene_bytes + 1, '\0');
  text.resize(file ? std::fread(&text[0], 1, text.size(), file) : 0);
  if (!file || std::ferror(file)) why = std::strerror(errno);
  if (file)
    std::fclose(file);
  else
    ::close(descriptor);
  if (!why.empty()) throw SceneError(path, 0, "", "cannot be read: " + why);
  if (text.size() > max_scene_bytes)
    throw SceneError(path, 0, "", "is larger than " + std::to_string(max_scene_bytes) + " bytes; a scene is a few kB");
  return text;
}

/// Parses a scene given as text (`name` locates its errors). \throws SceneError on a syntax error, with its line.
inline SceneFile parse_scene_text(const std::string& text, const std::string& name) {
  check_scene_text(text, name);
  try {
    return SceneFile{name, toml::parse(std::string_view(text), std::string_view(name)), {}};
  } catch (const toml::parse_error& error) {
    throw SceneError(name, static_cast<int>(error.source().begin.line), "(syntax)", std::string(error.description()));
  }
}

/// Parses the scene file. \throws SceneError if it cannot be read (read_scene_text) or on a syntax error.
inline SceneFile parse_scene_file(const std::string& path) { return parse_scene_text(read_scene_text(path), path); }

/// The parts of a `--set` key ("body[0].max": "body", "[0]", "max"): bare TOML keys joined by dots, each
/// optionally followed by one index [n] of at most 6 digits, the last without one. Empty for any other text.
inline std::vector<std::string> key_parts(const std::string& key) {
  std::vector<std::string> parts;
  auto bare = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; };
  for (std::size_t k = 0, names = 1; names <= static_cast<std::size_t>(max_scene_nesting); ++names, ++k) {
    const std::size_t start = k;
    while (k < key.size() && bare(key[k])) ++k;
    if (k == start) return {};
    parts.push_back(key.substr(start, k - start));
    if (k == key.size()) return parts;
    if (key[k] == '[') {
      const std::size_t open = k++;
      while (k < key.size() && std::isdigit(static_cast<unsigned char>(key[k]))) ++k;
      if (k == open + 1 || k - open > 7 || k + 1 >= key.size() || key[k] != ']') return {};
      parts.push_back(key.substr(open, ++k - open));
    }
    if (key[k] != '.') return {};
  }
  return {};
}

/// Applies one `--set KEY=VALUE`: VALUE is any TOML value (`0.2`, `[160]`, `"lme"`); KEY is a dotted
/// path, with [n] for the n-th entry of an array of tables (`body[0].max`). Missing tables are created.
inline void apply_override(SceneFile& scene, const std::string& assignment, int argument_number) {
  const std::string origin = "--set(" + std::to_string(argument_number) + ")";
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw SceneError(origin, 1, assignment.substr(0, 64), "expected KEY=VALUE, e.g. --set solver.cfl=0.2");
  const std::string key = assignment.substr(0, equals);
  const std::vector<std::string> parts = key_parts(key);
  if (parts.empty())
    throw SceneError(origin, 1, key.substr(0, 64),
                     "not a key: write a dotted path of letters, digits, _ and -, with [n] for the n-th [[table]], "
                     "e.g. solver.cfl or body[0].max (at most " + std::to_string(max_scene_nesting) + " levels)");
  const std::string value_text = "value = " + assignment.substr(equals + 1);
  toml::table parsed;
  try {
    check_scene_text(value_text, origin);
    parsed = toml::parse(std::string_view(value_text), std::string_view(origin));
  } catch (const toml::parse_error& error) {
    throw SceneError(origin, 1, key, "the value is not TOML (" + std::string(error.description()) +
                                         "); write strings in quotes, arrays in brackets");
  } catch (const SceneError& error) {
    throw SceneError(origin, 1, key, std::string("the value is not TOML: ") + error.what());
  }
  if (parsed.size() != 1) throw SceneError(origin, 1, key, "give one value only (no newline followed by other keys)");
  toml::table* table = &scene.table;
  std::string path;  // the path of `table`, as the keys of `overridden` write it
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
  scene.overridden[key] = origin;
}

/// Reads one table of the scene, remembering which keys it was asked for so that unknown keys (usually
/// typos) can be reported.
class SceneReader {
 public:
  SceneReader(const SceneFile& scene, const toml::table& table, std::string prefix)
      : file_(scene.path), overridden_(&scene.overridden), table_(table), prefix_(std::move(prefix)) {}

  /// True if the table holds `key`.
  bool has(const std::string& key) { return node(key) != nullptr; }
  /// The key's node, nullptr when absent.
  const toml::node* node(const std::string& key) {
    known_.insert(key);
    return table_.get(key);
  }

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

  /// \throws SceneError at `key`: what is wrong and what is allowed.
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    const auto [file, line] = location(key);
    throw SceneError(file, line, full(key), what);
  }

  /// Fails on the first key of the table that no one asked for.
  void reject_unknown_keys() const {
    for (const auto& [key, node] : table_)
      if (!known_.count(std::string(key.str())))
        fail(std::string(key.str()), "unknown key; allowed here: " + join({known_.begin(), known_.end()}));
  }

  /// The key's full name: "solver.cfl", "body[0].min".
  std::string full(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }

  /// A number as the messages show it ("3e+09", "0.5", "inf", "nan").
  static std::string describe(double value) {
    std::ostringstream out;
    out << std::setprecision(6) << value;
    return out.str();
  }

 private:
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

  CHECK(key_parts("solver.cfl") == std::vector<std::string>{"solver", "cfl"});
  CHECK(key_parts("body[0].max") == std::vector<std::string>{"body", "[0]", "max"});
  CHECK(key_parts("a-b_c.d9").size() == 2);
  std::string levels = "a";
  for (int k = 1; k < 64; ++k) levels += ".a";
  CHECK(key_parts(levels).size() == 64);  // 64 levels are allowed, 65 are not
  CHECK(key_parts(levels + ".a").empty());
  for (const char* bad : {"", ".", "a..b", ".a", "a.", "body[x].max", "body[0]", "body[].max", "body[-1].max", "body[1234567].max",
                          "a b", "a[0][1].b", "\"q\".a"})
    CHECK_MESSAGE(key_parts(bad).empty(), bad);

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
  const std::string fifo =
      (fs::temp_directory_path() / ("mpm_scene_file_fifo_" + std::to_string(::getpid()) + ".toml")).string();
  fs::remove(fifo);
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(message_of(fifo) == "error: " + fifo + ": not a regular file (a FIFO)");  // no writer waited for
  fs::remove(fifo);
  CHECK(message_of("/dev/zero") == "error: /dev/zero: not a regular file (a device)");
  const std::string folder = fs::temp_directory_path().string();
  CHECK(message_of(folder) == "error: " + folder + ": is a folder, not a regular file; give a file");
  CHECK(message_of(fifo) == "error: " + fifo + ": cannot be read: no such file, or no permission");
  const std::string large =
      (fs::temp_directory_path() / ("mpm_scene_file_large_" + std::to_string(::getpid()) + ".toml")).string();
  std::ofstream(large) << "# " << std::string(max_scene_bytes, 'x') << "\n";
  CHECK(message_of(large) == "error: " + large + ": is larger than 1048576 bytes; a scene is a few kB");
  std::ofstream(large) << "dimension = 1\n";
  CHECK(message_of(large) == "accepted");
  fs::remove(large);
}

}  // namespace mpm::io
