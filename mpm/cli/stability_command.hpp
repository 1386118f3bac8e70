/// \file
/// `mpm stability`: the largest stable CFL of a method, from the spectral radius of the code's own linearised step
/// on a uniform body held at its walls (mpm/stability.hpp, paper/10_integrator_analysis.md); CSV, one row.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/cli/options.hpp"
#include "mpm/cli/shape_command.hpp"
#include "mpm/stability_api.hpp"

namespace mpm::cli {

/// The method `mpm stability` is asked about (its body: StabilityBody).
struct StabilityRequest {
  std::string shape = "linear", integrator = "fe", npc_velocity = "eq32", stress_update = "usf";
  double newmark_gamma = 0.5, lme_gamma = 3.0, flip_fraction = 1.0, poisson_ratio = 0.0;
};

/// The option of `mpm stability` that sets a scene key of its body (`solver.lme_gamma`: `--lme-gamma`); the key itself
/// for one no option sets.
inline std::string option_of_key(const std::string& key) {
  if (key == "material.poisson_ratio") return "--poisson-ratio";
  if (key.rfind("solver.", 0) != 0) return key;
  std::string option = "--" + key.substr(7);
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

TEST_CASE("mpm stability: a scene key of its body is named by the option that sets it") {
  CHECK(option_of_key("solver.lme_gamma") == "--lme-gamma");
  CHECK(option_of_key("solver.newmark_gamma") == "--newmark-gamma");
  CHECK(option_of_key("material.poisson_ratio") == "--poisson-ratio");
  CHECK(option_of_key("grid.cells") == "grid.cells");
}

/// The scene of `body` with the method of `request`, checked as the options cannot be alone (at most 1000 unknowns,
/// an LME support within 100 cells, as `mpm shape`'s). \throws Refused naming the option.
inline io::Scene stability_request_scene(const StabilityRequest& request, StabilityBody& body) {
  const int fewest = body.dimension == 1 ? 4 : 2;  // a 2D body of 2 x 2 cells holds 5 x 5 particles per cell
  if (body.cells != 0 && body.cells < fewest)
    throw Refused("--cells: must be 0 (the default) or from " + std::to_string(fewest) + " to 256 in " +
                  std::to_string(body.dimension) + "D");
  if (request.integrator == "npc" && request.stress_update != "usf")
    throw Refused(
        "--stress-update: usl and musl are forward Euler's (the predictor-corrector updates stress first): "
        "give --integrator fe");
  if (stability_unknowns(body) > 1000)
    throw Refused(std::string(body.cells > 0 ? "--cells" : "--ppc") + ": the body would have " +
                  std::to_string(stability_unknowns(body)) +
                  " unknowns, more than 1000 (the step matrix is dense; its "
                  "eigenvalues cost their cube): fewer cells or particles");
  auto setting = [](const std::string& key, double value) {
    std::ostringstream number;
    number << "solver." << key << "=" << std::setprecision(17) << value;
    return number.str();
  };
  body.method = {"solver.shape=\"" + request.shape + "\"",
                 "solver.integrator=\"" + request.integrator + "\"",
                 "solver.npc_velocity=\"" + request.npc_velocity + "\"",
                 setting("newmark_gamma", request.newmark_gamma),
                 setting("flip_fraction", request.flip_fraction),
                 setting("lme_gamma", request.lme_gamma),
                 "solver.stress_update=\"" + request.stress_update + "\""};
  io::Scene scene;
  try {
    scene = stability_scene(body);
  } catch (const SceneError& error) {  // e.g. an LME gamma too large for its support tolerance: named by its option
    throw Refused(option_of_key(error.key) + ": " + error.what());
  }
  if (scene.shape == io::ShapeKind::lme && !lme_support_too_wide(scene.lme_gamma, scene.lme_tol).empty())
    throw Refused("--lme-gamma: " + lme_support_too_wide(scene.lme_gamma, scene.lme_tol));
  return scene;
}

/// `mpm stability`; returns the exit code.
inline int stability_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  StabilityRequest request;
  StabilityBody body;
  CommandParser app(
      "stability",
      "Prints CSV with the largest stable CFL (Eq. 42, c = sqrt(E / rho)) of a method: cfl_limit, from the spectral\n"
      "radius of the code's own step linearised about rest on a uniform bar (1D) or square (2D) held at its walls,\n"
      "and cfl_limit_from_modes, the one-mode analysis (2 for forward Euler and the Newmark average, "
      "2/sqrt(3 - 2 gamma)\n"
      "for Eq. 32) divided by the body's highest mode omega_max h / c (highest_mode); inf when no CFL up to 1000\n"
      "is unstable.");
  app.add_option("--shape", request.shape, "shape function")
      ->check(one_of({"linear", "ugimp", "lme", "bspline2", "bspline3"}));
  app.add_option("--integrator", request.integrator, "fe (forward Euler) | npc (the predictor-corrector)")
      ->check(one_of({"fe", "npc"}));
  app.add_option("--newmark-gamma", request.newmark_gamma, "Newmark gamma of npc")->check(number_in(0.0, 1.0));
  app.add_option("--npc-velocity", request.npc_velocity, "npc's particle velocity: Eq. (32) or the Newmark average")
      ->check(one_of({"eq32", "average"}));
  app.add_option("--flip-fraction", request.flip_fraction, "forward Euler's PIC/FLIP blend")
      ->check(number_in(0.0, 1.0));
  app.add_option("--stress-update", request.stress_update, "forward Euler's stress update")
      ->check(one_of({"usf", "usl", "musl"}));
  app.add_option("--ppc", body.ppc, "particles per cell and axis")->check(whole_in(1, 5));
  app.add_option("--lme-gamma", request.lme_gamma, "LME locality gamma")->check(positive());
  app.add_option("--dim", body.dimension, "dimension")->check(whole_in(1, 2));
  app.add_option("--poisson-ratio", body.poisson_ratio, "plane strain")->check(number_in(0.0, 0.5, true));
  app.add_option("--cells", body.cells,
                 "cells per axis, at most 1000 unknowns in all (0: max(16, 64 / ppc) in 1D; in 2D 8 / ppc,\n"
                 "3 at 3 ppc, 2 from 4 ppc)")
      ->check(whole_in(0, 256));
  return run_parsed(app, arguments, out, err, [&] {
    const io::Scene scene = stability_request_scene(request, body);
    const StabilityLimits limits = body.dimension == 1 ? stability_limits<1>(scene) : stability_limits<2>(scene);
    out << "dim,shape,lme_gamma,integrator,npc_velocity,newmark_gamma,flip_fraction,ppc,poisson_ratio,cells,unknowns,"
           "highest_mode,cfl_limit,cfl_limit_from_modes,stress_update\n"
        << std::setprecision(8) << body.dimension << "," << request.shape << "," << request.lme_gamma << ","
        << request.integrator << "," << request.npc_velocity << "," << request.newmark_gamma << ","
        << request.flip_fraction << "," << body.ppc << "," << body.poisson_ratio << "," << stability_cells(body) << ","
        << limits.unknowns << "," << limits.highest_mode << "," << limits.cfl_limit << ","
        << limits.cfl_limit_from_modes << "," << request.stress_update << "\n";
    return 0;
  });
}

TEST_CASE("mpm stability: linear shapes at 1 ppc, 2 for forward Euler and 2/sqrt(3 - 2 gamma) for Eq. (32), to 1e-3") {
  auto limit_of = [](const std::vector<std::string>& arguments) {
    std::ostringstream out, err;
    REQUIRE(stability_command(arguments, out, err) == 0);
    std::istringstream lines(out.str());
    std::string header, row;
    std::getline(lines, header);
    std::getline(lines, row);
    // cfl_limit is the 13th column
    std::istringstream fields(row);
    std::string field;
    for (int column = 0; column < 13; ++column) std::getline(fields, field, ',');
    return std::stod(field);
  };
  CHECK(limit_of({"--integrator", "fe"}) == doctest::Approx(2.0).epsilon(1e-3));
  CHECK(limit_of({"--integrator", "npc"}) == doctest::Approx(std::sqrt(2.0)).epsilon(1e-3));
  CHECK(limit_of({"--integrator", "npc", "--newmark-gamma", "0.75"}) ==
        doctest::Approx(2.0 / std::sqrt(1.5)).epsilon(1e-3));
  CHECK(limit_of({"--integrator", "npc", "--newmark-gamma", "0.6", "--npc-velocity", "average"}) ==
        doctest::Approx(2.0).epsilon(1e-3));
  std::ostringstream out, err;
  CHECK(stability_command({"--newmark-gamma", "1.5"}, out, err) == 2);
  CHECK(err.str().find("--newmark-gamma") != std::string::npos);
  CHECK(stability_command({"--ppc", "0"}, out, err) == 2);
  CHECK(stability_command({"--shape"}, out, err) == 2);
  CHECK(stability_command({"--shape", "cubic"}, out, err) == 2);
  CHECK(stability_command({"--lme-gamma", "50", "--shape", "lme"}, out, err) == 2);
  CHECK(stability_command({"--dim", "2", "--cells", "12"}, out, err) == 2);  // 1008 unknowns
  CHECK(stability_command({"--ppc", "6"}, out, err) == 2);
  CHECK(stability_command({"--cells", "3"}, out, err) == 2);  // 1D: from 4 cells
  CHECK(out.str().empty());
  for (const char* gamma :
       {"1e-3", "1e-12", "1e-18"}) {  // beyond 100 cells: refused at once, never out of memory or Newton
    std::ostringstream wide;
    CHECK(stability_command({"--shape", "lme", "--lme-gamma", gamma}, out, wide) == 2);
    CHECK(wide.str() ==
          "error: --lme-gamma: too small for the support tolerance 1e-06: the support would reach beyond 100 cells; "
          "give at least 0.00139\n");
  }
  CHECK(out.str().empty());
  std::ostringstream large;
  CHECK(stability_command({"--lme-gamma", "1e-18"}, out, large) == 0);                      // no LME: gamma unused
  CHECK(stability_command({"--shape", "lme", "--lme-gamma", "0.00139"}, out, large) == 0);  // the least it names
  // a Poisson ratio just below 0.5 reaches the body's scene as it is (at 6 digits it read 0.5, out of range)
  StabilityBody nearly_incompressible;
  nearly_incompressible.poisson_ratio = 0.4999999;
  CHECK(stability_scene(nearly_incompressible).bodies[0].material.poisson_ratio == 0.4999999);
  std::ostringstream fine;
  CHECK(stability_command({"--poisson-ratio", "0.4999999", "--dim", "2"}, fine, err) == 0);
}

TEST_CASE("mpm stability --dim 2: 3 to 5 particles per cell per axis on 3 x 3 or 2 x 2 cells, within 1000 unknowns") {
  auto row_of = [](const std::vector<std::string>& arguments) {
    std::ostringstream out, err;
    REQUIRE(stability_command(arguments, out, err) == 0);
    std::istringstream fields(out.str().substr(out.str().find('\n') + 1));
    std::vector<std::string> row;
    for (std::string field; std::getline(fields, field, ',');) row.push_back(field);
    return row;  // dim, ..., ppc (7), poisson_ratio, cells (9), unknowns (10), highest_mode, cfl_limit (12), ...
  };
  const auto five = row_of({"--dim", "2", "--ppc", "5"});
  CHECK(five.at(7) == "5");
  CHECK(five.at(9) == "2");
  CHECK(five.at(10) == "700");  // (2 x 5)^2 particles, 7 unknowns each
  // forward Euler's one-mode limit, 2 over the body's highest mode: the bisection on the spectral radius agrees
  CHECK(std::stod(five.at(12)) == doctest::Approx(2.0 / std::stod(five.at(11))).epsilon(1e-3));
  CHECK(row_of({"--dim", "2", "--ppc", "3"}).at(10) == "567");   // 3 x 3 cells
  CHECK(row_of({"--dim", "2", "--ppc", "2"}).at(10) == "448");   // 4 x 4 cells, as before
  std::ostringstream out, err;
  CHECK(stability_command({"--dim", "2", "--ppc", "5", "--cells", "3"}, out, err) == 2);  // 1575 unknowns
  CHECK(err.str().find("--cells: the body would have 1575 unknowns") != std::string::npos);
}

TEST_CASE("scene_cfl_limit: mpm run's warning limit for a scene, 1D and 2D, looked for only above a stable CFL") {
  const std::string bar =
      "[grid]\nlength = [1.0]\ncells = [10]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [1.0]\n[solver]\nend_time = 1.0\nintegrator = \"npc\"\nnewmark_gamma = 0.75\n";
  io::SceneFile file = io::parse_scene_text(bar, "bar.toml");
  CHECK(scene_cfl_limit(io::read_scene(file)) == doctest::Approx(2.0 / std::sqrt(1.5)).epsilon(1e-3));
  // The warning's limit is looked for only when the scene's CFL is unstable: none at 1.6, the limit at 1.65.
  io::apply_override(file, "solver.cfl=1.6", 1);
  CHECK(std::isnan(scene_cfl_limit_if_exceeded(io::read_scene(file))));
  io::apply_override(file, "solver.cfl=1.65", 2);
  CHECK(scene_cfl_limit_if_exceeded(io::read_scene(file)) == doctest::Approx(2.0 / std::sqrt(1.5)).epsilon(1e-3));
  // 2D plane strain, nu = 0.3: the P-wave modulus E (1 - nu) / ((1 + nu)(1 - 2 nu)) = 1.346 E makes the highest
  // mode faster than c = sqrt(E / rho) of Eq. (42), so the limit falls below forward Euler's 2 by about 1/sqrt(1.346)
  const std::string block =
      "dimension = 2\n[grid]\nlength = [1.0, 1.0]\ncells = [2, 2]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "poisson_ratio = 0.3\n[[body]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[solver]\nend_time = 1.0\n";
  io::SceneFile block_file = io::parse_scene_text(block, "block.toml");
  const double limit = scene_cfl_limit(io::read_scene(block_file));
  CHECK(limit < 2.0 / std::sqrt(1.346) * 1.05);
  CHECK(limit > 2.0 / std::sqrt(1.346) * 0.9);
}

TEST_CASE(
    "moved_body_cfl_limit: a free end's node entering the quadratic B-spline's support drops USL's limit, not USF's or the cubic's") {
  // A free bar, 1 particle per cell at the cell centres, 2 margin cells beyond its free end at x = 0, held at x = 1:
  // the node at x = -h lies exactly 1.5 h from the end particle, where the quadratic B-spline vanishes. Moved outward
  // by 1e-6 h, that node enters the support with a mass of 5e-13 m_p, and USL's strain rate takes from it
  // grad N v_I = O(1) (grad N ~ delta, v_I ~ dt f_I / m_I ~ 1/delta): the limit falls from USL's 1/sqrt(2) at rest to
  // 0.620 (measured, on this bar as on the 40-cell Dyka bar). USF and MUSL take v_I = p_I / m_I of the
  // particles' velocities, bounded, and keep 2; the cubic B-spline has no node at the end of its support.
  auto scene = [](const std::string& shape, const std::string& update) {
    io::SceneFile file = io::parse_scene_text(
        "[grid]\nlength = [1.0]\ncells = [16]\nmargin_min = [2]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
        "[[body]]\nmin = [0.0]\nmax = [1.0]\n[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n[solver]\nend_time = 1.0\n",
        "free_bar.toml");
    io::apply_override(file, "solver.shape=\"" + shape + "\"", 1);
    io::apply_override(file, "solver.stress_update=\"" + update + "\"", 2);
    return io::read_scene(file);
  };
  const io::Scene quadratic_usl = scene("bspline2", "usl");
  CHECK(moved_body_cfl_limit<1>(quadratic_usl, 0.0) == doctest::Approx(1.0 / std::sqrt(2.0)).epsilon(2e-3));
  const double moved = moved_body_cfl_limit<1>(quadratic_usl, -1e-6);
  CHECK(moved < 0.65);
  CHECK(moved > 0.55);
  CHECK(moved_body_cfl_limit<1>(quadratic_usl, 1e-6) ==
        doctest::Approx(1.0 / std::sqrt(2.0)).epsilon(2e-3));  // inward: no new node
  CHECK(moved_body_cfl_limit<1>(scene("bspline2", "usf"), -1e-6) == doctest::Approx(2.0).epsilon(1e-2));
  CHECK(moved_body_cfl_limit<1>(scene("bspline2", "musl"), -1e-6) == doctest::Approx(2.0).epsilon(1e-2));
  CHECK(moved_body_cfl_limit<1>(scene("linear", "usl"), -1e-6) == doctest::Approx(1.0 / std::sqrt(2.0)).epsilon(2e-3));
  const io::Scene cubic_usl = scene("bspline3", "usl");
  CHECK(moved_body_cfl_limit<1>(cubic_usl, -1e-6) ==
        doctest::Approx(moved_body_cfl_limit<1>(cubic_usl, 0.0)).epsilon(1e-3));
}

}  // namespace mpm::cli
