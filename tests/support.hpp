/// \file
/// What the whole-method tests share: running a scene in-process and recording one particle.
#pragma once
#include <string>
#include <vector>

#include "mpm/run.hpp"

namespace mpm::testing {

/// Records time, position and velocity of one particle, and the balances, at every sample.
template <int Dim>
struct Recorder : Monitor<Dim> {
  explicit Recorder(int observed_particle) : particle(observed_particle) {}
  void sample(long, double t, const Particles<Dim>& particles, const Balances<Dim>& sums) override {
    time.push_back(t);
    position.push_back(particles.position[particle]);
    velocity.push_back(particles.velocity[particle]);
    balances.push_back(sums);
  }
  int particle;
  std::vector<double> time;
  std::vector<Vector<Dim>> position, velocity;
  std::vector<Balances<Dim>> balances;
};

inline std::string source_path(const std::string& relative) { return std::string(MPM_SOURCE_DIR) + "/" + relative; }

/// A scene from TOML text (for tests that build their own scene).
inline io::Scene scene_from_text(const std::string& text, const std::vector<std::string>& overrides = {}) {
  io::SceneFile file = io::parse_scene_text(text, "test.toml");
  for (size_t k = 0; k < overrides.size(); ++k) io::apply_override(file, overrides[k], static_cast<int>(k) + 1);
  return io::read_scene(file);
}

}  // namespace mpm::testing
