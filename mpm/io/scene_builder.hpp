/// \file
/// From validated scene settings to the objects of a run: grid, model, particles, observers.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <limits>

#include "mpm/exact/manufactured.hpp"

#include "mpm/io/scene.hpp"
#include "mpm/model.hpp"
#include "mpm/particles/seeding.hpp"

namespace mpm::io {

/// The first Dim entries of `values` as a vector.
template <int Dim>
Vector<Dim> to_vector(const std::vector<double>& values) {
  return Eigen::Map<const Vector<Dim>>(values.data());
}

/// The grid spans the scene's [origin, origin + length] plus margin_min and margin_max cells beyond it on each
/// axis (paper/09_choices.md, 'Grid margins': room for free ends to move, and for their supports).
template <int Dim>
Grid<Dim> build_grid(const Scene& scene) {
  Vector<Dim> origin;
  std::array<int, Dim> cells{};
  for (int axis = 0; axis < Dim; ++axis) {
    origin[axis] = scene.origin[axis] - scene.margin_min[axis] * scene.spacing;
    cells[axis] = scene.cells[axis] + scene.margin_min[axis] + scene.margin_max[axis];
  }
  return Grid<Dim>(origin, scene.spacing, cells);
}

/// exact = "manufactured_small" | "manufactured_large": calls use(motion) with the motion of
/// mpm/exact/manufactured.hpp on the square [origin, origin + L]^2; nothing for any other scene.
template <class Use>
void with_manufactured_motion(const Scene& scene, Use use) {
  const exact::ManufacturedMaterial material{scene.length[0], scene.young_modulus, scene.poisson_ratio, scene.density};
  const std::vector<double>& a = scene.exact_displacement_amplitude;
  if (scene.exact == ExactKind::manufactured_small) use(exact::ManufacturedSmall(material, a[0]));
  if (scene.exact == ExactKind::manufactured_large) use(exact::ManufacturedLarge(material, a[0], a[1]));
}

/// The scene's distinct materials: [material] first, then each body's own that differs from those before it.
inline std::vector<MaterialSettings> distinct_materials(const Scene& scene) {
  std::vector<MaterialSettings> distinct{scene.material()};
  for (const BodySettings& body : scene.bodies)
    if (std::find(distinct.begin(), distinct.end(), body.material) == distinct.end()) distinct.push_back(body.material);
  return distinct;
}

/// The scene's materials, Eq. (3), in the order of distinct_materials.
inline std::vector<LinearElastic> materials_of(const Scene& scene) {
  std::vector<LinearElastic> materials;
  for (const MaterialSettings& m : distinct_materials(scene))
    materials.push_back({m.young_modulus, m.poisson_ratio, m.density});
  return materials;
}

/// The grid, the materials, the fixed faces and the body force b(x, X, t) of the scene.
template <int Dim>
Model<Dim> build_model(const Scene& scene) {
  Model<Dim> model;
  model.grid = build_grid<Dim>(scene);
  model.materials = materials_of(scene);
  for (const auto& fixed : scene.fixed) {
    // A fixed face is a rigid wall at the face of the scene's box [origin, origin + length]: its nodes and the
    // margin nodes beyond it are held, so a support that reaches past the wall (uGIMP, LME) meets rigid nodes,
    // as ghost nodes behind a wall are in GIMP practice.
    const int axis = fixed.axis(), face = scene.margin_min[axis] + (fixed.upper() ? scene.cells[axis] : 0);
    const int first = fixed.upper() ? face : 0, last = fixed.upper() ? model.grid.cells(axis) : face;
    for (int layer = first; layer <= last; ++layer) {
      const auto dofs = fixed_dofs_on_face(model.grid, Face{axis, layer}, fixed.components);
      model.fixed.insert(model.fixed.end(), dofs.begin(), dofs.end());
    }
  }
  // Each held component once: where two fixed faces meet (a corner, and the margin layers behind it) both list it,
  // and store_reactions, run twice on one component, would store the force it had already zeroed as its reaction.
  auto order = [](const FixedDof& a, const FixedDof& b) {
    return a.node != b.node ? a.node < b.node : a.component < b.component;
  };
  auto same = [](const FixedDof& a, const FixedDof& b) { return a.node == b.node && a.component == b.component; };
  std::sort(model.fixed.begin(), model.fixed.end(), order);
  model.fixed.erase(std::unique(model.fixed.begin(), model.fixed.end(), same), model.fixed.end());
  model.body_force.gravity.acceleration = to_vector<Dim>(scene.gravity);
  model.body_force.gravity.ramp_period = scene.ramp_period;
  model.body_force.field = body_force_field<Dim>(scene.formulas);
  if constexpr (Dim == 2)
    with_manufactured_motion(scene, [&](const auto& motion) {  // b(x, t) of the manufactured motion, Eq. (2)
      const Vector<2> origin = to_vector<2>(scene.origin);
      model.body_force.field = [motion, origin](const Vector<2>& x, const Vector<2>&, double t) {
        const exact::Pair b = motion.body_force({x[0] - origin[0], x[1] - origin[1]}, t);
        return Vector<2>(b[0], b[1]);
      };
    });
  return model;
}

/// Every body's particles: read from its file or seeded in its box (cut by its shape), then given the
/// [initial_field], the manufactured motion's initial velocity and the [[initial_velocity]] boxes, in that order.
/// \throws SceneError when a polygon holds no particle, or a formula is not finite at one.
template <int Dim>
Particles<Dim> build_particles(const Scene& scene, const Grid<Dim>& grid) {
  Particles<Dim> particles;
  const std::vector<MaterialSettings> distinct = distinct_materials(scene);
  for (size_t k = 0; k < scene.bodies.size(); ++k) {
    const BodySettings& body = scene.bodies[k];
    const int material = static_cast<int>(std::find(distinct.begin(), distinct.end(), body.material) - distinct.begin());
    const double density = body.material.density;
    for (const FileParticle& particle : body.particles) {  // a file's particles as read (mpm/io/particle_file.hpp)
      const double position[2] = {particle.x, particle.y}, velocity[2] = {particle.v_x, particle.v_y};
      particles.add(Eigen::Map<const Vector<Dim>>(position), particle.mass, density,
                    Eigen::Map<const Vector<Dim>>(velocity), Vector<Dim>::Constant(particle.half_length), material);
    }
    if (body.shape == BodyShape::Kind::file) continue;
    std::array<int, Dim> per_cell{};
    std::copy_n(body.particles_per_cell.begin(), Dim, per_cell.begin());
    const int before = particles.size();
    const int added = fill_box(grid, to_vector<Dim>(body.min), to_vector<Dim>(body.max), per_cell, density,
                               to_vector<Dim>(body.velocity), body.placement, particles, body_shape(body));
    std::fill(particles.material.begin() + before, particles.material.end(), material);
    if (added == 0)  // a polygon thinner than the particle spacing: its box holds seeds, none inside it
      throw scene_error(scene, "body[" + std::to_string(k) + "].vertices",
                        "the polygon holds no particle: make it wider than the particle spacing, or raise "
                        "particles_per_cell");
  }
  apply_scene_formulas<Dim>(scene.formulas, materials_of(scene), scene.control.end_time, particles);
  if constexpr (Dim == 2)
    with_manufactured_motion(scene, [&](const auto& motion) {
      for (int p = 0; p < particles.size(); ++p) {
        const Vector<2> X = particles.reference_position[p] - to_vector<2>(scene.origin);
        const exact::Pair v = motion.initial_velocity({X[0], X[1]});
        particles.velocity[p] = Vector<2>(v[0], v[1]);
      }
    });
  for (const auto& box : scene.initial_velocities) {  // applied in order: later boxes win
    const Vector<Dim> lower = to_vector<Dim>(box.min), upper = to_vector<Dim>(box.max);
    for (int p = 0; p < particles.size(); ++p) {
      const Vector<Dim>& x = particles.position[p];
      if ((x.array() >= lower.array()).all() && (x.array() <= upper.array()).all())
        particles.velocity[p] = to_vector<Dim>(box.velocity);
    }
  }
  return particles;
}

/// Index of the particle nearest to each observer's point at t = 0 (lowest index on ties).
template <int Dim>
std::vector<int> observed_particles(const Scene& scene, const Particles<Dim>& particles) {
  std::vector<int> observed;
  for (const auto& observer : scene.observers) {
    const Vector<Dim> point = to_vector<Dim>(observer.position);
    int nearest = 0;
    double best = std::numeric_limits<double>::infinity();
    for (int p = 0; p < particles.size(); ++p) {
      const double distance = (particles.position[p] - point).squaredNorm();
      if (distance < best * (1.0 - 1e-12)) best = distance, nearest = p;
    }
    observed.push_back(nearest);
  }
  return observed;
}

TEST_CASE("build_model: two fixed faces that meet hold each corner component once, and its reaction is its force") {
  // A 2 x 2 grid of cells (3 x 3 nodes, no margins), xmin and ymin fixed in x and y: 3 + 3 nodes minus the shared
  // corner, 5 nodes, 10 components; the corner node 0 is listed by both faces and must be held once.
  const std::string text =
      "dimension = 2\n[grid]\nlength = [2.0, 2.0]\ncells = [2, 2]\nmargin_min = [0, 0]\nmargin_max = [0, 0]\n"
      "[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0, 0.0]\nmax = [2.0, 2.0]\n[[fixed]]\nface = \"xmin\"\ncomponents = [\"x\", \"y\"]\n"
      "[[fixed]]\nface = \"ymin\"\ncomponents = [\"x\", \"y\"]\n[solver]\nend_time = 1.0\n";
  const Model<2> model = build_model<2>(read_scene(parse_scene_text(text, "corner.toml")));
  CHECK(model.fixed.size() == 10);
  CHECK(std::count_if(model.fixed.begin(), model.fixed.end(), [](const FixedDof& d) { return d.node == 0; }) == 2);
  std::vector<Vector<2>> force(model.grid.node_count(), Vector<2>(3.0, -4.0));
  std::vector<Vector<2>> reaction(model.grid.node_count(), Vector<2>::Zero());
  store_reactions(model.fixed, force, reaction);
  CHECK(reaction[0] == Vector<2>(3.0, -4.0));
  CHECK(force[0] == Vector<2>::Zero());
}

}  // namespace mpm::io
