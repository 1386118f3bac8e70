/// \file
/// The index of the thread that runs the current chunk of a parallel loop (mpm/core/parallel.hpp sets it): a slot for
/// counters kept per thread (ShapeDiagnostics), so that a reference kernel can count without knowing of threads.
#pragma once

namespace mpm {

/// 0 for the calling thread (and always in a serial run), 1, 2, ... for the workers of the fast layer's team; read
/// without a function call.
inline int& worker_index() {
  static thread_local int index = 0;
  return index;
}

}  // namespace mpm
