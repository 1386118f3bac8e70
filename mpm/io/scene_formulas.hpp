/// \file
/// Smooth data in scenes, compiled by muParser: [constants] (numbers, or formulas of other constants), the
/// [initial_field] velocity and stress (formulas of x, X and y, Y in 2D) and the [body_force] acceleration (also
/// of t). Every formula knows pi and the material's young_modulus, poisson_ratio and density.
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

/// Names a formula may use besides pi and the scene's constants: x, X (y, Y in 2D; none for dimension 0), t.
struct FormulaVariables {
  int dimension = 1;
  bool time = false;  ///< t is known (body force only)
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

  /// A parser of the text with its variables bound to the storage of a fresh state; compiled by a first evaluation.
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
    if (results != 1)
      throw mu::Parser::exception_type("a formula gives one value; this one gives " + std::to_string(results));
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
    for (const Formula& component : components) {
      values.push_back(component(position, reference_position, time));
      if (std::isfinite(values.back())) continue;
      std::ostringstream what;
      what.precision(9);
      what << "'" << component.text() << "' is " << values.back() << " at particle " << particle_id
           << " (X = " << reference_position[0];
      if (dimension == 2) what << ", Y = " << reference_position[1];
      what << ") at t = " << time << "; a formula must be finite at every particle";
      throw SceneError(source.file, source.line, source.key, what.str());
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

/// The table `key`, or an empty one when the scene has none (its required keys are then refused by name).
inline const toml::table& table_or_empty(const SceneFile& file, SceneReader& root, const std::string& key) {
  static const toml::table empty;
  if (!root.has(key)) return empty;
  const toml::table* table = file.table[key].as_table();
  if (!table) root.fail(key, "must be a table: write [" + key + "]");
  return *table;
}

/// muParser's complaint, made to name what is known when the formula uses an unknown name.
inline std::string formula_problem(const mu::Parser::exception_type& error, const std::string& text,
                                   const std::map<std::string, double>& constants, const FormulaVariables& variables) {
  std::string what = "'" + text + "': " + error.GetMsg();
  if (error.GetCode() != mu::ecUNASSIGNABLE_TOKEN) return what;
  what += std::string(" (unknown name; known here: ") +
          (variables.dimension == 2 ? "x, y, X, Y, " : variables.dimension == 1 ? "x, X, " : "") +
          (variables.time ? "t, " : "") + "pi";
  for (const auto& [name, value] : constants) what += ", " + name;
  return what + ")";
}

/// `key` of `reader`'s table, an array of `size` formulas (in quotes) or numbers; nothing when absent.
inline std::optional<FormulaList> read_formula_list(SceneReader& reader, const std::string& key, int size,
                                                    const std::string& size_text,
                                                    const std::map<std::string, double>& constants,
                                                    FormulaVariables variables) {
  const toml::node* node = reader.node(key);
  if (!node) return std::nullopt;
  const toml::array* array = node->as_array();
  if (!array) reader.fail(key, "must be an array of formulas in quotes, e.g. [\"sin(pi * x)\"]");
  if (static_cast<int>(array->size()) != size)
    reader.fail(key, "has " + std::to_string(array->size()) + " entries; needs " + std::to_string(size) + " (" +
                         size_text + ")");
  const auto [file, line] = reader.location(key);
  FormulaList list{{}, {file, line, reader.full(key)}};
  for (const auto& entry : *array) {
    std::ostringstream text;  // a number written as a formula, to 17 digits
    text.precision(17);
    if (entry.is_string()) text << *entry.value<std::string>();
    else if (entry.is_floating_point() || entry.is_integer()) text << *entry.value<double>();
    else reader.fail(key, "entries must be formulas in quotes or numbers");
    try {
      list.components.emplace_back(text.str(), constants, variables);
    } catch (const mu::Parser::exception_type& error) {
      reader.fail(key, formula_problem(error, text.str(), constants, variables));
    }
  }
  return list;
}

/// [constants]: numbers, or formulas of other constants, resolved in whatever order they allow, beside the
/// predefined constants `known`.
inline std::map<std::string, double> read_constants(const SceneFile& file, SceneReader& root,
                                                    std::map<std::string, double> known) {
  const toml::table& table = table_or_empty(file, root, "constants");
  SceneReader reader(file, table, "constants");
  const std::string variables[] = {"x", "y", "X", "Y", "t", "pi"};
  std::map<std::string, std::string> pending;
  for (const auto& [key, node] : table) {
    const std::string name(key.str());
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0])) ||
        name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos)
      reader.fail(name, "a constant's name is letters, digits and _, starting with a letter or _");
    if (known.count(name) || mu::Parser().GetFunDef().count(name) || std::count(variables, variables + 6, name))
      reader.fail(name, "'" + name + "' is a variable, function or predefined constant; choose another name");
    if (node.is_string()) {
      pending[name] = *node.value<std::string>();
      continue;
    }
    if (!node.is_floating_point() && !node.is_integer()) reader.fail(name, "must be a number or a formula in quotes");
    known[name] = *node.value<double>();
    if (!std::isfinite(known[name])) reader.fail(name, "must be finite");
  }
  const FormulaVariables none{0, false};
  for (bool progress = true; progress;) {  // each pass resolves every constant whose constants are known
    progress = false;
    for (auto entry = pending.begin(); entry != pending.end();) {
      double value = 0.0;
      try {
        value = Formula(entry->second, known, none)(nullptr, nullptr, 0.0);
      } catch (const mu::Parser::exception_type&) {
        ++entry;
        continue;
      }
      if (!std::isfinite(value)) reader.fail(entry->first, "'" + entry->second + "' is not finite");
      known[entry->first] = value;
      entry = pending.erase(entry);
      progress = true;
    }
  }
  // What is left does not compile, names an unknown constant, or is a cycle: first blamed is a constant
  // whose problem is not another pending constant.
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& [name, text] : pending) {
      try {
        Formula(text, known, none);
      } catch (const mu::Parser::exception_type& error) {
        if (pass == 0 && pending.count(error.GetToken())) continue;
        reader.fail(name, pass == 0 ? formula_problem(error, text, known, none)
                                    : "'" + text + "': the constants refer to each other in a cycle");
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
  const std::map<std::string, double>& constants = formulas.constants;
  const std::string axes = dimension == 1 ? "x" : "x, y";
  SceneReader field(file, detail::table_or_empty(file, root, "initial_field"), "initial_field");
  formulas.initial_velocity =
      detail::read_formula_list(field, "velocity", dimension, axes, constants, {dimension, false});
  formulas.initial_stress = detail::read_formula_list(field, "stress", dimension == 1 ? 1 : 3,
                                                      dimension == 1 ? "xx" : "xx, yy, xy", constants, {dimension, false});
  field.reject_unknown_keys();
  SceneReader force(file, detail::table_or_empty(file, root, "body_force"), "body_force");
  formulas.body_force = detail::read_formula_list(force, "acceleration", dimension, axes, constants, {dimension, true});
  force.reject_unknown_keys();
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
void apply_scene_formulas(const SceneFormulas& formulas, const std::vector<LinearElastic>& materials, double end_time,
                          Particles<Dim>& particles) {
  auto at = [&](const FormulaList& list, int p, double time) {
    return list.at(particles.position[p].data(), particles.reference_position[p].data(), time, particles.id[p], Dim);
  };
  for (int p = 0; formulas.initial_velocity && p < particles.size(); ++p)
    particles.velocity[p] = Eigen::Map<const Vector<Dim>>(at(*formulas.initial_velocity, p, 0.0).data());
  int next = 0;  // set_initial_stress visits the particles in order
  auto stress = [&](const Vector<Dim>&) {
    const std::vector<double> value = at(*formulas.initial_stress, next++, 0.0);
    Matrix<Dim> sigma;
    if constexpr (Dim == 1) sigma << value[0];
    else sigma << value[0], value[2], value[2], value[1];
    return sigma;
  };
  if (formulas.initial_stress) set_initial_stress<Dim>(stress, materials, particles);
  for (int p = 0; formulas.body_force && p < particles.size(); ++p)
    at(*formulas.body_force, p, 0.0), at(*formulas.body_force, p, end_time);
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
