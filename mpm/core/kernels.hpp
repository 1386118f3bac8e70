/// \file
/// The two layers of kernels a run can take, chosen once per run as a type (`solver.kernels`, mpm/run.hpp's
/// with_kernels): the integrators' step() calls each transfer with one of these tags, and overload resolution
/// picks the kernel of that layer.
///
/// - ReferenceKernels: the kernels paper/ and the Doxygen pages show, in mpm/transfer/ and mpm/grid/: each a
///   plain serial loop over the particles and their stencil nodes, in the paper's symbols.
/// - fast::FastKernels (the default): the same equations in mpm/fast/, run on every core (mpm/core/parallel.hpp,
///   mpm/core/scatter.hpp) and in component forms; each is tested against its reference on random states.
#pragma once

namespace mpm {

/// The reference kernels: the plain serial loops of mpm/transfer/ (`solver.kernels = "reference"`).
struct ReferenceKernels {
  static constexpr const char* name = "reference";
};

namespace fast {
/// The fast kernels of mpm/fast/: threads and component forms (`solver.kernels = "fast"`, the default). Declared in
/// mpm::fast so that a call with this tag finds the overloads of mpm/fast/ (and only those) by its argument.
struct FastKernels {
  static constexpr const char* name = "fast";
};
}  // namespace fast

using fast::FastKernels;

}  // namespace mpm
