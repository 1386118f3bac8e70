/// \file
/// From validated scene settings to the objects of a run: grid, model, particles, observers.
#pragma once
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include "mpm/exact/manufactured.hpp"

#include "mpm/io/scene.hpp"
#include "mpm/model.hpp"
#include "mpm/particles/seeding.hpp"

namespace mpm::io {

template <int Dim>
Vector<Dim> to_vector(const std::vector<double>& values) {
  Vector<Dim> vector;
  for (int axis = 0; axis < Dim; ++axis) vector[axis] = values[axis];
  return vector;
}

/// The grid spans the scene's [origin, origin + length] plus margin_min and margin_max cells
/// beyond it on each axis (paper/09_choices.md, 'Grid margins': room for free ends to move, and for their supports).
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

/// exact = "manufactured_small" | "manufactured_large": the motion of mpm/exact/manufactured.hpp on the square
/// [origin, origin + L]^2, as a function of the point measured from the origin. The scene gives its body
/// force and initial velocity (it refuses [body_force] and initial velocities of its own).
struct ManufacturedMotion {
  std::shared_ptr<const exact::ManufacturedSmall> small;
  std::shared_ptr<const exact::ManufacturedLarge> large;

  exact::Pair body_force(const exact::Pair& x, double t) const { return small ? small->body_force(x, t) : large->body_force(x, t); }
  exact::Pair initial_velocity(const exact::Pair& X) const { return small ? small->initial_velocity(X) : large->initial_velocity(X); }
};

/// The scene's manufactured motion; nullopt for any other exact solution.
inline std::optional<ManufacturedMotion> manufactured_motion(const Scene& scene) {
  if (scene.exact != ExactKind::manufactured_small && scene.exact != ExactKind::manufactured_large) return std::nullopt;
  const exact::ManufacturedMaterial material{scene.length[0], scene.young_modulus, scene.poisson_ratio, scene.density};
  const std::vector<double>& a = scene.exact_displacement_amplitude;
  ManufacturedMotion motion;
  if (scene.exact == ExactKind::manufactured_small) motion.small = std::make_shared<exact::ManufacturedSmall>(material, a[0]);
  else motion.large = std::make_shared<exact::ManufacturedLarge>(material, a[0], a[1]);
  return motion;
}

/// The scene's materials: [material] first, then each body's own material that differs from those before
/// it, in the order of the bodies (body_material gives a body's index).
inline std::vector<LinearElastic> materials_of(const Scene& scene) {
  std::vector<MaterialSettings> distinct{{scene.young_modulus, scene.poisson_ratio, scene.density}};
  for (const BodySettings& body : scene.bodies)
    if (std::find(distinct.begin(), distinct.end(), body.material) == distinct.end()) distinct.push_back(body.material);
  std::vector<LinearElastic> materials;
  for (const MaterialSettings& material : distinct) materials.push_back({material.young_modulus, material.poisson_ratio, material.density});
  return materials;
}

/// The index in materials_of(scene) of body k's material.
inline int body_material(const Scene& scene, size_t k) {
  const std::vector<LinearElastic> materials = materials_of(scene);
  const MaterialSettings& wanted = scene.bodies[k].material;
  for (size_t m = 0; m < materials.size(); ++m)
    if (MaterialSettings{materials[m].young_modulus, materials[m].poisson_ratio, materials[m].density} == wanted) return static_cast<int>(m);
  return 0;  // unreachable: materials_of lists every body's material
}

template <int Dim>
Model<Dim> build_model(const Scene& scene) {
  Model<Dim> model;
  model.grid = build_grid<Dim>(scene);
  model.materials = materials_of(scene);
  for (const auto& fixed : scene.fixed) {
    // A fixed face is a rigid wall at the face of the scene's box [origin, origin + length]: its
    // nodes and the margin nodes beyond it are held, so a support that reaches past the wall
    // (uGIMP, LME) meets rigid nodes, as ghost nodes behind a wall are in GIMP practice.
    const int axis = fixed.axis(), face = scene.margin_min[axis] + (fixed.upper() ? scene.cells[axis] : 0);
    const int first = fixed.upper() ? face : 0, last = fixed.upper() ? model.grid.cells(axis) : face;
    for (int layer = first; layer <= last; ++layer) {
      const auto dofs = fixed_dofs_on_face(model.grid, Face{axis, layer}, fixed.components);
      model.fixed.insert(model.fixed.end(), dofs.begin(), dofs.end());
    }
  }
  model.body_force.gravity.acceleration = to_vector<Dim>(scene.gravity);
  model.body_force.gravity.ramp_period = scene.ramp_period;
  model.body_force.field = body_force_field<Dim>(scene.formulas);
  if constexpr (Dim == 2) {
    if (const auto motion = manufactured_motion(scene)) {  // b(x, t) of the manufactured motion, Eq. (2)
      const Vector<2> origin(scene.origin[0], scene.origin[1]);
      model.body_force.field = [motion = *motion, origin](const Vector<2>& x, const Vector<2>&, double t) {
        const exact::Pair b = motion.body_force({x[0] - origin[0], x[1] - origin[1]}, t);
        return Vector<2>(b[0], b[1]);
      };
    }
  }
  return model;
}

/// uGIMP needs each particle's half-length l_p in (0, h] (mpm/shape/ugimp.hpp); a seeded body's particles
/// always fit, a file's may not. \throws SceneError located at the particle's row of the file.
inline void check_file_particle_for_ugimp(const Scene& scene, const BodySettings& body, const FileParticle& particle,
                                          double half_length) {
  if (scene.shape != ShapeKind::ugimp || half_length / scene.spacing <= 1.0) return;  // as UgimpShape::set_half_length tests it
  namespace fs = std::filesystem;
  const fs::path path = fs::path(body.file).is_absolute() ? fs::path(body.file) : fs::path(scene.file).parent_path() / body.file;
  std::ostringstream message;
  message << "the particle's half-length l_p = V^(1/" << scene.dimension << ") / 2 = " << half_length
          << " m exceeds the cell size h = " << scene.spacing
          << " m; uGIMP needs 0 < l_p <= h: give smaller particles, a coarser grid, or another shape";
  throw SceneError(path.string(), particle.line, "volume", message.str());
}

template <int Dim>
Particles<Dim> build_particles(const Scene& scene, const Grid<Dim>& grid) {
  Particles<Dim> particles;
  for (size_t k = 0; k < scene.bodies.size(); ++k) {
    const BodySettings& body = scene.bodies[k];
    const int material = body_material(scene, k);
    const double density = body.material.density;
    if (body.shape == BodyShape::Kind::file) {  // its particles as read (mpm/io/particle_file.hpp); l_p = V^(1/Dim) / 2 per axis
      for (const FileParticle& particle : body.particles) {
        const double position[2] = {particle.x, particle.y}, velocity[2] = {particle.v_x, particle.v_y};
        Vector<Dim> x, v;
        for (int axis = 0; axis < Dim; ++axis) x[axis] = position[axis], v[axis] = velocity[axis];
        const double half = 0.5 * std::pow(particle.mass / density, 1.0 / Dim);
        check_file_particle_for_ugimp(scene, body, particle, half);
        particles.add(x, particle.mass, density, v, Vector<Dim>::Constant(half), material);
      }
      continue;
    }
    std::array<int, Dim> per_cell{};
    for (int axis = 0; axis < Dim; ++axis) per_cell[axis] = body.particles_per_cell[axis];
    const int before = particles.size();
    const int added = fill_box(grid, to_vector<Dim>(body.min), to_vector<Dim>(body.max), per_cell, density, to_vector<Dim>(body.velocity),
                               body.placement, particles, body_shape(body));
    std::fill(particles.material.begin() + before, particles.material.end(), material);
    if (added == 0)  // a polygon thinner than the particle spacing: its box holds seeds, none inside it
      throw scene_error(scene, "body[" + std::to_string(k) + "].vertices",
                        "the polygon holds no particle: make it wider than the particle spacing, or raise particles_per_cell");
  }
  apply_scene_formulas<Dim>(scene.formulas, materials_of(scene),
                            scene.control.end_time, particles);  // [initial_field], before the boxes
  if constexpr (Dim == 2) {
    if (const auto motion = manufactured_motion(scene))
      for (int p = 0; p < particles.size(); ++p) {
        const Vector<2>& X = particles.reference_position[p];
        const exact::Pair v = motion->initial_velocity({X[0] - scene.origin[0], X[1] - scene.origin[1]});
        particles.velocity[p] = Vector<2>(v[0], v[1]);
      }
  }
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

}  // namespace mpm::io
