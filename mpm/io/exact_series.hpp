/// \file
/// exact.csv: the exact solution the scene names (`exact = "dyka_bar"` or `"soil_column"`), at each
/// observer's reference position and at every sample time, beside observers.csv:
///   dyka_bar     t, then per observer NAME.v_x, NAME.sigma_xx   (paper/06_exact_bar.md, mpm/exact/bar.hpp)
///   soil_column  t, then per observer NAME.y, NAME.sigma_yy     (paper/07_exact_column.md, mpm/exact/column.hpp)
/// The columns carry observers.csv's names, so `mpm plot` draws each beside its computed series.
/// The exact solutions take their parameters from the scene and the initial particles, never from
/// the solver's state during the run.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <memory>
#include <string>
#include <vector>

#include "mpm/exact/bar.hpp"
#include "mpm/exact/column.hpp"
#include "mpm/io/run_writer.hpp"
#include "mpm/io/scene.hpp"
#include "mpm/simulation.hpp"

namespace mpm::io {

/// The Dyka bar's initial data from the initial particles: each particle's domain
/// [X_p - l_p, X_p + l_p] (from the bar's free end) carries its initial velocity, unstressed;
/// neighbouring domains of equal velocity are merged.
template <int Dim>
std::vector<exact::BarPiece> bar_pieces(const Scene& scene, const Particles<Dim>& initial) {
  std::vector<int> order(initial.size());
  for (int p = 0; p < initial.size(); ++p) order[p] = p;
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return initial.reference_position[a][0] < initial.reference_position[b][0]; });
  std::vector<exact::BarPiece> pieces;
  for (int p : order) {
    const double from = initial.reference_position[p][0] - initial.half_length[p][0] - scene.origin[0];
    const double to = initial.reference_position[p][0] + initial.half_length[p][0] - scene.origin[0];
    const double velocity = initial.velocity[p][0];
    if (!pieces.empty() && pieces.back().velocity == velocity && std::abs(pieces.back().to - from) < 1e-9 * scene.spacing)
      pieces.back().to = to;
    else
      pieces.push_back({from, to, velocity, 0.0});
  }
  return pieces;
}

/// Writes exact.csv at every sample, then passes everything on to the run's writer.
template <int Dim>
class ExactWriter : public Monitor<Dim> {
 public:
  ExactWriter(const std::string& folder, const Scene& scene, const Particles<Dim>& initial,
              const std::vector<int>& observed, Monitor<Dim>& next)
      : scene_(scene), next_(next) {
    if (scene.exact == "none") return;
    for (int p : observed) reference_.push_back(initial.reference_position[p] - to_origin(scene));
    if (scene.exact == "dyka_bar")
      bar_ = std::make_unique<exact::ElasticBar>(scene.length[0], scene.young_modulus, scene.density, bar_pieces(scene, initial));
    else
      column_ = std::make_unique<exact::SoilColumn>(scene.length[Dim - 1], constrained_modulus(scene), scene.density,
                                                    -scene.gravity[Dim - 1], scene.ramp_period);
    path_ = folder + "/exact.csv";
    out_.open(path_);
    check_written(out_, path_);
    out_ << std::setprecision(12) << "t";
    for (const auto& observer : scene.observers)
      out_ << "," << observer.name << (bar_ ? ".v_x," : ".y,") << observer.name << (bar_ ? ".sigma_xx" : ".sigma_yy");
    out_ << "\n";
  }

  void sample(long step, double time, const Particles<Dim>& particles, const Balances<Dim>& balances) override {
    if (out_.is_open()) {
      out_ << time;
      for (const Vector<Dim>& X : reference_) {
        if (bar_) {
          out_ << "," << bar_->velocity(X[0], time) + 0.0 << "," << bar_->stress(X[0], time) + 0.0;  // + 0.0: no -0
        } else {
          const double height = X[Dim - 1];
          out_ << "," << scene_.origin[Dim - 1] + height + column_->displacement(height, time) << ","
               << column_->stress(height, time);
        }
      }
      out_ << "\n";
      check_written(out_, path_);
    }
    next_.sample(step, time, particles, balances);
  }

  /// Closes exact.csv. \throws OutputFailure if it could not be written in full.
  void finish() {
    if (out_.is_open()) close_checked(out_, path_);
  }
  void snapshot(int index, double time, const Particles<Dim>& particles) override { next_.snapshot(index, time, particles); }
  void progress(double time, double end_time) override { next_.progress(time, end_time); }

  /// paper/07_exact_column.md: the constrained modulus of a laterally confined column, M = E(1-nu)/((1+nu)(1-2nu)).
  static double constrained_modulus(const Scene& scene) {
    const double nu = scene.poisson_ratio;
    return scene.young_modulus * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  }

 private:
  static Vector<Dim> to_origin(const Scene& scene) {
    Vector<Dim> origin;
    for (int axis = 0; axis < Dim; ++axis) origin[axis] = scene.origin[axis];
    return origin;
  }

  const Scene& scene_;
  Monitor<Dim>& next_;
  std::vector<Vector<Dim>> reference_;  ///< each observed particle's X, from the scene's origin
  std::unique_ptr<exact::ElasticBar> bar_;
  std::unique_ptr<exact::SoilColumn> column_;
  std::ofstream out_;
  std::string path_;
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
