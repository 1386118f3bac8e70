/// \file
/// The two layers of kernels a run can take, chosen once per run as a type (`solver.kernels`, mpm/run.hpp's
/// with_kernels): the integrators' step() calls each transfer with one of these tags, and overload resolution
/// picks the kernel of that layer.
///
/// - ReferenceKernels: the kernels paper/ and the Doxygen pages show, in mpm/transfer/ and mpm/grid/: each a
///   plain serial loop over the particles and their stencil nodes, in the paper's symbols.
/// - fast::FastKernels (the default): the same equations in mpm/fast/, run on every core (mpm/core/parallel.hpp,
///   mpm/fast/scatter.hpp) and in component forms; each is tested against its reference on random states. Defined in
///   mpm/fast/fast_kernels.hpp: it holds the workspace of the fast layer's scatters, so a run holds one and its
///   integrator's step() takes it as its first argument.
#pragma once
#include <type_traits>

namespace mpm {

/// The reference kernels: the plain serial loops of mpm/transfer/ (`solver.kernels = "reference"`).
struct ReferenceKernels {
  static constexpr const char* name = "reference";
};

namespace fast {
struct FastKernels;  // mpm/fast/fast_kernels.hpp
}  // namespace fast

using fast::FastKernels;

/// The lab build (`make lab`, build type Lab, README "Editing a kernel"): the reference kernels alone, at -O1, so that a
/// student's edit of a kernel rebuilds the command-line program in seconds; every run and every stability analysis
/// then takes the reference kernels, and a scene that asks for the fast ones is refused (solver.kernels).
#ifdef MPM_LAB
#ifndef __OPTIMIZE__  // GCC and Clang define it from -O1 up: a lab at -O0 runs the Dyka bar some 300x slower
#error "the lab build (MPM_LAB) must be optimised: CMAKE_CXX_FLAGS_LAB (MPM_LAB_FLAGS) holds no -O level"
#endif
inline constexpr bool lab_build = true;
#else
inline constexpr bool lab_build = false;
#endif

/// The layer of the stability analyses (mpm/stability.hpp): the fast one, the reference one in the lab build.
using AnalysisKernels = std::conditional_t<lab_build, ReferenceKernels, FastKernels>;

}  // namespace mpm
