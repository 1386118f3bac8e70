/// \file
/// exact.csv beside observers.csv: the scene's small-strain exact solution (mpm/io/exact_solution.hpp) at the
/// material point each observer names and at every sample time, under observers.csv's names (NAME.v_x, ...), so
/// that `mpm plot` draws each beside its computed series. Its parameters come from the scene and the initial particles.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "mpm/io/exact_solution.hpp"
#include "mpm/io/run_writer.hpp"
#include "mpm/simulation.hpp"

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

/// Writes exact.csv at every sample (none when the scene names no exact solution), then passes everything on.
template <int Dim>
class ExactWriter : public Monitor<Dim> {
 public:
  ExactWriter(const std::string& folder, const Scene& scene, const Particles<Dim>& initial, Monitor<Dim>& next)
      : next_(next), observers_(scene.observers) {
    if (scene.exact == ExactKind::none) return;
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

  /// One row of exact.csv at each observer's material point (its `position`, a reference position).
  void sample(long step, double time, const Particles<Dim>& particles, const Balances<Dim>& balances) override {
    if (out_) {
      *out_ << time;
      for (const auto& observer : observers_) {
        const ExactState state = solution_->at(observer.position, time);
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
  void snapshot(int index, double time, const Particles<Dim>& particles) override {
    next_.snapshot(index, time, particles);
  }
  void progress(double time, double end_time) override { next_.progress(time, end_time); }

 private:
  Monitor<Dim>& next_;
  const std::vector<ObserverSettings>& observers_;  ///< the scene's, which outlives the run
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

}  // namespace mpm::io
