/// \file
/// exact.csv beside observers.csv: the scene's small-strain exact solution (mpm/io/exact_solution.hpp) at the
/// reference position of the particle each observer follows (run.json's `observed`, where the report scores Eq. 43)
/// and at every sample time, under observers.csv's names (NAME.v_x, ...), so that `mpm plot` draws each beside its
/// computed series; and exact_NNNN.csv beside each snapshot_NNNN.csv: the same solution at every particle's
/// reference position at the snapshot's time, the profile `mpm plot` draws the particles against. Its parameters
/// come from the scene and the initial particles.
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "mpm/io/exact_solution.hpp"
#include "mpm/io/run_writer.hpp"
#include "mpm/run_control.hpp"

namespace mpm::io {

/// The Dyka bar's initial data from the initial particles: each particle's domain [X_p - l_p, X_p + l_p] (from the
/// bar's free end) carries its initial velocity, unstressed; neighbouring domains of equal velocity are merged.
template <int Dim>
std::vector<exact::BarPiece> bar_pieces(const Scene& scene, const Particles<Dim>& initial) {
  std::vector<int> order(initial.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return initial.reference_position[a][0] < initial.reference_position[b][0]; });
  std::vector<exact::BarPiece> pieces;
  for (int p : order) {
    const double from = initial.reference_position[p][0] - initial.half_length[p][0] - scene.origin[0];
    const double to = initial.reference_position[p][0] + initial.half_length[p][0] - scene.origin[0];
    const double velocity = initial.velocity[p][0];
    if (!pieces.empty() && pieces.back().velocity == velocity &&
        std::abs(pieces.back().to - from) < 1e-9 * scene.spacing)
      pieces.back().to = to;
    else
      pieces.push_back({from, to, velocity, 0.0});
  }
  return pieces;
}

/// The reference position X_p of particle p as a point of the scene's coordinates.
template <int Dim>
std::vector<double> reference_point(const Particles<Dim>& particles, int p) {
  const auto& X = particles.reference_position[p];
  return std::vector<double>(X.data(), X.data() + Dim);
}

/// Writes exact.csv at every sample and exact_NNNN.csv at every snapshot (none when the scene names no exact
/// solution), then passes everything on.
template <int Dim>
class ExactWriter : public Monitor<Dim> {
 public:
  /// `observed`: the particle index of each observer (Setup::observed), whose X_p exact.csv is evaluated at.
  ExactWriter(const std::string& folder, const Scene& scene, const Particles<Dim>& initial,
              const std::vector<int>& observed, Monitor<Dim>& next)
      : next_(next), observers_(scene.observers), folder_(folder) {
    if (scene.exact == ExactKind::none) return;
    for (int p : observed) points_.push_back(reference_point(initial, p));
    std::optional<std::vector<exact::BarPiece>> pieces;
    if (scene.exact == ExactKind::dyka_bar) pieces = bar_pieces(scene, initial);
    solution_ = std::make_unique<SceneExactSolution>(scene, StrainMeasure::small, std::vector<double>{}, pieces);
    columns_ = exact_columns(scene.exact);
    out_ = std::make_unique<OutputFile>(folder + "/exact.csv");
    *out_ << "t";
    for (const auto& observer : observers_)
      for (const auto& column : columns_) *out_ << "," << observer.name << "." << column;
    *out_ << "\n";
  }

  /// The columns per observer: soil_column u_y (the settlement, as observers.csv's) and sigma_yy; the bars v_x and
  /// sigma_xx; the manufactured solutions v and sigma.
  static std::vector<std::string> exact_columns(ExactKind exact) {
    if (exact == ExactKind::soil_column) return {"u_y", "sigma_yy"};
    if (exact == ExactKind::dyka_bar || exact == ExactKind::vibrating_bar) return {"v_x", "sigma_xx"};
    return {"v_x", "v_y", "sigma_xx", "sigma_yy", "sigma_xy"};
  }

  /// One row of exact.csv at the reference position X_p of each observer's particle.
  void sample(long step, double time, const Particles<Dim>& particles, const Balances<Dim>& balances) override {
    if (out_) {
      *out_ << time;
      for (const auto& point : points_) {
        const ExactState state = solution_->at(point, time);
        for (const auto& column : columns_) *out_ << "," << state.quantity(column);
      }
      *out_ << "\n";
      out_->check();
    }
    next_.sample(step, time, particles, balances);
  }

  /// Closes exact.csv. \throws OutputFailure if it could not be written in full.
  void finish() {
    if (out_) out_->close();
  }
  /// exact_NNNN.csv, whole or absent: `id`, the reference position `X` (`Y`), then exact_quantities(Dim) (u since
  /// t = 0, v, sigma) of the solution at each particle's X_p at the snapshot's time, a row per particle in
  /// snapshot_NNNN.csv's order. \throws OutputFailure.
  void snapshot(int index, double time, const Particles<Dim>& particles) override {
    if (solution_) {  // before the snapshot, whose snapshots.pvd is written last
      char name[32];
      std::snprintf(name, sizeof name, "/exact_%04d.csv", index);
      OutputFile csv(folder_ + name, OutputFile::Mode::atomic);
      csv << "id,X" << (Dim == 2 ? ",Y" : "");
      for (const auto& quantity : exact_quantities(Dim)) csv << "," << quantity;
      csv << "\n";
      for (int p = 0; p < particles.size(); ++p) {
        const std::vector<double> X = reference_point(particles, p);
        const ExactState state = solution_->at(X, time);
        csv << particles.id[p];
        for (double coordinate : X) csv << "," << coordinate;
        for (const auto& quantity : exact_quantities(Dim)) csv << "," << state.quantity(quantity);
        csv << "\n";
      }
      csv.close();
    }
    next_.snapshot(index, time, particles);
  }
  void progress(double time, double end_time) override { next_.progress(time, end_time); }

 private:
  Monitor<Dim>& next_;
  const std::vector<ObserverSettings>& observers_;  ///< the scene's, which outlives the run
  std::string folder_;
  std::vector<std::vector<double>> points_;  ///< X_p of each observer's particle
  std::unique_ptr<SceneExactSolution> solution_;
  std::vector<std::string> columns_;
  std::unique_ptr<OutputFile> out_;  ///< exact.csv
};

TEST_CASE("exact.csv: the bar's initial data from the particles, merged where the velocity is equal") {
  Scene scene;
  scene.origin = {1.0};  // the bar spans [1, 2]: pieces are measured from its free end
  scene.spacing = 0.25;
  Particles<1> particles;  // four particles of 0.25 m; the two next to the free end at -5 m/s, listed out of order
  for (double x : {1.625, 1.125, 1.875, 1.375})
    particles.add(Vector<1>::Constant(x), 1.0, 1.0, Vector<1>::Constant(x < 1.5 ? -5.0 : 0.0), Vector<1>::Constant(0.125));
  const auto pieces = bar_pieces(scene, particles);
  REQUIRE(pieces.size() == 2);
  CHECK(pieces[0].from == 0.0);
  CHECK(pieces[0].to == 0.5);
  CHECK(pieces[0].velocity == -5.0);
  CHECK(pieces[1].from == 0.5);
  CHECK(pieces[1].to == 1.0);
  CHECK(pieces[1].velocity == 0.0);
  CHECK(pieces[1].stress == 0.0);
}

TEST_CASE("exact.csv at the observed particle's X_p (where Eq. (43) is scored), exact_NNNN.csv at every particle") {
  // A bar of 4 cells of 0.25 m, c = Z = 1, free at 0, its half next to the free end at -5 m/s; the observer names
  // the free end X = 0, whose particle is X_p = 0.125. The tension front from X = 0.5 reaches 0.125 at t = 0.375:
  // at t = 0.45 the particle's point has v = -5 / 2, sigma = Z 5 / 2, u = -5 (0.375) - 2.5 (0.075) = -2.0625, while
  // the free end X = 0 still moves at -5.
  const std::string text =
      "exact = \"dyka_bar\"\n[grid]\nlength = [1.0]\ncells = [4]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [1.0]\n[[initial_velocity]]\nmin = [0.0]\nmax = [0.5]\nvelocity = [-5.0]\n"
      "[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n[solver]\nend_time = 1.0\n"
      "[[observer]]\nname = \"A\"\nposition = [0.0]\n";
  const Scene scene = read_scene(parse_scene_text(text, "bar.toml"));
  Particles<1> particles;
  for (double x : {0.125, 0.375, 0.625, 0.875})
    particles.add(Vector<1>::Constant(x), 1.0, 1.0, Vector<1>::Constant(x < 0.5 ? -5.0 : 0.0),
                  Vector<1>::Constant(0.125));
  const auto folder = std::filesystem::temp_directory_path() / ("mpm_exact_series_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  Monitor<1> nothing;
  ExactWriter<1> writer(folder.string(), scene, particles, {0}, nothing);
  writer.sample(0, 0.45, particles, Balances<1>{});
  writer.snapshot(3, 0.45, particles);
  writer.finish();
  const auto lines = [&](const char* name) {
    std::ifstream in(folder / name);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);) all.push_back(line);
    return all;
  };
  CHECK(lines("exact.csv") == std::vector<std::string>{"t,A.v_x,A.sigma_xx", "0.45,-2.5,2.5"});
  const auto profile = lines("exact_0003.csv");
  REQUIRE(profile.size() == 5);
  CHECK(profile[0] == "id,X,u_x,v_x,sigma_xx");
  CHECK(profile[1] == "0,0.125,-2.0625,-2.5,2.5");
  CHECK(profile[4] == "3,0.875,-0.1875,-2.5,2.5");  // reached at t = 0.375 by the front running to the support
  std::filesystem::remove_all(folder);
}

}  // namespace mpm::io
