/// \file
/// The particle-parallel loops of the time step, on every core (OpenMP), deterministic.
///
/// Each loop splits [0, count) into one contiguous block per thread, in order. A sum over the
/// particles (a reduction, or the scatter of P2G into the nodes) is formed block by block and the
/// blocks' sums are then added in block order: a run repeats bit for bit with the same number of
/// threads, and with one thread it is the plain serial loop, bit for bit. Loops over fewer than
/// `parallel_threshold` items run on the calling thread alone (starting threads would cost more).
/// The number of threads is the calling thread's OpenMP setting (use_threads), so that the
/// verification suites can run several simulations side by side, each with its own count.
#pragma once
#include <doctest/doctest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include "mpm/core/types.hpp"

namespace mpm {

inline constexpr int max_threads = 64;
/// Fewer items than this: one thread (starting a team of threads costs a few microseconds, the
/// work of a linear 1D transfer over 1000 particles about as much).
inline constexpr int parallel_threshold = 1024;

/// The machine's cores (at most max_threads).
inline int available_cores() { return std::clamp(omp_get_num_procs(), 1, max_threads); }

/// Sets the threads of the loops below for the calling thread; 0 means every core.
inline void use_threads(int threads) { omp_set_num_threads(threads > 0 ? std::min(threads, max_threads) : available_cores()); }

/// The threads a loop over `count` items will use.
inline int threads_for(int count) { return count >= parallel_threshold ? std::min(omp_get_max_threads(), max_threads) : 1; }

/// [begin, end) of block `block` of `blocks` equal contiguous blocks of [0, count).
struct Block {
  int begin, end;
};
inline Block block_of(int count, int block, int blocks) {
  return {static_cast<int>(static_cast<long>(count) * block / blocks),
          static_cast<int>(static_cast<long>(count) * (block + 1) / blocks)};
}

/// The calling thread's index among the threads of the loop it runs in (parallel_for_blocks sets it;
/// 0 outside such a loop): a per-thread slot for counters (ShapeDiagnostics) read without a library
/// call. omp_get_thread_num() once per stencil cost a linear stencil phase 30 % of its time.
inline int& worker_index() {
  static thread_local int index = 0;
  return index;
}

/// body(thread, block) for each thread's block of [0, count); worker_index() is `thread` meanwhile.
/// body must not throw.
template <class Body>
void parallel_for_blocks(int count, Body body) {
  const int threads = threads_for(count);
  if (threads == 1) {  // no parallel region: its start-up costs more than a small loop
    worker_index() = 0;
    return body(0, Block{0, count});
  }
#pragma omp parallel num_threads(threads)
  {
    const int thread = omp_get_thread_num();
    worker_index() = thread;
    body(thread, block_of(count, thread, omp_get_num_threads()));
  }
}

/// body(p) for every p in [0, count), each block of p on its own thread. body must not throw.
template <class Body>
void parallel_for(int count, Body body) {
  parallel_for_blocks(count, [&](int, Block block) {
    for (int p = block.begin; p < block.end; ++p) body(p);
  });
}

/// The sum over p in [0, count) of what body(p, partial) adds into `partial`, formed per block from
/// `zero` and combined in block order by combine(total, partial).
template <class T, class Body, class Combine>
T parallel_sum(int count, const T& zero, Body body, Combine combine) {
  const int threads = threads_for(count);
  if (threads == 1) {  // no parallel region (see parallel_for_blocks)
    T sum = zero;
    for (int p = 0; p < count; ++p) body(p, sum);
    return sum;
  }
  std::array<T, max_threads> partial;
  int blocks = 1;
#pragma omp parallel num_threads(threads)
  {
    const int thread = omp_get_thread_num();
    const Block block = block_of(count, thread, omp_get_num_threads());
    T sum = zero;
    for (int p = block.begin; p < block.end; ++p) body(p, sum);
    partial[thread] = sum;
    if (thread == 0) blocks = omp_get_num_threads();
  }
  T total = partial[0];
  for (int block = 1; block < blocks; ++block) combine(total, partial[block]);
  return total;
}

inline void set_zero(double& value) { value = 0.0; }
template <class Derived>
void set_zero(Eigen::MatrixBase<Derived>& value) { value.setZero(); }

/// A nodal field that the particles scatter into (P2G), with its zeroed copies, one per thread
/// beyond the first, each the size of the field.
template <class T>
struct ScatterTarget {
  std::vector<T>& field;
  std::vector<std::vector<T>>& copies;
};

/// Adds the copies of `target` to its field node by node for the nodes of `block`, in thread
/// order, and zeroes them again.
template <class T>
void gather_copies(ScatterTarget<T>& target, int copies_used, Block block) {
  for (int copy = 0; copy < copies_used; ++copy)
    for (int node = block.begin; node < block.end; ++node) {
      target.field[node] += target.copies[copy][node];
      set_zero(target.copies[copy][node]);
    }
}

/// Scatter into the nodes (P2G) for particles [0, count), into one or more nodal fields in the same
/// pass over the particles: body(p, field...) adds particle p's share into field[I] of each target for
/// the nodes I of its stencil. Thread 0 adds into the fields themselves, thread t > 0 into their
/// copies[t - 1]; the copies are then added to the fields node by node in thread order and zeroed
/// again. Without copies it is the serial loop.
template <class Body, class... T>
void scatter_to_nodes(int count, Body body, ScatterTarget<T>... targets) {
  const int threads = std::min({threads_for(count), (static_cast<int>(targets.copies.size()) + 1)...});
  if (threads == 1) {  // no parallel region (see parallel_for_blocks)
    for (int p = 0; p < count; ++p) body(p, targets.field.data()...);
    return;
  }
  int blocks = 1;
#pragma omp parallel num_threads(threads)
  {
    const int thread = omp_get_thread_num();
    const Block block = block_of(count, thread, omp_get_num_threads());
    for (int p = block.begin; p < block.end; ++p)
      body(p, (thread == 0 ? targets.field.data() : targets.copies[thread - 1].data())...);
    if (thread == 0) blocks = omp_get_num_threads();
  }
  if (blocks == 1) return;
  // The nodes of the first target: every target is a nodal field of the same grid.
  const int nodes = static_cast<int>(std::get<0>(std::forward_as_tuple(targets...)).field.size());
#pragma omp parallel num_threads(blocks)
  {
    const Block block = block_of(nodes, omp_get_thread_num(), omp_get_num_threads());
    (gather_copies(targets, blocks - 1, block), ...);
  }
}

/// The same for one field: body(p, field).
template <class T, class Body>
void scatter_to_nodes(int count, std::vector<T>& field, std::vector<std::vector<T>>& copies, Body body) {
  scatter_to_nodes(count, body, ScatterTarget<T>{field, copies});
}

TEST_CASE("Parallel loops: blocks cover every item once, sums and scatters equal the serial loop") {
  for (int count : {0, 1, 7, 5000})
    for (int blocks : {1, 2, 3, 8}) {
      int covered = 0;
      for (int b = 0; b < blocks; ++b) {
        const Block block = block_of(count, b, blocks);
        CHECK(block.begin == (b == 0 ? 0 : block_of(count, b - 1, blocks).end));
        covered += block.end - block.begin;
      }
      CHECK(covered == count);
    }
  // Integers: any order gives the same sum, so the parallel result must equal the formula exactly.
  const int count = 10 * parallel_threshold;
  use_threads(2);
  const long sum = parallel_sum(count, 0L, [](int p, long& s) { s += p; }, [](long& a, long b) { a += b; });
  CHECK(sum == long(count) * (count - 1) / 2);
  std::vector<double> field(10, 0.0);
  std::vector<std::vector<double>> copies(1, std::vector<double>(10, 0.0));
  scatter_to_nodes(count, field, copies, [](int p, double* f) { f[p % 10] += 1.0; });
  for (int node = 0; node < 10; ++node) CHECK(field[node] == count / 10);
  for (double left : copies[0]) CHECK(left == 0.0);
  // Two fields in one pass, of different types: each gets its own sum, the copies are left zero.
  std::vector<Vector<2>> vectors(10, Vector<2>::Zero());
  std::vector<std::vector<Vector<2>>> vector_copies(1, std::vector<Vector<2>>(10, Vector<2>::Zero()));
  scatter_to_nodes(
      count,
      [](int p, double* f, Vector<2>* g) {
        f[p % 10] += 2.0;
        g[p % 5] += Vector<2>(1.0, double(p % 3));
      },
      ScatterTarget<double>{field, copies}, ScatterTarget<Vector<2>>{vectors, vector_copies});
  for (int node = 0; node < 10; ++node) CHECK(field[node] == 3 * (count / 10));
  long ones = 0, residues = 0;  // the sums over p with p % 5 == 0: count / 5 ones, and sum of p % 3
  for (int p = 0; p < count; p += 5) ++ones, residues += p % 3;
  CHECK(vectors[0] == Vector<2>(double(ones), double(residues)));
  for (const Vector<2>& left : vector_copies[0]) CHECK(left.isZero(0.0));
  for (double left : copies[0]) CHECK(left == 0.0);
  // Inside parallel_for_blocks each block's thread finds its own index in worker_index().
  std::array<int, max_threads> seen;
  seen.fill(-1);
  parallel_for_blocks(count, [&](int thread, Block) { seen[thread] = worker_index(); });
  const int used = threads_for(count);
  for (int thread = 0; thread < used; ++thread) CHECK(seen[thread] == thread);
  use_threads(0);
}

}  // namespace mpm
