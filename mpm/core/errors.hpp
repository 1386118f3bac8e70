/// \file
/// The three ways a run can fail, and how each is told to the user.
///
/// - SceneError: the input is wrong. Raised before anything runs; the CLI prints
///   `error: FILE:LINE: KEY: what is wrong and what is allowed` and exits with code 2.
/// - InputError: another input is wrong (a file named on the command line, an output folder); exit code 2.
/// - OutputFailure: a file of the output cannot be written; exit code 3, the file named.
/// - SimulationFailure: the method failed during the run (NaN, a particle leaving the grid,
///   an LME Newton iteration that does not converge, unbounded energy growth). The CLI prints
///   one line with step, time, particle, position and cause, and exits with code 3.
#pragma once
#include <sstream>
#include <stdexcept>
#include <string>

namespace mpm {

struct SceneError : std::runtime_error {
  SceneError(std::string file_, int line_, std::string key_, const std::string& what_is_wrong)
      : std::runtime_error(what_is_wrong), file(std::move(file_)), line(line_), key(std::move(key_)) {}
  std::string file;
  int line;  ///< 0 for a key the file does not write (its default), or the file as a whole (key "")
  std::string key;

  /// `error: FILE:LINE: KEY: what`; `error: FILE: KEY: what` for a key not written; `error: FILE: what`.
  std::string message() const {
    std::ostringstream out;
    out << "error: " << file << ":";
    if (line > 0) out << line << ":";
    if (!key.empty()) out << " " << key << ":";
    out << " " << what();
    return out.str();
  }
};

/// An input other than the scene is wrong (a file given on the command line, an output folder holding a
/// link where a file goes). The CLI prints `error: PATH: what is wrong` and exits with code 2.
struct InputError : std::runtime_error {
  InputError(std::string path_, const std::string& what_is_wrong) : std::runtime_error(what_is_wrong), path(std::move(path_)) {}
  std::string path;
  std::string message() const { return "error: " + path + ": " + what(); }
};

/// A file of the run's output could not be written (no permission, disk full). The CLI prints
/// `error: FILE: cannot write: REASON` and exits with code 3; it never says "wrote".
struct OutputFailure : std::runtime_error {
  OutputFailure(std::string path_, const std::string& reason)
      : std::runtime_error(reason), path(std::move(path_)) {}
  std::string path;
  std::string message() const { return "error: " + path + ": cannot write: " + what(); }
};

/// Raised by a shape function that cannot give a trustworthy stencil for a particle.
struct ShapeFailure : std::runtime_error {
  ShapeFailure(int particle_, const std::string& cause) : std::runtime_error(cause), particle(particle_) {}
  int particle;
};

struct SimulationFailure : std::runtime_error {
  SimulationFailure(long step_, double time_, int particle_, std::string position_, const std::string& cause)
      : std::runtime_error(cause), step(step_), time(time_), particle(particle_), position(std::move(position_)) {}
  long step;
  double time;
  int particle;          ///< -1 when the failure is not tied to one particle
  std::string position;  ///< "(x, y)" of that particle, empty otherwise

  std::string message() const {
    std::ostringstream out;
    out.precision(9);
    out << "failure: step " << step << ", t = " << time << " s";
    if (particle >= 0) out << ", particle " << particle << " at " << position;
    out << ": " << what();
    return out.str();
  }
};

}  // namespace mpm
