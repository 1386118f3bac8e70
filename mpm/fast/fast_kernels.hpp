/// \file
/// The fast layer's tag, FastKernels, with the workspace of the layer's chunked sums (mpm/fast/scatter.hpp).
#pragma once

#include "mpm/core/kernels.hpp"
#include "mpm/fast/scatter.hpp"

namespace mpm::fast {

/// The fast kernels of mpm/fast/: threads and component forms (`solver.kernels = "fast"`, the default). Declared in
/// mpm::fast so that a call with it finds the overloads of mpm/fast/ (and only those) by its argument. A run holds
/// one (mpm::Simulation), and its integrator's step() hands it to every kernel: it carries the workspace of the
/// layer's scatters, which no type of the method's data (GridFields, Stencils, the shapes) carries.
struct FastKernels {
  static constexpr const char* name = "fast";
  /// The chunks' copies of the nodal fields and the nodes each chunk reaches; mutable: a workspace, whose
  /// contents between two scatters mean nothing to the method (its copies are zero).
  mutable ScatterScratch scratch;
};

}  // namespace mpm::fast
