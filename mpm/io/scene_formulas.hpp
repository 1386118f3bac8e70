/// \file
/// Smooth data in scenes: an initial velocity and stress given as formulas of position, a body
/// force as a formula of position and time, compiled by muParser; and named constants.
///
///     [constants]          # usable in every formula; a value is a number or a formula of other constants
///     L = 1.0
///     V = "1e-6 * L * omega"
///     [initial_field]      # formulas of the position at t = 0: x, X (and y, Y in 2D)
///     velocity = ["V * cos(pi * X / (2 * L))"]          # one per axis
///     stress = ["0"]                                    # 1D: xx; 2D: xx, yy, xy
///     [body_force]         # per unit mass, added to [gravity]: formulas of x, X (y, Y) and t
///     acceleration = ["0"]                              # one per axis
///
/// x, y name the current position of a particle, X, Y its position at t = 0, t the time. Every
/// formula also knows pi and the material's young_modulus, poisson_ratio and density. A formula
/// that does not compile, names an unknown variable, or gives a non-finite value at a particle at
/// seeding is a scene error (`error: FILE:LINE: KEY: ...`, exit 2).
#pragma once
#include <doctest/doctest.h>
#include <muParser.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/io/scene_file.hpp"
#include "mpm/loading/body_force.hpp"
#include "mpm/loading/initial_fields.hpp"

namespace mpm::io {

/// Names a formula may use besides the scene's constants.
struct FormulaVariables {
  int dimension = 1;
  bool time = false;  ///< t is known (body force only)

  std::vector<std::string> names() const {
    std::vector<std::string> list;
    if (dimension >= 1) list.push_back("x");
    if (dimension == 2) list.push_back("y");
    if (dimension >= 1) list.push_back("X");
    if (dimension == 2) list.push_back("Y");
    if (time) list.push_back("t");
    return list;
  }
};

/// One formula, compiled by muParser with the variables x, y, X, Y, t and the given constants.
/// A copy compiles its own parser (muParser binds variables by address), so copies may be
/// evaluated independently, e.g. by simulations on different threads.
/// \throws mu::Parser::exception_type from the constructor when the formula does not compile.
class Formula {
 public:
  Formula(std::string text, std::map<std::string, double> constants, FormulaVariables variables)
      : text_(std::move(text)), constants_(std::move(constants)), variables_(variables), compiled_(compile()) {}
  Formula(const Formula& other) : Formula(other.text_, other.constants_, other.variables_) {}
  Formula& operator=(const Formula& other) {
    if (this != &other) *this = Formula(other);
    return *this;
  }
  Formula(Formula&&) = default;
  Formula& operator=(Formula&&) = default;

  /// The value at current position x, reference position X and time t (entries past the dimension ignored).
  double operator()(const double* position, const double* reference_position, double time) const {
    Compiled& state = *compiled_;
    for (int axis = 0; axis < variables_.dimension; ++axis) {
      state.position[axis] = position[axis];
      state.reference_position[axis] = reference_position[axis];
    }
    state.time = time;
    return state.parser.Eval();
  }

  const std::string& text() const { return text_; }

 private:
  struct Compiled {
    double position[2] = {0.0, 0.0}, reference_position[2] = {0.0, 0.0}, time = 0.0;
    mu::Parser parser;
  };

  std::unique_ptr<Compiled> compile() const {
    auto state = std::make_unique<Compiled>();
    mu::Parser& parser = state->parser;
    parser.DefineConst("pi", 3.14159265358979323846);
    for (const auto& [name, value] : constants_) parser.DefineConst(name, value);
    const char* axes[2][2] = {{"x", "X"}, {"y", "Y"}};
    for (int axis = 0; axis < variables_.dimension; ++axis) {
      parser.DefineVar(axes[axis][0], &state->position[axis]);
      parser.DefineVar(axes[axis][1], &state->reference_position[axis]);
    }
    if (variables_.time) parser.DefineVar("t", &state->time);
    parser.SetExpr(text_);
    int results = 0;
    parser.Eval(results);  // muParser parses on the first evaluation: syntax errors surface here
    if (results != 1) throw mu::Parser::exception_type("a formula gives one value; this one gives " + std::to_string(results));
    return state;
  }

  std::string text_;
  std::map<std::string, double> constants_;
  FormulaVariables variables_;
  std::unique_ptr<Compiled> compiled_;
};

/// Where a formula was written, for errors found when it is evaluated at the particles.
struct FormulaSource {
  std::string file;
  int line = 0;
  std::string key;
};

/// The formulas of one vector or tensor key, one per component.
struct FormulaList {
  std::vector<Formula> components;
  FormulaSource source;

  /// Every component at a particle. \throws SceneError naming the key when one is not finite.
  std::vector<double> at(const double* position, const double* reference_position, double time, int particle_id,
                         int dimension) const {
    std::vector<double> values;
    for (size_t k = 0; k < components.size(); ++k) {
      values.push_back(components[k](position, reference_position, time));
      if (!std::isfinite(values.back())) {
        std::ostringstream what;
        what.precision(9);
        what << "'" << components[k].text() << "' is " << values.back() << " at particle " << particle_id << " (X = "
             << reference_position[0];
        if (dimension == 2) what << ", Y = " << reference_position[1];
        what << ") at t = " << time << "; a formula must be finite at every particle";
        throw SceneError(source.file, source.line, source.key, what.str());
      }
    }
    return values;
  }
};

/// What [constants], [initial_field] and [body_force] say.
struct SceneFormulas {
  std::map<std::string, double> constants;  ///< the scene's [constants], resolved to numbers
  std::optional<FormulaList> initial_velocity, initial_stress, body_force;
};

namespace detail {

inline bool is_name(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  for (char character : name)
    if (!(std::isalnum(static_cast<unsigned char>(character)) || character == '_')) return false;
  return true;
}

/// Names a constant may not take: the variables, pi and muParser's functions.
inline bool is_reserved(const std::string& name) {
  static const std::vector<std::string> reserved{
      "x", "y", "X", "Y", "t", "pi", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh",
      "acosh", "atanh", "log2", "log10", "log", "ln", "exp", "sqrt", "sign", "rint", "abs", "min", "max", "sum", "avg"};
  return std::find(reserved.begin(), reserved.end(), name) != reserved.end();
}

inline std::string known_names(const std::map<std::string, double>& constants, const FormulaVariables& variables) {
  std::string list;
  for (const auto& name : variables.names()) list += name + ", ";
  list += "pi";
  for (const auto& [name, value] : constants) list += ", " + name;
  return list;
}

/// muParser's complaint, made to name what is known when the formula uses an unknown name.
inline std::string formula_problem(const mu::Parser::exception_type& error, const std::string& text,
                                   const std::map<std::string, double>& constants, const FormulaVariables& variables) {
  std::string what = "'" + text + "': " + error.GetMsg();
  if (error.GetCode() == mu::ecUNASSIGNABLE_TOKEN)
    what += " (unknown name; known here: " + known_names(constants, variables) + ")";
  return what;
}

inline FormulaSource source_of(const SceneFile& file, const toml::table& table, const std::string& prefix, const std::string& key) {
  const std::string full = prefix + "." + key;
  if (auto override = file.overridden.find(full); override != file.overridden.end()) return {override->second, 1, full};
  const toml::node* node = table.get(key);
  return {file.path, node ? line_of(*node) : line_of(table), full};
}

/// Reads `key` of `reader`'s table: an array of `size` formulas (strings) or numbers.
inline std::optional<FormulaList> read_formula_list(const SceneFile& file, const toml::table& table, SceneReader& reader,
                                                    const std::string& prefix, const std::string& key, int size,
                                                    const std::string& size_text, const std::map<std::string, double>& constants,
                                                    FormulaVariables variables) {
  if (!reader.has(key)) return std::nullopt;
  const toml::array* array = table.get(key)->as_array();
  if (!array) reader.fail(key, "must be an array of formulas in quotes, e.g. [\"sin(pi * x)\"]");
  if (static_cast<int>(array->size()) != size)
    reader.fail(key, "has " + std::to_string(array->size()) + " entries; needs " + std::to_string(size) + " (" + size_text + ")");
  FormulaList list;
  list.source = source_of(file, table, prefix, key);
  for (const auto& entry : *array) {
    std::string text;
    if (entry.is_string()) {
      text = *entry.value<std::string>();
    } else if (entry.is_floating_point() || entry.is_integer()) {
      std::ostringstream number;
      number.precision(17);
      number << *entry.value<double>();
      text = number.str();
    } else {
      reader.fail(key, "entries must be formulas in quotes or numbers");
    }
    try {
      list.components.emplace_back(text, constants, variables);
    } catch (const mu::Parser::exception_type& error) {
      reader.fail(key, formula_problem(error, text, constants, variables));
    }
  }
  return list;
}

/// [constants]: numbers, or formulas of other constants, resolved in whatever order they allow.
inline std::map<std::string, double> read_constants(const SceneFile& file, SceneReader& root, std::map<std::string, double> known) {
  if (!root.has("constants")) return known;
  const toml::table* table = file.table["constants"].as_table();
  if (!table) root.fail("constants", "must be a table: write [constants]");
  SceneReader reader(file, *table, "constants");
  std::map<std::string, std::string> pending;
  for (const auto& [key, node] : *table) {
    const std::string name(key.str());
    reader.has(name);
    if (!is_name(name)) reader.fail(name, "a constant's name is letters, digits and _, starting with a letter or _");
    if (is_reserved(name) || known.count(name)) reader.fail(name, "'" + name + "' is a variable, function or predefined constant; choose another name");
    if (node.is_floating_point() || node.is_integer()) {
      known[name] = *node.value<double>();
      if (!std::isfinite(known[name])) reader.fail(name, "must be finite");
    } else if (node.is_string()) {
      pending[name] = *node.value<std::string>();
    } else {
      reader.fail(name, "must be a number or a formula in quotes");
    }
  }
  const FormulaVariables none{0, false};
  while (!pending.empty()) {  // each pass resolves every constant whose constants are known
    bool progress = false;
    for (auto entry = pending.begin(); entry != pending.end();) {
      try {
        const double value = Formula(entry->second, known, none)(nullptr, nullptr, 0.0);
        if (!std::isfinite(value)) reader.fail(entry->first, "'" + entry->second + "' is not finite");
        known[entry->first] = value;
        entry = pending.erase(entry);
        progress = true;
      } catch (const mu::Parser::exception_type&) {
        ++entry;
      }
    }
    if (!progress) {  // what is left does not compile, names an unknown constant, or is a cycle
      for (int pass = 0; pass < 2; ++pass)  // first a constant whose problem is not another pending constant
        for (const auto& [name, text] : pending) {
          try {
            Formula(text, known, none);
          } catch (const mu::Parser::exception_type& error) {
            if (pass == 0 && pending.count(error.GetToken())) continue;
            reader.fail(name, pass == 0 ? formula_problem(error, text, known, none)
                                        : "'" + text + "': the constants refer to each other in a cycle");
          }
        }
    }
  }
  return known;
}

}  // namespace detail

/// Reads [constants], [initial_field] and [body_force]. The material's young_modulus,
/// poisson_ratio and density are predefined constants. \throws SceneError at the first problem.
inline SceneFormulas read_scene_formulas(const SceneFile& file, SceneReader& root, int dimension, double young_modulus,
                                         double poisson_ratio, double density) {
  SceneFormulas formulas;
  formulas.constants = detail::read_constants(
      file, root, {{"young_modulus", young_modulus}, {"poisson_ratio", poisson_ratio}, {"density", density}});
  const std::string axes = dimension == 1 ? "x" : "x, y";
  const std::string stress_components = dimension == 1 ? "xx" : "xx, yy, xy";
  const int stress_size = dimension == 1 ? 1 : 3;
  for (const std::string name : {"initial_field", "body_force"}) {
    if (!root.has(name)) continue;
    const toml::table* table = file.table[name].as_table();
    if (!table) root.fail(name, "must be a table: write [" + name + "]");
    SceneReader reader(file, *table, name);
    if (name == "initial_field") {
      const FormulaVariables variables{dimension, false};
      formulas.initial_velocity = detail::read_formula_list(file, *table, reader, name, "velocity", dimension, axes, formulas.constants, variables);
      formulas.initial_stress = detail::read_formula_list(file, *table, reader, name, "stress", stress_size, stress_components,
                                                          formulas.constants, variables);
    } else {
      formulas.body_force = detail::read_formula_list(file, *table, reader, name, "acceleration", dimension, axes, formulas.constants,
                                                      FormulaVariables{dimension, true});
    }
    reader.reject_unknown_keys();
  }
  return formulas;
}

/// The [body_force] formulas as the field b(x, X, t) of Model; empty without them.
template <int Dim>
BodyForceField<Dim> body_force_field(const SceneFormulas& formulas) {
  if (!formulas.body_force) return {};
  return [list = *formulas.body_force](const Vector<Dim>& x, const Vector<Dim>& reference, double time) {
    Vector<Dim> b;
    for (int axis = 0; axis < Dim; ++axis) b[axis] = list.components[axis](x.data(), reference.data(), time);
    return b;
  };
}

/// Sets the [initial_field] velocity and stress of every particle, and checks that the
/// [body_force] is finite at every particle at t = 0 and at the end time.
/// \throws SceneError naming the key of a formula that is not finite at a particle.
template <int Dim>
void apply_scene_formulas(const SceneFormulas& formulas, const std::vector<LinearElastic>& materials, double end_time, Particles<Dim>& particles) {
  auto at = [&](const FormulaList& list, int p, double time) {
    return list.at(particles.position[p].data(), particles.reference_position[p].data(), time, particles.id[p], Dim);
  };
  if (formulas.initial_velocity)
    for (int p = 0; p < particles.size(); ++p) particles.velocity[p] = Eigen::Map<const Vector<Dim>>(at(*formulas.initial_velocity, p, 0.0).data());
  if (formulas.initial_stress) {
    std::vector<Matrix<Dim>> stress(particles.size());
    for (int p = 0; p < particles.size(); ++p) {
      const std::vector<double> value = at(*formulas.initial_stress, p, 0.0);
      if constexpr (Dim == 1) stress[p](0, 0) = value[0];
      else stress[p] << value[0], value[2], value[2], value[1];
    }
    int next = 0;  // set_initial_stress visits the particles in order
    set_initial_stress<Dim>([&](const Vector<Dim>&) { return stress[next++]; }, materials, particles);
  }
  if (formulas.body_force)
    for (int p = 0; p < particles.size(); ++p) at(*formulas.body_force, p, 0.0), at(*formulas.body_force, p, end_time);
}

TEST_CASE("Scene formulas: constants, a formula against a hand value, each bad formula names its key and line") {
  const std::string head = "[material]\nyoung_modulus = 200e9\ndensity = 8000.0\n";
  auto read = [&](const std::string& text, int dimension = 1) {
    const SceneFile file = parse_scene_text(head + text, "f.toml");
    SceneReader root(file, file.table, "");
    return read_scene_formulas(file, root, dimension, 200e9, 0.0, 8000.0);
  };
  auto message_of = [&](const std::string& text, int dimension = 1) -> std::string {
    try {
      read(text, dimension);
    } catch (const SceneError& error) {
      return error.message();
    }
    return "no error";
  };

  // c = sqrt(E / rho) = 5000 m/s; omega = pi c / (2 L) with L = 2: 3926.99 rad/s; V = 1e-6 L omega.
  const auto bar = read("[constants]\nV = \"1e-6 * L * omega\"\nomega = \"pi * c / (2 * L)\"\nc = \"sqrt(young_modulus / density)\"\nL = 2\n"
                        "[initial_field]\nvelocity = [\"V * cos(pi * X / (2 * L))\"]\nstress = [-1.5e6]\n"
                        "[body_force]\nacceleration = [\"x * t + X\"]\n");
  CHECK(bar.constants.at("c") == doctest::Approx(5000.0));
  CHECK(bar.constants.at("V") == doctest::Approx(1e-6 * 2.0 * 3.14159265358979 * 5000.0 / 4.0).epsilon(1e-12));
  REQUIRE(bar.initial_velocity);
  const double X = 0.5, x = 0.75;
  CHECK(bar.initial_velocity->components[0](&X, &X, 0.0) == doctest::Approx(bar.constants.at("V") * std::cos(3.14159265358979 / 8.0)));
  CHECK(bar.initial_stress->components[0](&X, &X, 0.0) == -1.5e6);
  CHECK(bar.body_force->components[0](&x, &X, 2.0) == doctest::Approx(0.75 * 2.0 + 0.5));
  const Formula copy = bar.body_force->components[0];  // a copy evaluates on its own
  CHECK(copy(&X, &X, 1.0) == doctest::Approx(1.0));
  CHECK(bar.body_force->source.line == 13);  // the line of body_force.acceleration

  // 2D: the body force as Model's field, and the initial stress at the particles.
  const auto block = read("[initial_field]\nstress = [\"-density * 9.81 * (10 - Y)\", \"0\", \"x * y\"]\n"
                          "[body_force]\nacceleration = [\"sin(pi * x) * t\", \"-9.81\"]\n", 2);
  const auto field = body_force_field<2>(block);
  const Vector<2> b = field(Vector<2>(0.5, 3.0), Vector<2>(0.5, 3.0), 2.0);
  CHECK(b[0] == doctest::Approx(2.0));
  CHECK(b[1] == -9.81);
  Particles<2> particles;
  particles.add(Vector<2>(2.0, 4.0), 1.0, 8000.0, Vector<2>::Zero(), Vector<2>(0.5, 0.5));
  apply_scene_formulas<2>(block, {LinearElastic{200e9, 0.0, 8000.0}}, 1.0, particles);
  CHECK(particles.stress[0](0, 0) == doctest::Approx(-8000.0 * 9.81 * 6.0));
  CHECK(particles.stress[0](1, 0) == doctest::Approx(8.0));

  CHECK(message_of("[initial_field]\nvelocity = [\"2 * x +\"]\n") ==
        "error: f.toml:5: initial_field.velocity: '2 * x +': Unexpected end of expression at position 8");
  CHECK(message_of("[initial_field]\nvelocity = [\"sin(t)\"]\n") ==
        "error: f.toml:5: initial_field.velocity: 'sin(t)': Unexpected token \"t\" found at position 4. "
        "(unknown name; known here: x, X, pi, density, poisson_ratio, young_modulus)");
  CHECK(message_of("[body_force]\nacceleration = [\"y\"]\n").rfind("error: f.toml:5: body_force.acceleration: 'y': Unexpected token", 0) == 0);
  CHECK(message_of("[body_force]\nacceleration = [\"1\", \"2\"]\n").rfind("error: f.toml:5: body_force.acceleration: has 2 entries", 0) == 0);
  CHECK(message_of("[constants]\na = \"b + 1\"\nb = \"2 * a\"\n") == "error: f.toml:5: constants.a: 'b + 1': the constants refer to each other in a cycle");
  CHECK(message_of("[constants]\nA = \"b + 1\"\nb = \"q\"\n") ==
        "error: f.toml:6: constants.b: 'q': Unexpected token \"q\" found at position 0. (unknown name; known here: pi, density, poisson_ratio, young_modulus)");
  CHECK(message_of("[constants]\nsin = 1\n").rfind("error: f.toml:5: constants.sin: ", 0) == 0);
  CHECK(message_of("[initial_field]\nvelocty = [\"1\"]\n").rfind("error: f.toml:5: initial_field.velocty: unknown key", 0) == 0);

  // Non-finite at a particle: found at seeding, named by key and line.
  const auto singular = read("[initial_field]\nvelocity = [\"1 / (X - 0.25)\"]\n");
  Particles<1> bar_particles;
  bar_particles.add(Vector<1>(0.25), 1.0, 8000.0, Vector<1>(0.0), Vector<1>(0.25));
  try {
    apply_scene_formulas<1>(singular, {LinearElastic{200e9, 0.0, 8000.0}}, 1.0, bar_particles);
    FAIL("an infinite velocity must be rejected");
  } catch (const SceneError& error) {
    CHECK(error.message().rfind("error: f.toml:5: initial_field.velocity: '1 / (X - 0.25)' is inf at particle 0", 0) == 0);
  }
}

}  // namespace mpm::io
