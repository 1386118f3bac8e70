/// \file
/// The resolved scene: every key of a validated Scene, defaults filled in, as a TOML table. `mpm run
/// --print-scene` prints it (keys in the order of scene_keys(), units as comments); run.json holds it as JSON.
#pragma once
#include <doctest/doctest.h>

#include <charconv>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/io/scene.hpp"
#include "mpm/io/scene_keys.hpp"

namespace mpm::io {

namespace detail {

/// A TOML value as the scenes write it: floats in their shortest round-trip form (1e-06, 0.5, 200000000000.0),
/// strings in double quotes, arrays on one line.
inline std::string toml_text(const toml::node& node) {
  std::string text;
  if (const auto* array = node.as_array()) {
    for (const toml::node& entry : *array) text += (text.empty() ? "" : ", ") + toml_text(entry);
    return "[" + text + "]";
  }
  if (node.is_floating_point()) {
    char buffer[64];
    text.assign(buffer, std::to_chars(buffer, buffer + sizeof buffer, *node.value<double>()).ptr);
    return text.find_first_of(".eni") == std::string::npos ? text + ".0" : text;  // 2e11 is 200000000000.0
  }
  if (!node.is_string()) {
    std::ostringstream out;
    node.visit([&](auto&& value) { out << value; });
    return out.str();
  }
  const std::string value = *node.value<std::string>();
  for (const char character : value) {
    char escaped[8] = {character, '\0'};
    if (character == '"' || character == '\\') std::snprintf(escaped, sizeof escaped, "\\%c", character);
    if (character == '\n') std::snprintf(escaped, sizeof escaped, "\\n");
    else if (static_cast<unsigned char>(character) < 0x20 || character == 0x7f)
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned char>(character));
    text += escaped;
  }
  return "\"" + text + "\"";
}

/// The number of entries of the array of tables `section` ([[body]]) the scene holds.
inline std::size_t entries_of(const Scene& scene, const std::string& section) {
  if (section == "body") return scene.bodies.size();
  if (section == "initial_velocity") return scene.initial_velocities.size();
  return section == "fixed" ? scene.fixed.size() : scene.observers.size();
}

}  // namespace detail

/// Every key of the scene with its value, defaults included, by the table of mpm/io/scene_keys.hpp; an
/// optional table the scene does not give is absent, an array of tables it does not give is empty.
inline toml::table resolved_table(const Scene& scene) {
  toml::table table;
  for (const SceneKey& key : scene_keys()) {
    const std::string section = key.section();
    if (section.empty()) {
      key.print(scene, 0, table);
    } else if (!key.in_array()) {
      toml::table values;
      key.print(scene, 0, values);
      if (values.empty()) continue;  // an optional key not given
      toml::table& entry = *table.insert(section, toml::table{}).first->second.as_table();
      entry.insert(values.begin(), values.end());
    } else {
      toml::array& entries = *table.insert(section, toml::array{}).first->second.as_array();
      for (std::size_t k = 0; k < detail::entries_of(scene, section); ++k) {
        if (entries.size() <= k) entries.push_back(toml::table{});
        key.print(scene, k, *entries.get(k)->as_table());
      }
    }
  }
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
  auto print_keys = [&](const std::string& section, const toml::table& values) {  // the section's keys, in order
    for (const SceneKey& key : scene_keys()) {
      if (key.section() != section) continue;
      for (const auto& [name, value] : values) {
        if (name.str() != key.name() && key.name() != "<name>") continue;  // constants.<name>: every entry
        std::string line = std::string(name.str()) + " = " + detail::toml_text(value);
        const int padding = std::max(1, 40 - static_cast<int>(line.size()));  // units from column 41
        if (std::string(key.unit) != "-") line += std::string(padding, ' ') + "# " + key.unit;
        out << line << "\n";
      }
    }
  };
  print_keys("", table);
  std::vector<std::string> sections;  // in order of first appearance
  for (const SceneKey& key : scene_keys()) {
    const std::string section = key.section();
    if (section.empty() || !table.contains(section) || (!sections.empty() && sections.back() == section)) continue;
    sections.push_back(section);
    if (const toml::array* array = table.get(section)->as_array()) {
      for (const toml::node& entry : *array) {
        out << "\n[[" << section << "]]\n";
        print_keys(section, *entry.as_table());
      }
    } else {
      out << "\n[" << section << "]\n";
      print_keys(section, *table.get(section)->as_table());
    }
  }
}

TEST_CASE("Scene keys: the resolved scene holds every key but the optional ones, a required key is refused by name") {
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
  auto holder_of = [](toml::table& table, const SceneKey& key) -> toml::table* {
    if (key.section().empty()) return &table;
    toml::node* holder = table.get(key.section());
    if (holder && holder->is_array()) holder = holder->as_array()->empty() ? nullptr : holder->as_array()->get(0);
    return holder ? holder->as_table() : nullptr;
  };
  for (const std::string& minimal : {minimal_1d, minimal_2d}) {
    const Scene scene = read_scene(parse_scene_text(minimal, "m.toml"));
    toml::table resolved = resolved_table(scene);
    const toml::table file = toml::parse(minimal);
    for (const auto& key : scene_keys()) {
      CAPTURE(key.key);
      toml::table* holder = holder_of(resolved, key);
      const bool present = holder && holder->contains(key.name());
      CHECK(present == !key.is_optional());  // optional keys are absent unless given; the minimal scene gives none
      if (key.fallback) continue;
      toml::table without = file;  // a required key: the scene without it is refused, naming it
      REQUIRE(holder_of(without, key));
      holder_of(without, key)->erase(key.name());
      std::ostringstream text;
      text << without;
      std::string message = "no error";
      try {
        read_scene(parse_scene_text(text.str(), "m.toml"));
      } catch (const SceneError& error) {
        message = error.message();
      }
      std::string full = key.key;
      if (key.in_array()) full.replace(full.find("[]"), 2, "[0]");
      CHECK_MESSAGE(message.find(" " + full + ": missing") != std::string::npos, message);
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
