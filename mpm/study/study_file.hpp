/// \file
/// A study file (`mpm study STUDY.toml`): which scene, which observer is scored, fixed overrides and the axes
/// whose product is the study. It is TOML, read by the scenes' own reader (io::parse_scene_file: the same size
/// and nesting limits, syntax errors with their line), and every key is checked before anything runs or is
/// written: each problem is a SceneError, `error: STUDY.toml:LINE: KEY: why` (exit 2).
///
///   scene = "../scenes/dyka_bar.toml"     # relative to the study file
///   observer = "A"                        # default: the scene's first [[observer]]
///   refine = "grid.cells"                 # the axis orders are fitted over (default grid.cells if an axis)
///   [set]                                 # fixed overrides, as `mpm run --set KEY=VALUE`
///   solver.end_time = 1.0e-4
///   [axes]                                # KEY = [values...]; the study is their product
///   grid.cells = [[10], [20], [40], [80]]
///   solver.shape = ["linear", "lme"]
///   "body[0].particles_per_cell" = [[1], [2]]
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mpm/io/scene_file.hpp"
#include "mpm/io/scene_keys.hpp"

namespace mpm::study {

/// The most cases a study may have: each is a run, and their folders are numbered with four digits.
inline constexpr std::size_t most_cases = 10000;

/// One value of a key: as TOML for `--set` (`[40]`, `"lme"`, `0.5`) and as a CSV cell (`40`, `lme`, `0.5`).
struct Value {
  std::string toml, label;
  std::optional<double> number;  ///< a number, or an array's first entry when it is one: the refine axis's N
};

/// A `[set]` entry: one fixed override.
struct Setting {
  std::string key;
  Value value;
  int line = 1;
};

/// An `[axes]` entry: a key and the values it takes, in the file's order.
struct Axis {
  std::string key;
  std::vector<Value> values;
  int line = 1;
};

/// A study as its file gives it, every key checked.
struct Study {
  std::string path;               ///< the study file (the default --out is runs/NAME, NAME its stem: io::default_folder)
  std::string scene;              ///< the scene's path, relative to the study file's folder when written relative
  std::optional<std::string> observer;
  std::vector<Setting> set;
  std::vector<Axis> axes;
  int refine = -1;                ///< the index in `axes` of the axis the orders are fitted over; -1: none
  int scene_line = 1, observer_line = 1;
};

/// A float as TOML writes it back, kept a float (`1.0`, `2e-05`): 15 digits, or 17 where 15 do not read back the same.
inline std::string float_text(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.15g", value);
  if (std::strtod(text, nullptr) != value) std::snprintf(text, sizeof text, "%.17g", value);
  std::string result = text;
  if (result.find_first_of(".eEn") == std::string::npos) result += ".0";
  return result;
}

/// `node` (a number, string, boolean or array of them) as a Value. \throws SceneError at `key` for any other node.
inline Value value_of(const toml::node& node, const std::string& file, const std::string& key) {
  if (const auto* array = node.as_array()) {
    Value value{"[", "", std::nullopt};
    for (std::size_t k = 0; k < array->size(); ++k) {
      const Value entry = value_of((*array)[k], file, key);
      value.toml += (k ? ", " : "") + entry.toml, value.label += (k ? " " : "") + entry.label;
      if (k == 0) value.number = entry.number;
    }
    return value.toml += "]", value;
  }
  if (node.is_integer()) {
    const double number = static_cast<double>(*node.value_exact<int64_t>());
    return {std::to_string(*node.value_exact<int64_t>()), std::to_string(*node.value_exact<int64_t>()), number};
  }
  if (node.is_floating_point()) {
    const double number = *node.value_exact<double>();
    char label[32];
    std::snprintf(label, sizeof label, "%.12g", number);
    return {float_text(number), label, number};
  }
  if (node.is_boolean()) return {*node.value_exact<bool>() ? "true" : "false", *node.value_exact<bool>() ? "true" : "false", {}};
  if (const auto text = node.value_exact<std::string>()) {
    std::string quoted = "\"";
    for (char character : *text) {
      if (static_cast<unsigned char>(character) < 0x20 || character == 0x7f)
        throw SceneError(file, io::line_of(node), key, "a string holding a control character");
      quoted += character == '"' || character == '\\' ? std::string("\\") + character : std::string(1, character);
    }
    return {quoted + "\"", *text, {}};
  }
  throw SceneError(file, io::line_of(node), key, "must be a number, a string, a boolean or an array of them");
}

/// True if `key` names a key of a scene (io::scene_keys: `body[0].max` as `body[].max`; any `constants.NAME`).
inline bool is_scene_key(const std::string& key) {
  if (io::key_parts(key).empty()) return false;
  if (key.rfind("constants.", 0) == 0) return key.find('.', 10) == std::string::npos;
  std::string general;
  for (std::size_t k = 0; k < key.size(); ++k) {
    general += key[k];
    if (key[k] == '[') k = key.find(']', k) - 1;
  }
  for (const auto& known : io::scene_keys())
    if (known.key == general) return true;
  return false;
}

/// The leaves of `table` as dotted keys (`[set] solver.cfl = 0.5` and `"solver.cfl" = 0.5` both give solver.cfl),
/// in the file's order (a toml::table is ordered by key).
inline void flatten(const toml::table& table, const std::string& prefix, std::vector<std::pair<std::string, const toml::node*>>& leaves) {
  for (const auto& [name, node] : table) {
    const std::string key = prefix + std::string(name.str());
    if (const auto* inner = node.as_table()) flatten(*inner, key + ".", leaves);
    else leaves.emplace_back(key, &node);
  }
  std::stable_sort(leaves.begin(), leaves.end(), [](const auto& a, const auto& b) {
    const auto &x = a.second->source().begin, &y = b.second->source().begin;
    return x.line != y.line ? x.line < y.line : x.column < y.column;
  });
}

/// The `[set]` entries of `table`, each a scene key with a value. \throws SceneError.
inline std::vector<Setting> read_settings(const toml::table& table, const std::string& file) {
  std::vector<std::pair<std::string, const toml::node*>> leaves;
  flatten(table, "", leaves);
  std::vector<Setting> settings;
  for (const auto& [key, node] : leaves) {
    if (!is_scene_key(key)) throw SceneError(file, io::line_of(*node), key, "not a scene key (mpm run --help lists them)");
    settings.push_back({key, value_of(*node, file, key), io::line_of(*node)});
  }
  return settings;
}

/// The keys of an axis: "grid.cells" alone, or those of a linked axis, "grid.cells, solver.dt". \throws SceneError.
inline std::vector<std::string> axis_keys(const std::string& key, const std::string& file, int line) {
  std::vector<std::string> keys;
  for (std::size_t start = 0, end = 0; end != std::string::npos; start = end + 1) {
    end = key.find(',', start);
    std::string part = key.substr(start, end == std::string::npos ? std::string::npos : end - start);
    part.erase(0, part.find_first_not_of(' '));
    part.erase(part.find_last_not_of(' ') + 1);
    if (!is_scene_key(part))
      throw SceneError(file, line, key, (key.find(',') == std::string::npos ? "" : "'" + part + "' is ") +
                                            "not a scene key (mpm run --help lists them)");
    if (std::find(keys.begin(), keys.end(), part) != keys.end())
      throw SceneError(file, line, key, part + " is linked twice");
    keys.push_back(part);
  }
  return keys;
}

/// One value of an axis of `keys`; a linked axis's is an array of one value per key. \throws SceneError.
inline Value axis_value(const Axis& axis, const std::vector<std::string>& keys, const toml::node& entry,
                        const std::string& file) {
  Value value = value_of(entry, file, axis.key);
  const auto* parts = entry.as_array();
  if (keys.size() > 1 && (!parts || parts->size() != keys.size()))
    throw SceneError(file, axis.line, axis.key, "each value of a linked axis is an array of one value per key, [" +
                                                    std::to_string(keys.size()) + " values], got " + value.toml);
  return value;
}

/// The overrides of one value of `axis`: `key=value`, or for a linked axis one per key. \throws SceneError.
inline std::vector<std::string> axis_overrides(const Axis& axis, const Value& value) {
  const std::vector<std::string> keys = axis_keys(axis.key, "", axis.line);
  if (keys.size() < 2) return {axis.key + "=" + value.toml};
  const toml::table parsed = toml::parse("value = " + value.toml);
  const toml::array& parts = *parsed["value"].as_array();
  std::vector<std::string> overrides;
  for (std::size_t j = 0; j < keys.size(); ++j)
    overrides.push_back(keys[j] + "=" + value_of(parts[j], "", axis.key).toml);
  return overrides;
}

/// The `[axes]` entries of `table`: scene keys, each with a non-empty array of distinct values; a linked axis names
/// several keys, "grid.cells, solver.dt" = [[[10], 1e-5], [[20], 5e-6]], that change together. \throws SceneError.
inline std::vector<Axis> read_axes(const toml::table& table, const std::string& file) {
  std::vector<std::pair<std::string, const toml::node*>> leaves;
  flatten(table, "", leaves);
  std::vector<Axis> axes;
  for (const auto& [key, node] : leaves) {
    const int line = io::line_of(*node);
    Axis axis{key, {}, line};
    const std::vector<std::string> keys = axis_keys(key, file, line);
    for (const auto& other : axes)
      for (const auto& linked : keys)
        if (const auto others = axis_keys(other.key, file, other.line);
            std::find(others.begin(), others.end(), linked) != others.end())
          throw SceneError(file, line, key,
                           linked + " is on another axis too (line " + std::to_string(other.line) + ")");
    const auto* values = node->as_array();
    if (!values || values->empty())
      throw SceneError(file, line, key, "an axis is a non-empty array of the values the key takes: [v1, v2, ...] "
                                        "(grid.cells = [[10], [20]]: each value an array of cells)");
    for (const auto& entry : *values) {
      axis.values.push_back(axis_value(axis, keys, entry, file));
      for (std::size_t k = 0; k + 1 < axis.values.size(); ++k)
        if (axis.values[k].toml == axis.values.back().toml)
          throw SceneError(file, line, key, "the value " + axis.values.back().toml + " is given twice");
    }
    axes.push_back(axis);
  }
  return axes;
}

/// A string key of the study's top level. \throws SceneError if it is not a string (or an empty one).
inline std::string read_string(const toml::node& node, const std::string& file, const std::string& key) {
  const auto text = node.value_exact<std::string>();
  if (!text || text->empty()) throw SceneError(file, io::line_of(node), key, "must be a non-empty string");
  return *text;
}

/// The refine axis: `refine` if given, else grid.cells if it is an axis, else none; its values must be numbers
/// > 0 (or arrays starting with one: grid.cells = [[10], [20]]). \throws SceneError.
inline int find_refine_axis(const Study& study, const toml::node* refine, const std::string& file) {
  const std::string wanted = refine ? read_string(*refine, file, "refine") : "grid.cells";
  int found = -1;
  for (std::size_t k = 0; k < study.axes.size(); ++k)
    if (study.axes[k].key == wanted) found = static_cast<int>(k);
  if (found < 0 && refine) throw SceneError(file, io::line_of(*refine), "refine", "'" + wanted + "' is not a key of [axes]");
  if (found < 0) return -1;
  for (const auto& value : study.axes[found].values)
    if (!value.number || !(*value.number > 0.0))
      throw SceneError(file, refine ? io::line_of(*refine) : study.axes[found].line, refine ? "refine" : wanted,
                       "the refine axis's values must be numbers > 0 (or arrays starting with one), got " + value.toml);
  return found;
}

/// Reads and checks the study file `path`. \throws SceneError (`error: FILE:LINE: KEY: why`).
inline Study read_study(const std::string& path) {
  const io::SceneFile file = io::parse_scene_file(path);
  Study study;
  study.path = path;
  for (const auto& [name, node] : file.table) {
    const std::string key(name.str());
    if (key != "scene" && key != "observer" && key != "refine" && key != "set" && key != "axes")
      throw SceneError(path, io::line_of(node), key, "unknown key; a study has scene, observer, refine, [set] and [axes]");
    if ((key == "set" || key == "axes") && !node.is_table())
      throw SceneError(path, io::line_of(node), key, "must be a table: [" + key + "]");
  }
  const toml::node* scene = file.table.get("scene");
  if (!scene) throw SceneError(path, 1, "scene", "required: the scene file the study runs, relative to the study file");
  study.scene = read_string(*scene, path, "scene"), study.scene_line = io::line_of(*scene);
  const std::filesystem::path relative(study.scene);
  if (relative.is_relative()) study.scene = (std::filesystem::path(path).parent_path() / relative).lexically_normal().string();
  if (const toml::node* observer = file.table.get("observer"))
    study.observer = read_string(*observer, path, "observer"), study.observer_line = io::line_of(*observer);
  if (const auto* set = file.table.get_as<toml::table>("set")) study.set = read_settings(*set, path);
  if (const auto* axes = file.table.get_as<toml::table>("axes")) study.axes = read_axes(*axes, path);
  if (study.axes.empty()) throw SceneError(path, 1, "axes", "required: [axes] with at least one KEY = [values...]");
  for (const auto& axis : study.axes)
    for (const auto& setting : study.set)
      if (const auto keys = axis_keys(axis.key, path, axis.line);
          std::find(keys.begin(), keys.end(), setting.key) != keys.end())
        throw SceneError(path, setting.line, setting.key, "is an axis too; give it in one place");
  std::size_t cases = 1;
  for (const auto& axis : study.axes)
    if ((cases *= axis.values.size()) > most_cases)
      throw SceneError(path, axis.line, axis.key, "the study has more than " + std::to_string(most_cases) + " cases; run fewer values");
  study.refine = find_refine_axis(study, file.table.get("refine"), path);
  return study;
}

TEST_CASE("study file: axes and overrides as TOML values, every key checked with its line") {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("mpm_study_file_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  auto write = [&](const std::string& text) {
    const std::string file = (folder / "s.toml").string();
    std::FILE* out = std::fopen(file.c_str(), "w");
    std::fputs(text.c_str(), out);
    std::fclose(out);
    return file;
  };
  auto refusal = [&](const std::string& text) {
    try {
      read_study(write(text));
    } catch (const SceneError& error) {
      return error.message();
    }
    return std::string("(accepted)");
  };
  const Study study = read_study(write("scene = \"x.toml\"\nrefine = \"grid.cells\"\n[set]\nsolver.end_time = 1e-4\n"
                                       "[axes]\ngrid.cells = [[10], [20]]\nsolver.shape = [\"linear\", \"lme\"]\n"
                                       "\"body[0].particles_per_cell\" = [[1], [2]]\nsolver.cfl = [0.5, 1.0]\n"));
  CHECK(study.scene == (folder / "x.toml").string());
  REQUIRE(study.axes.size() == 4);
  CHECK(study.set[0].key == "solver.end_time");
  CHECK(study.set[0].value.toml == "0.0001");
  CHECK(study.axes[0].values[1].toml == "[20]");
  CHECK(study.axes[0].values[1].label == "20");
  CHECK(study.axes[1].values[1].toml == "\"lme\"");
  CHECK(study.axes[1].values[1].label == "lme");
  CHECK(study.axes[2].key == "body[0].particles_per_cell");
  CHECK(study.axes[3].values[1].toml == "1.0");
  CHECK(float_text(0.1) == "0.1");
  CHECK(float_text(0.1 + 0.2) == "0.30000000000000004");
  CHECK(study.refine == 0);
  CHECK(refusal("scene = \"x.toml\"\n[axes]\nsolver.cfll = [1]\n") == "error: " + (folder / "s.toml").string() +
                                                                         ":3: solver.cfll: not a scene key (mpm run --help lists them)");
  CHECK(refusal("scene = \"x.toml\"\nbogus = 1\n[axes]\nsolver.cfl = [1]\n").find(":2: bogus: unknown key") != std::string::npos);
  CHECK(refusal("[axes]\nsolver.cfl = [1]\n").find(":1: scene: required") != std::string::npos);
  CHECK(refusal("scene = \"x.toml\"\n[axes]\nsolver.cfl = []\n").find(":3: solver.cfl: an axis is a non-empty array") != std::string::npos);
  CHECK(refusal("scene = \"x.toml\"\n[axes]\nsolver.cfl = [1, 1]\n").find("given twice") != std::string::npos);
  CHECK(refusal("scene = \"x.toml\"\nrefine = \"solver.shape\"\n[axes]\nsolver.shape = [\"lme\"]\n").find(":2: refine: the refine axis") !=
        std::string::npos);
  CHECK(refusal("scene = \"x.toml\"\n[set]\nsolver.cfl = 1\n[axes]\nsolver.cfl = [1]\n").find(":3: solver.cfl: is an axis too") !=
        std::string::npos);
  CHECK(refusal("scene = \"x.toml\"\n[axes]\nsolver.cfl = [{a = 1}]\n").find("must be a number, a string") != std::string::npos);
  std::string many = "scene = \"x.toml\"\n[axes]\n";
  for (const char* key : {"solver.cfl", "solver.lme_gamma", "solver.lme_tol", "solver.newmark_gamma", "solver.flip_fraction"})
    many += std::string(key) + " = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7]\n";
  CHECK(refusal(many).find("more than 10000 cases") != std::string::npos);
  const Study linked = read_study(write("scene = \"x.toml\"\n[axes]\n\"grid.cells, solver.dt\" = [[[10], 1e-5], "
                                        "[[20], 5e-6]]\nsolver.shape = [\"linear\"]\n"));
  REQUIRE(linked.axes.size() == 2);
  CHECK(axis_overrides(linked.axes[0], linked.axes[0].values[1]) ==
        std::vector<std::string>{"grid.cells=[20]", "solver.dt=5e-06"});
  CHECK(linked.axes[0].values[1].label == "20 5e-06");
  CHECK(axis_overrides(linked.axes[1], linked.axes[1].values[0]) ==
        std::vector<std::string>{"solver.shape=\"linear\""});
  CHECK(refusal("scene = \"x.toml\"\n[axes]\n\"grid.cells, solver.dt\" = [[[10], 1e-5], [[20]]]\n")
            .find(":3: grid.cells, solver.dt: each value of a linked axis is an array of one value per key, "
                  "[2 values], got [[20]]") != std::string::npos);
  CHECK(refusal("scene = \"x.toml\"\n[axes]\n\"grid.cells, solver.dtt\" = [[[10], 1e-5]]\n")
            .find("'solver.dtt' is not a scene key") != std::string::npos);
  CHECK(refusal("scene = \"x.toml\"\n[axes]\n\"grid.cells, solver.dt\" = [[[10], 1e-5]]\nsolver.dt = [1e-5]\n")
            .find(":4: solver.dt: solver.dt is on another axis too (line 3)") != std::string::npos);
  CHECK(refusal("scene = \"x.toml\"\n[set]\nsolver.dt = 1e-5\n[axes]\n\"grid.cells, solver.dt\" = [[[10], 1e-5]]\n")
            .find(":3: solver.dt: is an axis too") != std::string::npos);
  CHECK(is_scene_key("body[3].min"));
  CHECK(is_scene_key("constants.k"));
  CHECK(!is_scene_key("body.min"));
  fs::remove_all(folder);
}

}  // namespace mpm::study
