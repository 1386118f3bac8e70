/// \file
/// Writes what a run produces into its output folder:
///   observers.csv        t, then per observer NAME.x, NAME.v_x, NAME.sigma_xx (2D adds y components)
///   energy.csv           t,kinetic,strain,total,momentum_x (2D adds momentum_y)
///   snapshot_NNNN.csv    every particle: id, position, velocity, stress, density
///   snapshot_NNNN.vtk    the same as legacy VTK polydata
///   snapshot_NNNN.vtp    the same as VTK XML polydata, listed with its time in
///   snapshots.pvd        the collection ParaView opens as a time series (mpm/io/vtk_collection.hpp)
/// and shows progress on stderr when stderr is a terminal. Every stream is checked: a file that
/// cannot be opened or written (no permission, disk full) raises OutputFailure naming it.
#pragma once
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

#include "mpm/io/scene.hpp"
#include "mpm/io/scene_resolved.hpp"
#include "mpm/io/vtk_collection.hpp"
#include "mpm/simulation.hpp"

namespace mpm::io {

/// \throws OutputFailure if `out` failed (opening, writing or flushing `path`).
inline void check_written(const std::ostream& out, const std::string& path) {
  if (!out) throw OutputFailure(path, errno != 0 ? std::strerror(errno) : "the stream failed");
}

/// Flushes and closes `out`, then checks it: a full disk shows only when the buffer is written.
inline void close_checked(std::ofstream& out, const std::string& path) {
  if (out.is_open()) out.close();
  check_written(out, path);
}

template <int Dim>
class RunWriter : public Monitor<Dim> {
 public:
  RunWriter(const std::string& folder, const Scene& scene, std::vector<int> observed)
      : folder_(folder), scene_(scene), observed_(std::move(observed)),
        observers_(folder + "/observers.csv"), energy_(folder + "/energy.csv"), collection_(folder + "/snapshots.pvd"),
        show_progress_(isatty(fileno(stderr))) {
    observers_ << std::setprecision(12) << "t";
    for (const auto& observer : scene.observers) {
      const std::string& name = observer.name;
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << name << "." << axis_name(axis);
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << name << ".v_" << axis_name(axis);
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << name << ".sigma_" << axis_name(axis) << axis_name(axis);
      if (Dim == 2) observers_ << "," << name << ".sigma_xy";
    }
    observers_ << "\n";
    energy_ << std::setprecision(12) << "t,kinetic,strain,total,momentum_x" << (Dim == 2 ? ",momentum_y" : "") << "\n";
    for (auto [stream, name] : {std::pair{&observers_, "/observers.csv"}, {&energy_, "/energy.csv"}}) {
      if (!*stream) errno = 0, stream->clear(), stream->open(folder_ + name);  // again, for the reason in errno
      check_written(*stream, folder_ + name);
    }
  }

  /// Closes the CSV histories. \throws OutputFailure if either could not be written in full.
  void finish() {
    close_checked(observers_, folder_ + "/observers.csv");
    close_checked(energy_, folder_ + "/energy.csv");
  }

  void sample(long, double time, const Particles<Dim>& particles, const Balances<Dim>& balances) override {
    observers_ << time;
    for (int p : observed_) {
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << particles.position[p][axis];
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << particles.velocity[p][axis];
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << particles.stress[p](axis, axis);
      if (Dim == 2) observers_ << "," << particles.stress[p](0, Dim - 1);
    }
    observers_ << "\n";
    energy_ << time << "," << balances.kinetic << "," << balances.strain << "," << balances.total();
    for (int axis = 0; axis < Dim; ++axis) energy_ << "," << balances.momentum[axis];
    energy_ << "\n";
    check_written(observers_, folder_ + "/observers.csv");
    check_written(energy_, folder_ + "/energy.csv");
  }

  void snapshot(int index, double time, const Particles<Dim>& particles) override {
    char stem[32];
    std::snprintf(stem, sizeof stem, "/snapshot_%04d", index);
    write_csv(folder_ + stem + ".csv", particles);
    write_vtk(folder_ + stem + ".vtk", time, particles);
    if (!write_vtp(folder_ + stem + ".vtp", particles))
      throw OutputFailure(folder_ + stem + ".vtp", errno != 0 ? std::strerror(errno) : "the stream failed");
    if (!collection_.add(time, std::string(stem + 1) + ".vtp"))
      throw OutputFailure(folder_ + "/snapshots.pvd", errno != 0 ? std::strerror(errno) : "the stream failed");
  }

  void progress(double time, double end_time) override {
    if (!show_progress_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_progress_ < std::chrono::milliseconds(200) && time < end_time) return;
    last_progress_ = now;
    std::fprintf(stderr, "\r%s: t = %.4g s of %.4g s (%3.0f%%)%s", scene_.title.c_str(), time, end_time,
                 100.0 * time / end_time, time >= end_time ? "\n" : "");
  }

 private:
  void write_csv(const std::string& path, const Particles<Dim>& particles) const {
    std::ofstream out(path);
    out << std::setprecision(12) << "id";
    for (int axis = 0; axis < Dim; ++axis) out << "," << axis_name(axis);
    for (int axis = 0; axis < Dim; ++axis) out << ",v_" << axis_name(axis);
    for (int axis = 0; axis < Dim; ++axis) out << ",sigma_" << axis_name(axis) << axis_name(axis);
    if (Dim == 2) out << ",sigma_xy,sigma_zz";
    out << ",density\n";
    for (int p = 0; p < particles.size(); ++p) {
      out << particles.id[p];
      for (int axis = 0; axis < Dim; ++axis) out << "," << particles.position[p][axis];
      for (int axis = 0; axis < Dim; ++axis) out << "," << particles.velocity[p][axis];
      for (int axis = 0; axis < Dim; ++axis) out << "," << particles.stress[p](axis, axis);
      if (Dim == 2) out << "," << particles.stress[p](0, 1) << "," << particles.stress_zz[p];
      out << "," << particles.density[p] << "\n";
    }
    close_checked(out, path);
  }

  void write_vtk(const std::string& path, double time, const Particles<Dim>& particles) const {
    std::ofstream out(path);
    const int count = particles.size();
    out << std::setprecision(12) << "# vtk DataFile Version 3.0\n" << scene_.title << " t = " << time
        << "\nASCII\nDATASET POLYDATA\nPOINTS " << count << " double\n";
    for (int p = 0; p < count; ++p) {
      const auto& x = particles.position[p];
      out << x[0] << " " << (Dim == 2 ? x[Dim - 1] : 0.0) << " 0\n";
    }
    out << "VERTICES " << count << " " << 2 * count << "\n";
    for (int p = 0; p < count; ++p) out << "1 " << p << "\n";
    out << "POINT_DATA " << count << "\nVECTORS velocity double\n";
    for (int p = 0; p < count; ++p) {
      const auto& v = particles.velocity[p];
      out << v[0] << " " << (Dim == 2 ? v[Dim - 1] : 0.0) << " 0\n";
    }
    out << "TENSORS stress double\n";
    for (int p = 0; p < count; ++p) {
      const auto& s = particles.stress[p];
      const double xy = Dim == 2 ? s(0, Dim - 1) : 0.0, yy = Dim == 2 ? s(Dim - 1, Dim - 1) : 0.0;
      out << s(0, 0) << " " << xy << " 0\n" << xy << " " << yy << " 0\n0 0 " << particles.stress_zz[p] << "\n";
    }
    out << "SCALARS density double 1\nLOOKUP_TABLE default\n";
    for (int p = 0; p < count; ++p) out << particles.density[p] << "\n";
    out << "SCALARS id int 1\nLOOKUP_TABLE default\n";
    for (int p = 0; p < count; ++p) out << particles.id[p] << "\n";
    close_checked(out, path);
  }

  std::string folder_;
  const Scene& scene_;
  std::vector<int> observed_;
  std::ofstream observers_, energy_;
  PvdCollection collection_;
  bool show_progress_;
  std::chrono::steady_clock::time_point last_progress_{};
};

/// run.json: the resolved scene (every key, defaults filled in), the step statistics, the speed and, for LME, Newton statistics.
/// \throws OutputFailure if it cannot be written.
inline void write_run_json(const std::string& path, const Scene& scene, const RunSummary& summary,
                           const std::string& status, int particle_count) {
  std::ofstream out(path);
  out << std::setprecision(12) << "{\n"
      << "  \"status\": \"" << status << "\",\n"
      << "  \"scene\": " << resolved_json(scene) << ",\n"
      << "  \"particles\": " << particle_count << ",\n"
      << "  \"steps\": " << summary.steps << ",\n"
      << "  \"final_time\": " << summary.final_time << ",\n"
      << "  \"smallest_time_step\": " << summary.smallest_time_step << ",\n"
      << "  \"largest_time_step\": " << summary.largest_time_step << ",\n"
      << "  \"wall_seconds\": " << summary.wall_seconds << ",\n"
      << "  \"particle_steps_per_second\": " << summary.particle_steps_per_second << ",\n"
      << "  \"largest_mass_error\": " << summary.largest_mass_error << ",\n"
      << "  \"neighbours_mean\": " << summary.shape.neighbours_mean() << ",\n"
      << "  \"neighbours_max\": " << summary.shape.neighbours_max() << ",\n"
      << "  \"newton_iterations_mean\": " << summary.shape.newton_iterations_mean() << ",\n"
      << "  \"newton_iterations_max\": " << summary.shape.newton_iterations_max() << ",\n"
      << "  \"threads\": " << summary.threads << ",\n"
      << "  \"phase_seconds\": {";
  for (int phase = 0; phase < phase_count; ++phase)
    out << (phase ? ", " : "") << "\"" << phase_name(phase) << "\": " << summary.phase_seconds[phase];
  out << "}\n"
      << "}\n";
  close_checked(out, path);
}

}  // namespace mpm::io
