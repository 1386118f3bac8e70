/// \file
/// The resolved scene: every key of a validated Scene, defaults filled in, as a TOML table.
/// `mpm run --print-scene` prints it (in the order of mpm/io/scene_keys.hpp, units as comments) and
/// run.json carries it as JSON, so a run says exactly what it ran. Its doctest holds the key table
/// of scene_keys.hpp to the parser of scene.hpp.
#pragma once
#include <doctest/doctest.h>

#include <charconv>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/io/scene.hpp"
#include "mpm/io/scene_keys.hpp"

namespace mpm::io {

namespace detail {

inline toml::array numbers_array(const std::vector<double>& values) {
  toml::array array;
  for (double value : values) array.push_back(value);
  return array;
}

inline toml::array integers_array(const std::vector<int>& values) {
  toml::array array;
  for (int value : values) array.push_back(static_cast<int64_t>(value));
  return array;
}

inline toml::array axis_names(const std::vector<int>& components) {
  toml::array array;
  for (int component : components) array.push_back(component == 0 ? "x" : "y");
  return array;
}

/// A TOML value as text: floats in their shortest round-trip form (1e-06, 0.5, 200000000000.0).
inline std::string toml_text(const toml::node& node) {
  if (const auto* array = node.as_array()) {
    std::string text = "[";
    for (size_t k = 0; k < array->size(); ++k) text += (k ? ", " : "") + toml_text(*array->get(k));
    return text + "]";
  }
  if (node.is_floating_point()) {
    char buffer[64];
    const double value = *node.value<double>();
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    std::string text(buffer, end);
    if (text.find_first_of(".eni") == std::string::npos) text += ".0";  // 200000000000 -> 200000000000.0
    return text;
  }
  if (node.is_string()) {  // a basic string, as the scenes write them
    std::string text = "\"";
    const std::string value = *node.value<std::string>();
    for (char character : value) {
      if (character == '"' || character == '\\') text += std::string("\\") + character;
      else if (character == '\n') text += "\\n";
      else if (static_cast<unsigned char>(character) < 0x20 || character == 0x7f) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned char>(character));
        text += escaped;
      } else text += character;
    }
    return text + "\"";
  }
  std::ostringstream out;
  node.visit([&](auto&& value) { out << value; });
  return out.str();
}

}  // namespace detail

/// Every key of the scene with its value, defaults included (the names of mpm/io/scene_keys.hpp).
inline toml::table resolved_table(const Scene& scene) {
  using detail::axis_names;
  using detail::integers_array;
  using detail::numbers_array;
  toml::table table;
  table.insert("title", scene.title);
  table.insert("dimension", static_cast<int64_t>(scene.dimension));
  table.insert("exact", scene.exact);
  toml::table exact_parameters{{"mode", static_cast<int64_t>(scene.exact_mode)}};
  if (scene.exact_velocity_amplitude) exact_parameters.insert("velocity_amplitude", *scene.exact_velocity_amplitude);
  if (!scene.exact_displacement_amplitude.empty())
    exact_parameters.insert("displacement_amplitude", numbers_array(scene.exact_displacement_amplitude));
  table.insert("exact_parameters", exact_parameters);
  table.insert("grid", toml::table{{"origin", numbers_array(scene.origin)},
                                   {"length", numbers_array(scene.length)},
                                   {"cells", integers_array(scene.cells)},
                                   {"margin_min", integers_array(scene.margin_min)},
                                   {"margin_max", integers_array(scene.margin_max)}});
  table.insert("material", toml::table{{"young_modulus", scene.young_modulus},
                                       {"poisson_ratio", scene.poisson_ratio},
                                       {"density", scene.density}});
  toml::array bodies, velocities, fixed, observers;
  for (const auto& body : scene.bodies) {
    toml::table entry{{"min", numbers_array(body.min)},
                      {"max", numbers_array(body.max)},
                      {"particles_per_cell", integers_array(body.particles_per_cell)},
                      {"velocity", numbers_array(body.velocity)},
                      {"placement", body.placement},
                      {"shape", body.shape}};
    if (!(body.material == MaterialSettings{scene.young_modulus, scene.poisson_ratio, scene.density})) {  // a material of its own
      entry.insert("young_modulus", body.material.young_modulus);
      entry.insert("poisson_ratio", body.material.poisson_ratio);
      entry.insert("density", body.material.density);
    }
    if (!body.file.empty()) entry.insert("file", body.file);
    if (!body.vertices.empty()) {
      toml::array vertices;
      for (const auto& vertex : body.vertices) vertices.push_back(toml::array{vertex[0], vertex[1]});
      entry.insert("vertices", vertices);
    }
    bodies.push_back(entry);
  }
  for (const auto& box : scene.initial_velocities)
    velocities.push_back(toml::table{{"min", numbers_array(box.min)},
                                     {"max", numbers_array(box.max)},
                                     {"velocity", numbers_array(box.velocity)}});
  for (const auto& face : scene.fixed)
    fixed.push_back(toml::table{{"face", std::string(face.axis == 0 ? "x" : "y") + (face.upper ? "max" : "min")},
                                {"components", axis_names(face.components)}});
  for (const auto& observer : scene.observers)
    observers.push_back(toml::table{{"name", observer.name}, {"position", numbers_array(observer.position)}});
  table.insert("body", bodies);
  table.insert("initial_velocity", velocities);
  table.insert("fixed", fixed);
  table.insert("gravity", toml::table{{"acceleration", numbers_array(scene.gravity)},
                                      {"ramp_period", scene.ramp_period},
                                      {"evaluate_at", scene.control.body_force_time == BodyForceTime::step_end
                                                          ? "step_end" : "step_start"}});
  const RunControl& control = scene.control;
  table.insert("solver", toml::table{{"shape", scene.shape},
                                     {"integrator", scene.integrator},
                                     {"cfl", control.cfl},
                                     {"courant", control.courant == CourantSpeed::maximum ? "max" : "sum"},
                                     {"end_time", control.end_time},
                                     {"lme_gamma", scene.lme_gamma},
                                     {"lme_tol", scene.lme_tol},
                                     {"lme_newton_tol", scene.lme_newton_tol},
                                     {"lme_max_iterations", static_cast<int64_t>(scene.lme_max_iterations)},
                                     {"lme_beta", scene.lme_beta},
                                     {"newmark_gamma", scene.newmark_gamma},
                                     {"fe_position_velocity", scene.fe_position_velocity},
                                     {"npc_position_velocity", scene.npc_position_velocity},
                                     {"npc_velocity", scene.npc_velocity},
                                     {"flip_fraction", scene.flip_fraction},
                                     {"stress_update", scene.stress_update},
                                     {"energy_growth_limit", control.energy_growth_limit}});
  // The optional formula tables (mpm/io/scene_formulas.hpp), only when the scene gives them.
  const SceneFormulas& formulas = scene.formulas;
  toml::table constants;
  for (const auto& [name, value] : formulas.constants)
    if (name != "young_modulus" && name != "poisson_ratio" && name != "density") constants.insert(name, value);
  if (!constants.empty()) table.insert("constants", constants);
  auto texts = [](const FormulaList& list) {
    toml::array array;
    for (const auto& component : list.components) array.push_back(component.text());
    return array;
  };
  toml::table initial_field;
  if (formulas.initial_velocity) initial_field.insert("velocity", texts(*formulas.initial_velocity));
  if (formulas.initial_stress) initial_field.insert("stress", texts(*formulas.initial_stress));
  if (!initial_field.empty()) table.insert("initial_field", initial_field);
  if (formulas.body_force) table.insert("body_force", toml::table{{"acceleration", texts(*formulas.body_force)}});
  table.insert("observer", observers);
  toml::table output{{"snapshots", numbers_array(control.snapshot_times)}, {"times", numbers_array(control.sample_times)}};
  if (control.sample_times.empty()) output.insert("every", static_cast<int64_t>(control.sample_every));  // times replaces every
  table.insert("output", output);
  return table;
}

/// The resolved scene as JSON (for run.json).
inline std::string resolved_json(const Scene& scene) {
  std::ostringstream json;
  json << toml::json_formatter{resolved_table(scene)};
  return json.str();
}

/// The resolved scene as a TOML scene file, keys in the order of scene_keys(), units as comments.
/// Reading it back gives the same scene.
inline void print_resolved_scene(const Scene& scene, std::ostream& out) {
  const toml::table table = resolved_table(scene);
  out << "# " << scene.file << " resolved: every key, defaults filled in (mpm run --print-scene)\n";
  auto print_line = [&](const SceneKey& key, const std::string& name, const toml::node& value) {
    std::string line = name + " = " + detail::toml_text(value);
    if (std::string(key.unit) != "-") line += std::string(line.size() < 40 ? 40 - line.size() : 1, ' ') + "# " + key.unit;
    out << line << "\n";
  };
  auto print_key = [&](const SceneKey& key, const toml::table& section) {
    if (key_name(key.key) == any_name) {  // a table of free names: every entry
      for (const auto& [name, value] : section) print_line(key, std::string(name.str()), value);
      return;
    }
    if (const toml::node* value = section.get(key_name(key.key))) print_line(key, key_name(key.key), *value);
  };
  std::vector<std::string> sections;  // in order of first appearance
  for (const auto& key : scene_keys()) {
    const std::string section = key_section(key.key);
    if (section.empty()) print_key(key, table);
    else if (std::find(sections.begin(), sections.end(), section) == sections.end()) sections.push_back(section);
  }
  for (const auto& section : sections) {
    if (!table.contains(section)) continue;  // an optional table the scene does not give
    auto print_section = [&](const toml::table& values) {
      for (const auto& key : scene_keys())
        if (key_section(key.key) == section) print_key(key, values);
    };
    if (const auto* array = table.get(section)->as_array()) {
      for (const auto& entry : *array) {
        out << "\n[[" << section << "]]\n";
        print_section(*entry.as_table());
      }
    } else {
      out << "\n[" << section << "]\n";
      print_section(*table.get(section)->as_table());
    }
  }
}

namespace detail {

/// Numbers compare by value (1 == 1.0), strings by text, arrays entry by entry.
inline bool same_value(const toml::node& a, const toml::node& b) {
  if (a.is_array() && b.is_array()) {
    const auto &x = *a.as_array(), &y = *b.as_array();
    if (x.size() != y.size()) return false;
    for (size_t k = 0; k < x.size(); ++k)
      if (!same_value(*x.get(k), *y.get(k))) return false;
    return true;
  }
  if (a.is_number() && b.is_number()) return *a.value<double>() == *b.value<double>();
  if (a.is_string() && b.is_string()) return *a.value<std::string>() == *b.value<std::string>();
  return false;
}

}  // namespace detail

TEST_CASE("Scene keys: the help table lists exactly the keys the parser accepts, its defaults and its required keys") {
  // Only the required keys, one table of each array of tables: every other key takes its default.
  const std::string minimal_1d =
      "[grid]\nlength = [1.0]\ncells = [10]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [1.0]\n[[initial_velocity]]\nmin = [0.0]\nmax = [0.5]\nvelocity = [1.0]\n"
      "[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n[solver]\nend_time = 1.0\n"
      "[[observer]]\nname = \"A\"\nposition = [0.0]\n";
  const std::string minimal_2d =
      "dimension = 2\n[grid]\nlength = [1.0, 1.0]\ncells = [10, 10]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[[initial_velocity]]\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\nvelocity = [1.0, 0.0]\n"
      "[[fixed]]\nface = \"ymin\"\ncomponents = [\"y\"]\n[solver]\nend_time = 1.0\n"
      "[[observer]]\nname = \"A\"\nposition = [0.0, 0.0]\n";
  // the node of `key` ("body[].min": of the first [[body]]) in a table of the resolved layout
  auto node_of = [](const toml::table& table, const SceneKey& key) -> const toml::node* {
    const std::string section = key_section(key.key);
    if (section.empty()) return table.get(key.key);
    const toml::node* holder = table.get(section);
    if (!holder) return nullptr;
    if (const auto* array = holder->as_array()) holder = array->empty() ? nullptr : array->get(0);
    return holder && holder->is_table() ? holder->as_table()->get(key_name(key.key)) : nullptr;
  };
  for (const std::string& minimal : {minimal_1d, minimal_2d}) {
    const Scene scene = read_scene(parse_scene_text(minimal, "m.toml"));
    const toml::table resolved = resolved_table(scene);
    const toml::table file = toml::parse(minimal);
    for (const auto& key : scene_keys()) {
      const std::string name = key.key;
      CAPTURE(name);
      const toml::node* value = node_of(resolved, key);
      if (key.optional) {  // absent unless given: the minimal scene gives none, and reads without it
        CHECK(value == nullptr);
        continue;
      }
      REQUIRE(value != nullptr);  // every key of the table is in the resolved scene
      if (key.fallback) {
        if (node_of(file, key)) continue;  // `dimension = 2` of the 2D scene; 1D leaves it to its default
        toml::table parsed = toml::parse("value = " + std::string(key.fallback));
        toml::array per_axis;
        for (int axis = 0; axis < scene.dimension; ++axis) per_axis.push_back(*parsed.get("value"));
        const toml::node& expected = key.per_axis ? static_cast<const toml::node&>(per_axis) : *parsed.get("value");
        CHECK_MESSAGE(detail::same_value(*value, expected), "parser default " << detail::toml_text(*value));
      } else {  // required: the scene without it is refused, naming it
        if (!node_of(file, key)) {
          FAIL_CHECK("required in the table, yet the scene without it was read: the parser has a default");
          continue;
        }
        toml::table without = file;
        const std::string section = key_section(key.key);
        toml::table* holder = &without;
        if (!section.empty()) {
          toml::node* node = without.get(section);
          holder = node->is_array() ? node->as_array()->get(0)->as_table() : node->as_table();
        }
        holder->erase(key_name(key.key));
        std::ostringstream text;
        text << without;
        std::string message = "no error";
        try {
          read_scene(parse_scene_text(text.str(), "m.toml"));
        } catch (const SceneError& error) {
          message = error.message();
        }
        std::string full = key.key;
        if (key_in_array(full)) full.replace(full.find("[]"), 2, "[0]");
        CHECK_MESSAGE(message.find(" " + full + ": ") != std::string::npos, message);
      }
    }
    // Every key of the resolved scene is in the table (nothing resolved that help does not list).
    std::set<std::string> listed;
    for (const auto& key : scene_keys()) listed.insert(key.key);
    for (const auto& [name, node] : resolved) {
      if (const auto* array = node.as_array()) {
        for (const auto& entry : *array)
          for (const auto& [inner, value] : *entry.as_table()) CHECK(listed.count(std::string(name.str()) + "[]." + std::string(inner.str())));
      } else if (const auto* table = node.as_table()) {
        for (const auto& [inner, value] : *table)
          CHECK((listed.count(std::string(name.str()) + "." + std::string(inner.str())) ||
                 listed.count(std::string(name.str()) + "." + any_name)));
      } else {
        CHECK(listed.count(std::string(name.str())));
      }
    }
    // The parser accepts no other key: an unknown key in each table is refused with the list of the
    // keys it allows, which must be the table's.
    std::map<std::string, std::set<std::string>> allowed_by_table;  // section -> names
    for (const auto& key : scene_keys()) {
      allowed_by_table[key_section(key.key)].insert(key_name(key.key));
      if (!key_section(key.key).empty()) allowed_by_table[""].insert(key_section(key.key));
    }
    for (const auto& [section, names] : allowed_by_table) {
      CAPTURE(section);
      if (names.count(any_name)) continue;  // a table of free names accepts any name
      toml::table with_unknown = file;
      toml::table* holder = &with_unknown;
      if (!section.empty()) {
        if (!with_unknown.contains(section)) with_unknown.insert(section, toml::table{});
        toml::node* node = with_unknown.get(section);
        holder = node->is_array() ? node->as_array()->get(0)->as_table() : node->as_table();
      }
      holder->insert("zz_not_a_key", 1);
      std::ostringstream text;
      text << with_unknown;
      std::string message;
      try {
        read_scene(parse_scene_text(text.str(), "m.toml"));
      } catch (const SceneError& error) {
        message = error.message();
      }
      const std::string marker = "allowed here: ";
      REQUIRE_MESSAGE(message.find(marker) != std::string::npos, message);
      std::set<std::string> allowed;
      std::stringstream list(message.substr(message.find(marker) + marker.size()));
      for (std::string word; list >> word;)
        if (word != "|") allowed.insert(word);
      CHECK(allowed == names);
    }
    // Printed and read back, the resolved scene is the same scene.
    std::ostringstream printed;
    print_resolved_scene(scene, printed);
    CHECK(resolved_table(read_scene(parse_scene_text(printed.str(), "printed.toml"))) == resolved);
  }
}

TEST_CASE("Scene keys: the formula tables are printed as given and read back to the same scene") {
  const std::string scene_text =
      "[constants]\nlength_of_bar = 2.0\nspeed = 'sqrt(young_modulus / density)'\n"
      "[grid]\nlength = [2.0]\ncells = [4]\n[material]\nyoung_modulus = 4.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [2.0]\n[solver]\nend_time = 1e-4\n"
      "[initial_field]\nvelocity = ['1e-3 * cos(pi * X / (2 * length_of_bar))']\nstress = ['0']\n"
      "[body_force]\nacceleration = ['speed * t']\n";
  const Scene scene = read_scene(parse_scene_text(scene_text, "formulas.toml"));
  const toml::table resolved = resolved_table(scene);
  CHECK(*resolved["constants"]["speed"].value<double>() == 2.0);  // sqrt(4 / 1), resolved to a number
  CHECK(resolved["constants"]["young_modulus"].node() == nullptr);  // predefined, not printed
  CHECK(*resolved["initial_field"]["velocity"][0].value<std::string>() == "1e-3 * cos(pi * X / (2 * length_of_bar))");
  CHECK(*resolved["body_force"]["acceleration"][0].value<std::string>() == "speed * t");
  std::ostringstream printed;
  print_resolved_scene(scene, printed);
  CHECK(printed.str().find("[initial_field]") != std::string::npos);
  CHECK(resolved_table(read_scene(parse_scene_text(printed.str(), "printed.toml"))) == resolved);
}

TEST_CASE("Scene keys: the printed scene is a readable scene file, in the table's order, with units") {
  const std::string scene_text =
      "title = \"bar \\\"one\\\" \\\\two\"\n[grid]\nlength = [2.0]\ncells = [4]\n[material]\nyoung_modulus = 200e9\ndensity = 7833\n"
      "[[body]]\nmin = [0.0]\nmax = [2.0]\n[solver]\nend_time = 1e-4\nlme_tol = 1e-6\n";
  std::ostringstream printed;
  print_resolved_scene(read_scene(parse_scene_text(scene_text, "bar.toml")), printed);
  const std::string text = printed.str();
  CHECK(text.find("title = \"bar \\\"one\\\" \\\\two\"\ndimension = 1\nexact = \"none\"\n") != std::string::npos);
  CHECK(read_scene(parse_scene_text(text, "printed.toml")).title == "bar \"one\" \\two");
  CHECK(text.find("\n[grid]\norigin = [0.0]") != std::string::npos);
  CHECK(text.find("young_modulus = 2e+11 ") != std::string::npos);
  CHECK(text.find("end_time = 1e-04") != std::string::npos);
  CHECK(text.find("lme_tol = 1e-06") != std::string::npos);
  CHECK(text.find("placement = \"uniform\"") != std::string::npos);
  CHECK(text.find("cfl = 0.5\n") != std::string::npos);  // no unit comment for a dimensionless key
  CHECK(text.find("# kg/m^3") != std::string::npos);
  CHECK(text.find("[[observer]]") == std::string::npos);  // none in the scene, none printed
  CHECK(text.find("\n[output]\nevery = 1 ") != std::string::npos);
  CHECK(text.find("\nsnapshots = []  ") != std::string::npos);
}

}  // namespace mpm::io
