/// \file
/// Every key a scene may hold, declared once: its name, the member it fills, its default, unit, range or
/// choices and meaning. From this table come read_scene (mpm/io/scene.hpp), `--set`, the resolved scene of
/// --print-scene and run.json (mpm/io/scene_resolved.hpp), `mpm --help`'s key list and README's key table.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "mpm/core/kernels.hpp"
#include "mpm/io/scene_file.hpp"
#include "mpm/io/scene_settings.hpp"

namespace mpm::io {

/// The values a number may take: from low to high, either end open; `note` ends the message of a refusal.
struct Range {
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
  bool low_open = false, high_open = false;
  const char* note = "";

  /// True if `value` lies in the range.
  bool holds(double value) const {
    return (low_open ? value > low : value >= low) && (high_open ? value < high : value <= high);
  }
  /// "[0, 0.5)", "(0, 10]"; "[1, 2147483647]" for integers
  std::string text() const {
    auto show = [](double x) {
      const bool integer = x == std::floor(x) && std::abs(x) < 1e18;
      return integer ? std::to_string(static_cast<long long>(x)) : SceneReader::describe(x);
    };
    return (low_open ? "(" : "[") + show(low) + ", " + show(high) + (high_open ? ")" : "]");
  }
  /// Why `value` is refused: "must be > 0, got -1.000000", "must be >= 0 (0: no ramp)", "must be in [0, 1]".
  std::string refusal(double value) const {
    if (low == 0.0 && low_open && !(value > 0.0)) return "must be > 0, got " + std::to_string(value);
    if (std::isinf(high)) return "must be >= " + SceneReader::describe(low) + note;
    return "must be in " + text() + note;
  }
};
/// (0, inf), [low, inf), [low, high] or [low, high), and the whole numbers from low to high.
inline Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true}; }
inline Range at_least(double low, const char* note) {
  return {low, std::numeric_limits<double>::infinity(), false, false, note};
}
inline Range within(double low, double high, const char* note = "", bool high_open = false) {
  return {low, high, false, high_open, note};
}
inline Range whole(long long low, long long high) { return {double(low), double(high)}; }

/// A key's default: `required` (none: the scene must give it) or `optional` (none: absent unless given).
inline constexpr const char* required = nullptr;
inline constexpr const char* optional = "";

struct SceneKey {
  std::string key;       ///< "solver.cfl"; "body[].min" for `min` of every [[body]]
  const char* fallback;  ///< the default as TOML ("0.5", "\"linear\"", "[]"; per axis: one entry); required or optional
  const char* unit;
  const char* meaning;
  Range range;                       ///< numbers and integers, each entry of an array
  std::vector<std::string> choices;  ///< a choice's words, its default first
  bool per_axis = false;             ///< the default stands for one entry per axis ("0" means [0, 0] in 2D)
  /// reads the key from `reader` (its table) into entry k of its array of tables (0 outside one)
  std::function<void(SceneReader& reader, const SceneKey&, Scene&, std::size_t k)> read;
  /// inserts the key's value into `table` (its section of the resolved scene); nothing for an optional key not given
  std::function<void(const Scene&, std::size_t k, toml::table& table)> print;

  /// true for a key absent unless given
  bool is_optional() const { return fallback && !*fallback; }
  /// its table, "" at the top ("body[].min" -> "body")
  std::string section() const {
    return key.find('.') == std::string::npos ? "" : key.substr(0, key.find_first_of(".["));
  }
  /// its name in its table ("body[].min" -> "min"; npos + 1 is 0: a key at the top is its own name)
  std::string name() const { return key.substr(key.find('.') + 1); }
  /// true for a key of an array of tables ("body[].min")
  bool in_array() const { return key.find("[]") != std::string::npos; }
  /// the default's node, in `holder` (an array of `dimension` entries for a per-axis default); nullptr if none
  const toml::node* default_node(toml::table& holder, int dimension) const {
    if (!fallback || !*fallback) return nullptr;
    holder = toml::parse("value = " + std::string(fallback));
    if (per_axis) {
      toml::array entries;
      for (int axis = 0; axis < dimension; ++axis) entries.push_back(*holder.get("value"));
      holder.insert_or_assign("value", entries);
    }
    return holder.get("value");
  }
};

namespace detail {

/// A number's value, an integer's included; nothing for any other node.
inline std::optional<double> number_value(const toml::node& node) {
  if (node.is_integer()) return static_cast<double>(*node.value_exact<int64_t>());
  if (node.is_floating_point()) return *node.value_exact<double>();
  return std::nullopt;
}

/// A finite number within `range`; `entry`: an entry of an array ("must hold numbers only", "entries must be > 0").
inline double read_number(SceneReader& reader, const std::string& name, const toml::node& node, const Range& range,
                          bool entry) {
  const auto value = number_value(node);
  if (!value) reader.fail(name, entry ? "must hold numbers only" : "must be a number");
  if (!std::isfinite(*value))
    reader.fail(name, std::string(entry ? "must hold finite numbers only" : "must be a finite number") + ", got " +
                          SceneReader::describe(*value));
  if (range.holds(*value)) return *value;
  const std::string refusal = range.refusal(*value);
  reader.fail(name, entry ? "entries " + refusal.substr(0, refusal.find(", got")) : refusal);
}

/// A whole number within `range`, checked on the file's 64-bit value whatever its size and named as written;
/// `entry`: an entry of an array, a number (checked before) that may be written as a float (40.0).
inline int read_integer(SceneReader& reader, const std::string& name, const toml::node& node, const Range& range,
                        bool entry) {
  const std::string allowed = (entry ? "entries must be whole numbers in " : "must be an integer in ") + range.text();
  if (!node.is_integer() && !entry) reader.fail(name, allowed);
  const double value = *number_value(node);
  if ((node.is_integer() || value == std::floor(value)) && range.holds(value)) return static_cast<int>(value);
  const auto integer = node.value_exact<int64_t>();
  reader.fail(name, allowed + ", got " + (integer ? std::to_string(*integer) : SceneReader::describe(value)));
}

/// The node, nullptr when the scene lacks it, as a value of the member's type M within the key's range or choices.
template <class M>
M convert(SceneReader& reader, const SceneKey& key, const toml::node* node, int dimension) {
  const std::string name = key.name();
  const int size = key.fallback && std::string(key.fallback) == "[]" ? -1 : dimension;  // an empty default: any length
  if constexpr (std::is_same_v<M, double>) {
    if (!node) reader.fail(name, "missing; a number is required");
    return read_number(reader, name, *node, key.range, false);
  } else if constexpr (std::is_same_v<M, int>) {
    if (!node) reader.fail(name, "missing; an integer in " + key.range.text() + " is required");
    return read_integer(reader, name, *node, key.range, false);
  } else if constexpr (std::is_same_v<M, std::vector<double>> || std::is_same_v<M, std::vector<int>>) {
    constexpr bool integers = std::is_same_v<M, std::vector<int>>;
    if (!node) reader.fail(name, "missing; an array of " + std::to_string(dimension) + " numbers is required");
    const toml::array* array = node->as_array();
    if (!array) reader.fail(name, "must be an array of numbers, e.g. [1.0]");
    if (size >= 0 && static_cast<int>(array->size()) != size)
      reader.fail(name, "has " + std::to_string(array->size()) + " entries; the scene's dimension needs " +
                            std::to_string(size));
    std::vector<double> numbers;  // all of them numbers before any is checked whole
    for (const toml::node& entry : *array)
      numbers.push_back(read_number(reader, name, entry, integers ? Range{} : key.range, true));
    if constexpr (!integers) {
      return numbers;
    } else {
      std::vector<int> values;
      for (const toml::node& entry : *array) values.push_back(read_integer(reader, name, entry, key.range, true));
      return values;
    }
  } else if constexpr (std::is_enum_v<M>) {
    if (!node) reader.fail(name, "missing; one of " + join(key.choices) + " is required");
    if (!node->is_string()) reader.fail(name, "must be a string in quotes, one of " + join(key.choices));
    const std::string value = *node->value<std::string>();
    const auto found = std::find(key.choices.begin(), key.choices.end(), value);
    if (found == key.choices.end())
      reader.fail(name, "'" + value + "' is not allowed; use one of " + join(key.choices));
    return static_cast<M>(found - key.choices.begin());
  } else {
    static_assert(std::is_same_v<M, std::string>);
    if (!node) reader.fail(name, "missing; a string in quotes is required");
    if (!node->is_string()) reader.fail(name, "must be a string in quotes");
    return *node->value<std::string>();
  }
}

/// A value as the resolved scene writes it: integers as integers, choices as their words.
template <class M>
void insert_value(toml::table& table, const std::string& name, const M& value) {
  if constexpr (std::is_enum_v<M>) {
    table.insert(name, name_of(value));
  } else if constexpr (std::is_same_v<M, std::vector<double>> || std::is_same_v<M, std::vector<int>>) {
    toml::array array;
    for (const auto entry : value) array.push_back(entry);
    table.insert(name, array);
  } else {
    table.insert(name, value);
  }
}

/// The object of type Owner a key of entry k fills: the scene, its RunControl, a body (its own material), a box.
template <class Owner, class S>
auto& owner_of(S& scene, std::size_t k) {
  if constexpr (std::is_same_v<Owner, Scene>) return scene;
  else if constexpr (std::is_same_v<Owner, RunControl>) return scene.control;
  else if constexpr (std::is_same_v<Owner, BodySettings>) return scene.bodies.at(k);
  else if constexpr (std::is_same_v<Owner, MaterialSettings>) return scene.bodies.at(k).material;
  else if constexpr (std::is_same_v<Owner, VelocityBox>) return scene.initial_velocities.at(k);
  else if constexpr (std::is_same_v<Owner, FixedSettings>) return scene.fixed.at(k);
  else return scene.observers.at(k);
}

}  // namespace detail

/// A key bound to a typed member (of the Scene, its RunControl, or an entry of an array of tables).
template <class Owner, class M>
SceneKey key(const std::string& name, M Owner::*member, const char* fallback, const char* unit, const char* meaning,
             Range range = {}) {
  SceneKey key{name, fallback, unit, meaning, range, {}, false, {}, {}};
  if constexpr (std::is_enum_v<M>) key.choices.assign(choice_words<M>.begin(), choice_words<M>.end());
  if constexpr (std::is_same_v<M, std::vector<double>> || std::is_same_v<M, std::vector<int>>)
    key.per_axis = fallback && *fallback && *fallback != '[';
  key.read = [member](SceneReader& reader, const SceneKey& key, Scene& scene, std::size_t k) {
    const toml::node* node = reader.node(key.name());
    toml::table holder;
    if (!node && key.is_optional()) return;
    detail::owner_of<Owner>(scene, k).*member =
        detail::convert<M>(reader, key, node ? node : key.default_node(holder, scene.dimension), scene.dimension);
  };
  key.print = [member, name = key.name(), skip_empty = key.is_optional()](const Scene& scene, std::size_t k,
                                                                          toml::table& table) {
    const M& value = detail::owner_of<Owner>(scene, k).*member;
    if constexpr (std::is_same_v<M, std::string>)
      if (skip_empty && value.empty()) return;
    detail::insert_value(table, name, value);
  };
  return key;
}

/// A key read and printed by its own functions (`read` nullptr: read with its section by another reader).
inline SceneKey custom_key(const std::string& name, const char* fallback, const char* unit, const char* meaning,
                           decltype(SceneKey::read) read, decltype(SceneKey::print) print) {
  return SceneKey{name, fallback, unit, meaning, {}, {}, false, std::move(read), std::move(print)};
}

/// `key` printed only where `shown` holds (output.every beside output.times, a body's own material).
inline SceneKey shown_if(SceneKey key, bool (*shown)(const Scene&, std::size_t)) {
  key.print = [print = key.print, shown](const Scene& scene, std::size_t k, toml::table& table) {
    if (shown(scene, k)) print(scene, k, table);
  };
  return key;
}

namespace detail {

/// The largest count of cells or margin cells on one axis: a bound that keeps every sum and
/// product of them exact in 64-bit arithmetic; the budget (scene_budget.hpp) bounds the totals.
inline constexpr int max_cells_per_axis = 100'000'000;

/// exact_parameters.velocity_amplitude or displacement_amplitude: `1.5`, `"V"` or `[1.5, "0.05 * L"]`, each a
/// number or a formula of the scene's constants in quotes. \throws SceneError naming the key.
inline void read_amplitudes(SceneReader& reader, const SceneKey& key, Scene& scene, std::size_t) {
  const toml::node* node = reader.node(key.name());
  if (!node) return;
  const toml::array* array = node->as_array();
  if (array && (array->empty() || array->size() > 2)) reader.fail(key.name(), "give one or two values");
  const FormulaVariables none{0, false};
  std::vector<double> values;
  for (std::size_t k = 0; k < (array ? array->size() : 1); ++k) {
    const toml::node& entry = array ? *array->get(k) : *node;
    std::optional<double> value = number_value(entry);
    if (!value && entry.is_string()) {
      const std::string text = *entry.value<std::string>();
      try {
        value = Formula(text, scene.formulas.constants, none)(nullptr, nullptr, 0.0);
      } catch (const mu::Parser::exception_type& error) {
        reader.fail(key.name(), formula_problem(error, text, scene.formulas.constants, none));
      }
    }
    if (!value) reader.fail(key.name(), "must be a number or a formula of the constants in quotes");
    if (!std::isfinite(*value)) reader.fail(key.name(), "must be finite, got " + SceneReader::describe(*value));
    values.push_back(*value);
  }
  if (key.name() == "velocity_amplitude") scene.exact_velocity_amplitude = values.at(0);
  else scene.exact_displacement_amplitude = values;
}

/// Prints both amplitudes, as numbers (displacement_amplitude's own print does nothing).
inline void print_amplitudes(const Scene& scene, std::size_t, toml::table& table) {
  if (scene.exact_velocity_amplitude) table.insert("velocity_amplitude", *scene.exact_velocity_amplitude);
  if (!scene.exact_displacement_amplitude.empty())
    insert_value(table, "displacement_amplitude", scene.exact_displacement_amplitude);
}

/// body[].vertices: the polygon's vertices [[x, y], ...].
inline void read_vertices(SceneReader& reader, const SceneKey&, Scene& scene, std::size_t k) {
  const toml::node* node = reader.node("vertices");
  if (!node) return;
  const toml::array* list = node->as_array();
  if (!list || list->size() < 3 || list->size() > 10000)
    reader.fail("vertices", "must be an array of 3 to 10000 points [x, y], e.g. [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]");
  for (const toml::node& entry : *list) {
    const toml::array* point = entry.as_array();
    std::array<double, 2> vertex{};
    for (int axis = 0; axis < 2; ++axis) {
      const toml::node* coordinate = point && point->size() == 2 ? point->get(axis) : nullptr;
      const auto value = coordinate ? number_value(*coordinate) : std::nullopt;
      if (!value || !std::isfinite(*value))
        reader.fail("vertices", "every vertex is a point [x, y] of two finite numbers (m)");
      vertex[axis] = *value;
    }
    scene.bodies.at(k).vertices.push_back(vertex);
  }
}

/// Prints a polygon's vertices; nothing for another shape.
inline void print_vertices(const Scene& scene, std::size_t k, toml::table& table) {
  toml::array vertices;
  for (const auto& vertex : scene.bodies.at(k).vertices) vertices.push_back(toml::array{vertex[0], vertex[1]});
  if (!vertices.empty()) table.insert("vertices", vertices);
}

/// fixed[].components: the velocity components held, ["x"] or ["x", "y"] (0: x, 1: y).
inline void read_components(SceneReader& reader, const SceneKey&, Scene& scene, std::size_t k) {
  std::vector<std::string> axes{"x", "y"};
  axes.resize(scene.dimension);
  const toml::node* node = reader.node("components");
  if (!node) reader.fail("components", "missing; an array of " + join(axes) + " is required");
  if (!node->is_array()) reader.fail("components", "must be an array of strings, each one of " + join(axes));
  for (const toml::node& entry : *node->as_array()) {
    const auto value = entry.value<std::string>();
    if (!value || std::find(axes.begin(), axes.end(), *value) == axes.end())
      reader.fail("components", "entries must be one of " + join(axes));
    scene.fixed.at(k).components.push_back(*value == "x" ? 0 : 1);
  }
}

/// Prints the components held as their names.
inline void print_components(const Scene& scene, std::size_t k, toml::table& table) {
  toml::array names;
  for (int component : scene.fixed.at(k).components) names.push_back(component == 0 ? "x" : "y");
  table.insert("components", names);
}

/// Prints [constants] resolved to numbers, the predefined material constants left out ([constants],
/// [initial_field] and [body_force] are read by read_scene_formulas, mpm/io/scene_formulas.hpp).
inline void print_constants(const Scene& scene, std::size_t, toml::table& table) {
  for (const auto& [name, value] : scene.formulas.constants)
    if (name != "young_modulus" && name != "poisson_ratio" && name != "density") table.insert(name, value);
}

/// A print of a formula list (initial_field.velocity, ...) as given, as texts.
inline auto print_formulas(const std::optional<FormulaList> SceneFormulas::*member, const char* name) {
  return [member, name](const Scene& scene, std::size_t, toml::table& table) {
    const std::optional<FormulaList>& list = scene.formulas.*member;
    if (!list) return;
    toml::array texts;
    for (const auto& component : list->components) texts.push_back(component.text());
    table.insert(name, texts);
  };
}

/// True if solver.cfl is printed: solver.dt replaces it.
inline bool courant_step(const Scene& scene, std::size_t) { return !(scene.control.fixed_dt > 0.0); }
/// True if solver.dt is printed: it was given.
inline bool fixed_step(const Scene& scene, std::size_t) { return scene.control.fixed_dt > 0.0; }
/// True if output.every is printed: output.times replaces it.
inline bool every_shown(const Scene& scene, std::size_t) { return scene.control.sample_times.empty(); }
/// True if body k has a material of its own, printed with it.
inline bool own_material(const Scene& scene, std::size_t k) {
  return !(scene.bodies.at(k).material == scene.material());
}

/// The run's title and exact solution, the grid and the material.
inline std::vector<SceneKey> header_keys() {
  return {
    key("title", &Scene::title, "\"untitled\"", "-", "name of the run (printed, written into run.json)"),
    key("dimension", &Scene::dimension, "1", "-", "1 or 2 (2D is plane strain)", whole(1, 2)),
    key("exact", &Scene::exact, "\"none\"", "-",
        "exact solution written beside the observers into exact.csv, drawn by `mpm plot`, evaluated by `mpm exact` "
        "and `mpm compare`: none | dyka_bar (1D bar free at xmin, fixed at xmax; appendix A.1-A.19) | "
        "soil_column (2D column on a roller base under gravity along -y, its height H the top of its bodies; "
        "mpm/exact/column.hpp) | vibrating_bar (a mode of the dyka_bar's bar; mpm/exact/vibrating_bar.hpp) | "
        "manufactured_small | manufactured_large (2D square, its body force and initial velocity set by the "
        "solution; mpm/exact/manufactured.hpp)"),
    key("exact_parameters.mode", &Scene::exact_mode, "1", "-",
        "vibrating_bar: the mode n, v(X, 0) = V cos((2n - 1) pi X / 2L)", whole(1, 1000)),
    custom_key("exact_parameters.velocity_amplitude", optional, "m/s",
               "vibrating_bar: V, a number or a formula of the constants (\"V\")", read_amplitudes, print_amplitudes),
    custom_key("exact_parameters.displacement_amplitude", optional, "m",
               "manufactured_small: A; manufactured_large: [a_x, a_y]; numbers or formulas of the constants",
               read_amplitudes, [](const Scene&, std::size_t, toml::table&) {}),
    key("grid.origin", &Scene::origin, "0.0", "m",
        "lower corner of the box [origin, origin + length] the body's grid spans"),
    key("grid.length", &Scene::length, required, "m", "size of the box on each axis", positive()),
    key("grid.cells", &Scene::cells, required, "cells",
        "cells on each axis; cells must be square (equal length/cells)", whole(1, max_cells_per_axis)),
    key("grid.margin_min", &Scene::margin_min, "0", "cells",
        "extra cells below origin on each axis (room to move, supports)", whole(0, max_cells_per_axis)),
    key("grid.margin_max", &Scene::margin_max, "0", "cells", "extra cells above origin + length on each axis",
        whole(0, max_cells_per_axis)),
    key("material.young_modulus", &Scene::young_modulus, required, "Pa",
        "Young's modulus E of the linear elastic material, Eq. (3)", positive()),
    key("material.poisson_ratio", &Scene::poisson_ratio, "0.0", "-", "Poisson's ratio nu, in [0, 0.5)",
        within(0.0, 0.5, "", true)),
    key("material.density", &Scene::density, required, "kg/m^3", "initial density rho", positive()),
  };
}

/// The bodies: their boxes of particles, their shapes and their own materials.
inline std::vector<SceneKey> body_keys() {
  return {
    key("body[].min", &BodySettings::min, required, "m",
        "lower corner of a box of whole cells filled with particles; bodies may not overlap (their boxes may touch)"),
    key("body[].max", &BodySettings::max, required, "m", "upper corner of the box"),
    key("body[].particles_per_cell", &BodySettings::particles_per_cell, "1", "-", "particles per cell on each axis",
        whole(1, max_cells_per_axis)),
    key("body[].velocity", &BodySettings::velocity, "0.0", "m/s", "initial velocity of the body's particles"),
    key("body[].placement", &BodySettings::placement, "\"uniform\"", "-",
        "uniform (cell split evenly) | gauss (2x2 Gauss points)"),
    key("body[].shape", &BodySettings::shape, "\"box\"", "-",
        "box | ellipse (inscribed in the box [min, max]: a disk in a square box) | polygon (vertices): the particles "
        "of the box's cells that lie in the shape are kept, each with its share of the cell's mass (2D) | file "
        "(particles read from file)"),
    custom_key("body[].vertices", optional, "m",
               "polygon: its vertices [[x, y], ...], in order, inside [min, max]; a simple polygon (its edges do "
               "not cross)", read_vertices, print_vertices),
    key("body[].file", &BodySettings::file, optional, "-",
        "file: a CSV of the body's particles, x[,y] (m), volume (m^Dim) or mass (kg), optional v_x[,v_y] (m/s), by "
        "column name; relative to the scene's folder; every particle inside [min, max]"),
    shown_if(key("body[].young_modulus", &MaterialSettings::young_modulus, optional, "Pa",
                 "the body's own material: E (default [material]'s); the time step takes the largest sqrt(E/rho); an "
                 "exact solution refuses a body of another material",
                 positive()),
             own_material),
    shown_if(key("body[].poisson_ratio", &MaterialSettings::poisson_ratio, optional, "-",
                 "the body's own material: nu in [0, 0.5) (default [material]'s)", within(0.0, 0.5, "", true)),
             own_material),
    shown_if(key("body[].density", &MaterialSettings::density, optional, "kg/m^3",
                 "the body's own material: rho_0, its particles' masses (default [material]'s)", positive()),
             own_material),
  };
}

/// The initial velocity boxes, the walls and gravity.
inline std::vector<SceneKey> loading_keys() {
  return {
    key("initial_velocity[].min", &VelocityBox::min, required, "m",
        "lower corner of a box; particles in it start with `velocity`"),
    key("initial_velocity[].max", &VelocityBox::max, required, "m", "upper corner of the box"),
    key("initial_velocity[].velocity", &VelocityBox::velocity, required, "m/s",
        "their initial velocity (later boxes win)"),
    key("fixed[].face", &FixedSettings::face, required, "-",
        "xmin | xmax | ymin | ymax of the box: a rigid wall there and beyond"),
    custom_key("fixed[].components", required, "-", "velocity components held at zero, e.g. [\"x\"]",
               read_components, print_components),
    key("gravity.acceleration", &Scene::gravity, "0.0", "m/s^2", "body force per unit mass"),
    key("gravity.ramp_period", &Scene::ramp_period, "0.0", "s",
        "T of the ramp of Eq. (44), full gravity from T/2 on (0: no ramp)", at_least(0.0, " (0: no ramp)")),
    key("gravity.evaluate_at", &RunControl::body_force_time, "\"step_end\"", "-",
        "time of a step at which the ramp is read: step_end | step_start"),
  };
}

/// The solver: shape function, integrator, time step and their options.
inline std::vector<SceneKey> solver_keys() {
  return {
    key("solver.shape", &Scene::shape, "\"linear\"", "-",
        "shape function: linear | ugimp | lme (Eqs. 34-41) | bspline2 | bspline3 (quadratic, cubic B-splines)"),
    key("solver.integrator", &Scene::integrator, "\"fe\"", "-",
        "fe (forward Euler) | npc (Newmark predictor-corrector)"),
    shown_if(key("solver.cfl", &RunControl::cfl, "0.5", "-", "Courant number of Eq. (42)",
                 {0.0, 10.0, true, false, ": far beyond any explicit scheme's stability limit"}),
             courant_step),
    shown_if(key("solver.dt", &RunControl::fixed_dt, optional, "s",
                 "a fixed time step instead of Eq. (42)'s: a scene gives dt or cfl, not both (`--set` of one "
                 "replaces the other); refused above CFL 10 at t = 0 (dt c / h), warned above the method's limit "
                 "(`mpm stability`); steps still land on output times and end_time",
                 positive()),
             fixed_step),
    key("solver.courant", &RunControl::courant, "\"max\"", "-",
        "max (Eq. 42 as printed) | sum (the authors' c + |v|)"),
    key("solver.end_time", &RunControl::end_time, required, "s",
        "time at which the run ends (the last step lands on it)", positive()),
    key("solver.lme_gamma", &Scene::lme_gamma, "3.0", "-", "LME locality gamma, beta = gamma / h^2 (Eq. 36)",
        positive()),
    key("solver.lme_tol", &Scene::lme_tol, "1e-6", "-",
        "LME support tolerance, in (0, 1): R = h sqrt(-ln(tol) / gamma)", {0.0, 1.0, true, true, ""}),
    key("solver.lme_newton_tol", &Scene::lme_newton_tol, "1e-10", "-",
        "relative tolerance of the LME Newton iteration", positive()),
    key("solver.lme_max_iterations", &Scene::lme_max_iterations, "100", "-",
        "most LME Newton iterations before the run fails", whole(1, 1000)),
    key("solver.lme_beta", &Scene::lme_beta, "\"grid_spacing\"", "-",
        "grid_spacing | mean_neighbour_distance | authors (NL-PartSol's)"),
    key("solver.lme_neighbours", &Scene::lme_neighbours, "\"support_radius\"", "-",
        "support_radius (the nodes within R) | authors_patch (NL-PartSol's 4x4 node patch)"),
    key("solver.newmark_gamma", &Scene::newmark_gamma, "0.5", "-",
        "Newmark gamma of the predictor-corrector, in [0, 1]", within(0.0, 1.0)),
    key("solver.fe_position_velocity", &Scene::fe_position_velocity, "\"updated\"", "-",
        "updated | start (literal Eqs. 19-22)"),
    key("solver.npc_position_velocity", &Scene::npc_position_velocity, "\"projected\"", "-",
        "projected (literal Eq. 33, v_I^k) | corrected (the authors' code, v_I^{k+1}) | predicted"),
    key("solver.npc_velocity", &Scene::npc_velocity, "\"eq32\"", "-",
        "eq32 (Eq. 32 as printed: new acceleration only, damped) | average (Eq. 23: Newmark average, undamped)"),
    key("solver.flip_fraction", &Scene::flip_fraction, "1.0", "-",
        "forward Euler's PIC/FLIP blend of the particle velocity: 1 FLIP, 0 PIC",
        within(0.0, 1.0, " (1: FLIP, 0: PIC)")),
    key("solver.stress_update", &Scene::stress_update, "\"usf\"", "-",
        "forward Euler's stress update: usf (first, the paper's) | usl (last) | musl (last, from the particle "
        "velocities projected again); paper/11_stress_update.md"),
    key("solver.kernels", &Scene::kernels, lab_build ? "\"reference\"" : "\"fast\"", "-",
        "fast (threads, component forms: mpm/fast/) | reference (the plain serial kernels of mpm/transfer/, "
        "which the book shows; the same results to round-off); the lab build (make lab) has reference only"),
    key("solver.energy_growth_limit", &RunControl::energy_growth_limit, "10.0", "-",
        "stop (exit 3) when the energy exceeds this times (initial + work of gravity); 0: off",
        at_least(0.0, " (0: no check)")),
  };
}

/// The constants, the fields given by formulas, the observers and the output.
inline std::vector<SceneKey> field_and_output_keys() {
  return {
    custom_key("constants.<name>", optional, "-",
               "a named constant: a number, or a formula of other constants (pi, young_modulus, poisson_ratio and "
               "density are predefined); usable in every formula",
               nullptr, print_constants),
    custom_key("initial_field.velocity", optional, "m/s",
               "initial velocity per axis as formulas (muParser, in quotes) of x, X (y, Y) and the constants; "
               "[[initial_velocity]] boxes win",
               nullptr, print_formulas(&SceneFormulas::initial_velocity, "velocity")),
    custom_key("initial_field.stress", optional, "Pa", "initial stress as formulas: [xx] in 1D, [xx, yy, xy] in 2D",
               nullptr, print_formulas(&SceneFormulas::initial_stress, "stress")),
    custom_key("body_force.acceleration", optional, "m/s^2",
               "body force per unit mass per axis as formulas of x, X (y, Y) and t, added to [gravity]", nullptr,
               print_formulas(&SceneFormulas::body_force, "acceleration")),
    key("observer[].name", &ObserverSettings::name, required, "-",
        "column name in observers.csv (letters, digits, _)"),
    key("observer[].position", &ObserverSettings::position, required, "m",
        "the particle nearest this point at t = 0 is observed (run.json: `observed`); exact.csv holds the exact "
        "solution at that particle's reference position; the point must lie in the body"),
    shown_if(key("output.every", &RunControl::sample_every, "1", "steps",
                 "observers and energy sampled every n steps and at the end", whole(1, 2147483647)),
             every_shown),
    key("output.snapshots", &RunControl::snapshot_times, "[]", "s",
        "times at which every particle is written (CSV, VTK, .pvd); [] writes none"),
    key("output.times", &RunControl::sample_times, "[]", "s",
        "times at which observers, energy and exact.csv are sampled, each landed on by a step; replaces every"),
  };
}

/// The scene's keys, in the order a scene file writes them: the sections' keys one after another. A function's
/// static, built on the first call: a namespace-scope inline table would be initialised (and compiled, ~8 CPU-s at
/// -O3) in every translation unit that includes this header, the run units too, which never read it.
inline const std::vector<SceneKey>& all_keys() {
  static const std::vector<SceneKey> keys = [] {
    std::vector<SceneKey> all;
    for (std::vector<SceneKey> (*section)() : {header_keys, body_keys, loading_keys, solver_keys, field_and_output_keys})
      for (SceneKey& entry : section()) all.push_back(std::move(entry));
    return all;
  }();
  return keys;
}

}  // namespace detail

/// The scene's keys, in the order a scene file writes them.
inline const std::vector<SceneKey>& scene_keys() { return detail::all_keys(); }

TEST_CASE("Scene keys: ranges, integers of any size and choices are refused with the key's own words") {
  auto message_of = [](const std::string& text, const SceneKey& key) {
    SceneFile file = parse_scene_text(text, "k.toml");
    SceneReader reader(file, *file.table["t"].as_table(), "t");
    Scene scene;
    scene.bodies.emplace_back();
    try {
      key.read(reader, key, scene, 0);
    } catch (const SceneError& error) {
      return error.message();
    }
    return std::string("read");
  };
  const SceneKey cfl = key("t.cfl", &RunControl::cfl, "0.5", "-", "", {0.0, 10.0, true, false, ": far"});
  CHECK(message_of("[t]\ncfl = -1\n", cfl) == "error: k.toml:2: t.cfl: must be > 0, got -1.000000");
  CHECK(message_of("[t]\ncfl = 11\n", cfl) == "error: k.toml:2: t.cfl: must be in (0, 10]: far");
  CHECK(message_of("[t]\n", cfl) == "read");
  const SceneKey margin = key("t.margin", &Scene::margin_max, "0", "cells", "", whole(0, 100'000'000));
  CHECK(message_of("[t]\nmargin = [9223372036854775807]\n", margin) ==
        "error: k.toml:2: t.margin: entries must be whole numbers in [0, 100000000], got 9223372036854775807");
  CHECK(message_of("[t]\nmargin = [-9223372036854775808]\n", margin).find("got -9223372036854775808") != std::string::npos);
  CHECK(message_of("[t]\nmargin = [3e9]\n", margin).find("got 3e+09") != std::string::npos);
  const SceneKey times = key("t.times", &RunControl::sample_times, "[]", "s", "");
  Scene scene;
  SceneFile file = parse_scene_text("[t]\ntimes = [9223372036854775807, 1.5]\n", "k.toml");
  SceneReader reader(file, *file.table["t"].as_table(), "t");
  times.read(reader, times, scene, 0);
  CHECK(scene.control.sample_times == std::vector<double>{9223372036854775807.0, 1.5});
  const SceneKey every = key("t.every", &RunControl::sample_every, "1", "steps", "", whole(1, 2147483647));
  CHECK(message_of("[t]\nevery = 9223372036854775807\n", every) ==
        "error: k.toml:2: t.every: must be an integer in [1, 2147483647], got 9223372036854775807");
  const SceneKey shape = key("t.shape", &Scene::shape, "\"linear\"", "-", "");
  CHECK(message_of("[t]\nshape = \"cubic\"\n", shape) ==
        "error: k.toml:2: t.shape: 'cubic' is not allowed; use one of linear | ugimp | lme | bspline2 | bspline3");
  CHECK(key("t.density", &MaterialSettings::density, optional, "kg/m^3", "", positive()).is_optional());
  CHECK(margin.per_axis);
  CHECK(!times.per_axis);
  CHECK(margin.section() == "t");
  CHECK(key("body[].min", &BodySettings::min, required, "m", "").section() == "body");
  CHECK(key("body[].min", &BodySettings::min, required, "m", "").name() == "min");
}

}  // namespace mpm::io
