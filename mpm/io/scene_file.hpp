/// \file
/// Reading a scene: a TOML file plus `--set KEY=VALUE` overrides, with every error pointing at
/// the file and line of the offending key.
///
/// A SceneFile holds the parsed table; a SceneReader reads typed values out of it and turns
/// every problem into a SceneError (`error: FILE:LINE: KEY: what is wrong and what is allowed`).
#pragma once
#include <doctest/doctest.h>

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#define TOML_EXCEPTIONS 1
#define TOML_HEADER_ONLY 1
#include <toml++/toml.h>

#include "mpm/core/errors.hpp"

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

/// Parses the scene file. \throws SceneError on a syntax error, with its line.
inline SceneFile parse_scene_file(const std::string& path) {
  try {
    return SceneFile{path, toml::parse_file(path), {}};
  } catch (const toml::parse_error& error) {
    if (error.source().begin.line == 0 && std::string(error.description()).find("open") != std::string::npos)
      throw SceneError(path, 0, "(file)", "cannot be read: " + std::string(error.description()));
    throw SceneError(path, static_cast<int>(error.source().begin.line), "(syntax)", std::string(error.description()));
  }
}

/// Parses a scene given as text (tests, tools). \throws SceneError on a syntax error.
inline SceneFile parse_scene_text(const std::string& text, const std::string& name) {
  try {
    return SceneFile{name, toml::parse(std::string_view(text), std::string_view(name)), {}};
  } catch (const toml::parse_error& error) {
    throw SceneError(name, static_cast<int>(error.source().begin.line), "(syntax)", std::string(error.description()));
  }
}

/// Applies one `--set KEY=VALUE`: VALUE is any TOML value (`0.2`, `[160]`, `"lme"`); KEY is a dotted
/// path, with [n] for the n-th entry of an array of tables (`body[0].max`). Missing tables are created.
inline void apply_override(SceneFile& scene, const std::string& assignment, int argument_number) {
  const std::string origin = "--set(" + std::to_string(argument_number) + ")";
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw SceneError(origin, 1, assignment, "expected KEY=VALUE, e.g. --set solver.cfl=0.2");
  const std::string key = assignment.substr(0, equals);
  toml::table parsed;
  try {
    parsed = toml::parse(std::string_view("value = " + assignment.substr(equals + 1)), std::string_view(origin));
  } catch (const toml::parse_error& error) {
    throw SceneError(origin, 1, key, "the value is not TOML (" + std::string(error.description()) +
                                         "); write strings in quotes, arrays in brackets");
  }
  const auto parts = split_key_path(key);
  toml::table* table = &scene.table;
  for (size_t k = 0; k + 1 < parts.size(); ++k) {
    const std::string& part = parts[k];
    if (k + 1 < parts.size() && parts[k + 1][0] == '[') {
      toml::array* array = (*table)[part].as_array();
      const int index = std::stoi(parts[k + 1].substr(1));
      if (!array || index < 0 || index >= static_cast<int>(array->size()) || !(*array)[index].is_table())
        throw SceneError(origin, 1, key, "no table " + part + "[" + std::to_string(index) + "] in the scene");
      table = (*array)[index].as_table();
      ++k;
      continue;
    }
    if (!table->contains(part)) table->insert(part, toml::table{});
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

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    if (auto override = overridden_->find(full(key)); override != overridden_->end())
      throw SceneError(override->second, 1, full(key), what);
    const toml::node* node = table_.get(key);
    throw SceneError(file_, node ? line_of(*node) : line_of(table_), full(key), what);
  }

  double number(const std::string& key, std::optional<double> fallback = std::nullopt) {
    known_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing; a number is required");
    }
    if (auto value = node->value<double>(); value && (node->is_floating_point() || node->is_integer())) return *value;
    fail(key, "must be a number");
  }

  double positive(const std::string& key, std::optional<double> fallback = std::nullopt) {
    const double value = number(key, fallback);
    if (!(value > 0.0)) fail(key, "must be > 0, got " + std::to_string(value));
    return value;
  }

  int integer(const std::string& key, std::optional<int> fallback = std::nullopt) {
    known_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing; an integer is required");
    }
    if (!node->is_integer()) fail(key, "must be an integer");
    return static_cast<int>(*node->value<int64_t>());
  }

  std::string text(const std::string& key, const std::vector<std::string>& allowed, std::optional<std::string> fallback = std::nullopt) {
    known_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing; one of " + join(allowed) + " is required");
    }
    if (!node->is_string()) fail(key, "must be a string in quotes, one of " + join(allowed));
    const std::string value = *node->value<std::string>();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), value) == allowed.end())
      fail(key, "'" + value + "' is not allowed; use one of " + join(allowed));
    return value;
  }

  std::string any_text(const std::string& key, const std::string& fallback) {
    known_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) return fallback;
    if (!node->is_string()) fail(key, "must be a string in quotes");
    return *node->value<std::string>();
  }

  /// An array of numbers; `size` < 0 accepts any length.
  std::vector<double> numbers(const std::string& key, int size, std::optional<std::vector<double>> fallback = std::nullopt) {
    known_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing; an array of " + count_text(size) + " numbers is required");
    }
    const toml::array* array = node->as_array();
    if (!array) fail(key, "must be an array of numbers, e.g. [1.0]");
    if (size >= 0 && static_cast<int>(array->size()) != size)
      fail(key, "has " + std::to_string(array->size()) + " entries; the scene's dimension needs " + std::to_string(size));
    std::vector<double> values;
    for (const auto& entry : *array) {
      if (!(entry.is_floating_point() || entry.is_integer())) fail(key, "must hold numbers only");
      values.push_back(*entry.value<double>());
    }
    return values;
  }

  std::vector<std::string> texts(const std::string& key, const std::vector<std::string>& allowed) {
    known_.insert(key);
    const toml::node* node = table_.get(key);
    const toml::array* array = node ? node->as_array() : nullptr;
    if (!array) fail(key, "must be an array of strings, each one of " + join(allowed));
    std::vector<std::string> values;
    for (const auto& entry : *array) {
      auto value = entry.value<std::string>();
      if (!value || std::find(allowed.begin(), allowed.end(), *value) == allowed.end())
        fail(key, "entries must be one of " + join(allowed));
      values.push_back(*value);
    }
    return values;
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
  const std::string& file() const { return file_; }
  int line() const { return line_of(table_); }

 private:
  static std::string count_text(int size) { return size < 0 ? "some" : std::to_string(size); }
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

TEST_CASE("Scene file: overrides land in nested tables and arrays of tables; errors carry file and line") {
  SceneFile scene = parse_scene_text("dimension = 1\n[solver]\ncfl = 0.5\n[[body]]\nmin = [0.0]\n", "test.toml");
  apply_override(scene, "solver.cfl=0.2", 1);
  apply_override(scene, "grid.cells=[160]", 2);
  apply_override(scene, "body[0].min=[1.5]", 3);
  CHECK(scene.table["solver"]["cfl"].value<double>() == 0.2);
  CHECK(scene.table["grid"]["cells"][0].value<int>() == 160);
  CHECK(scene.table["body"][0]["min"][0].value<double>() == 1.5);
  CHECK_THROWS_AS(apply_override(scene, "solver.cfl", 4), SceneError);
  CHECK_THROWS_AS(apply_override(scene, "solver.shape=lme", 5), SceneError);  // unquoted string

  SceneReader solver(scene, *scene.table["solver"].as_table(), "solver");
  CHECK(solver.number("cfl") == 0.2);
  CHECK(scene.overridden.at("body[0].min") == "--set(3)");
  try {
    solver.positive("shape_of_things", -1.0);
    FAIL("a negative value must be rejected");
  } catch (const SceneError& error) {
    CHECK(error.message().rfind("error: test.toml:2: solver.shape_of_things: must be > 0", 0) == 0);
  }
  apply_override(scene, "solver.cfl=-0.5", 6);
  try {
    solver.positive("cfl");
    FAIL("a negative CFL must be rejected");
  } catch (const SceneError& error) {
    CHECK(error.message() == "error: --set(6):1: solver.cfl: must be > 0, got -0.500000");
  }
  try {
    SceneReader root(scene, scene.table, "");
    root.integer("dimension");
    root.reject_unknown_keys();  // solver, grid and body were not asked for
    FAIL("unknown keys must be rejected");
  } catch (const SceneError& error) {
    CHECK(error.message().rfind("error: test.toml:", 0) == 0);
  }
  SceneFile bad = parse_scene_text("[solver]\ncfl = -1\n", "bad.toml");
  SceneReader bad_solver(bad, *bad.table["solver"].as_table(), "solver");
  try {
    bad_solver.positive("cfl");
    FAIL("a negative CFL must be rejected");
  } catch (const SceneError& error) {
    CHECK(error.message() == "error: bad.toml:2: solver.cfl: must be > 0, got -1.000000");
  }
}

}  // namespace mpm::io
