/// \file
/// The fast layer's particle-to-grid scatter (P2G) on the machine's cores, with nodal sums that do not depend on
/// how many threads run them (the chunks and their model: mpm/core/parallel.hpp), and its workspace, ScatterScratch.
///
/// Chunk 0 of the particles adds into the nodal fields themselves; chunk c > 0 adds, from zero, into a copy
/// of the fields that covers only its window, the nodes its stencils reach (fast::compute_stencils notes them,
/// mpm/fast/fast_stencils.hpp). The copies are then added to the fields node by node in chunk order, and zeroed
/// again. The copies of all chunks lie one after another in one buffer per field, allocated by the first scatter
/// of a run with room for max_chunks - 1 whole grids (copy_room): with the particles in spatial order the windows
/// take about one
/// grid together, however many chunks there are. Should they need more room (particles in no spatial
/// order), the scatter adds in max_chunks groups of consecutive chunks instead, each group's window the
/// union of its chunks': a group's sum is then formed over all its particles from zero. Which way a
/// scatter adds depends on the windows, which depend on the particles only: the bits stay the same on any
/// number of threads either way.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <random>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "mpm/core/parallel.hpp"
#include "mpm/core/types.hpp"

namespace mpm::fast {

inline void set_zero(double& value) { value = 0.0; }
template <class Derived>
void set_zero(Eigen::MatrixBase<Derived>& value) { value.setZero(); }

/// For each chunk of the particles, the nodes [begin, end) its stencils reach (fast::compute_stencils notes them).
/// A list of another length than the chunks counts as every chunk reaching every node.
using ChunkNodes = std::vector<Range>;
inline constexpr Range all_nodes{0, 1 << 30};

/// How one scatter adds: `parts` parts of consecutive chunks (one chunk each, or max_chunks groups), part
/// g > 0 into the copy of nodes window[g], which starts at offset[g] of each field's buffer.
struct ScatterPlan {
  int chunks = 0, parts = 0;
  std::vector<Range> window;  ///< per part: its nodes, within [0, nodes)
  std::vector<long> offset;   ///< per part, and one past the last: where its copy starts in the buffer
  long room_used() const { return offset[parts]; }
};

/// The values of each field's buffer of copies for scatters over `count` particles into `nodes` nodes:
/// max_chunks - 1 grids at most, one per chunk beyond the first.
inline long copy_room(int count, int nodes) {
  return static_cast<long>(std::min(chunks_of(count), max_chunks) - 1) * nodes;
}

/// Lays the parts' windows out in the buffer, in part order: part g's copy at offset[g] = the larger of
/// where part g - 1's ends and window[g].begin, so that the copy indexed by node (from its start less
/// window[g].begin) never points before the buffer. Each window within one grid, so max_chunks parts need
/// at most (max_chunks - 1) grids: the copy of part g ends by g grids.
template <class WindowOf>
void lay_out(int parts, WindowOf window_of, ScatterPlan& plan) {
  plan.parts = parts;
  plan.window.resize(parts);
  plan.offset.resize(parts + 1);
  plan.offset[0] = plan.offset[1] = 0;
  for (int part = 0; part < parts; ++part) {
    plan.window[part] = window_of(part);
    if (part == 0) continue;
    plan.offset[part] = std::max(plan.offset[part], static_cast<long>(plan.window[part].begin));
    plan.offset[part + 1] = plan.offset[part] + (plan.window[part].end - plan.window[part].begin);
  }
}

/// The plan of a scatter over `count` particles into `nodes` nodes, from the nodes each chunk reached:
/// one part per chunk when their copies fit copy_room, else max_chunks groups of chunks.
inline void plan_scatter(int count, int nodes, const ChunkNodes& reached, ScatterPlan& plan) {
  plan.chunks = chunks_of(count);
  const bool known = static_cast<int>(reached.size()) == plan.chunks;
  auto window_of_chunks = [&](Range chunks) {  // the union of the chunks' windows, within [0, nodes)
    Range window{nodes, 0};
    for (int chunk = chunks.begin; chunk < chunks.end; ++chunk) {
      const Range of = known ? reached[chunk] : all_nodes;
      if (of.begin < of.end) window = {std::min(window.begin, of.begin), std::max(window.end, of.end)};
    }
    window = {std::max(window.begin, 0), std::min(window.end, nodes)};
    return window.begin < window.end ? window : Range{0, 0};
  };
  lay_out(plan.chunks, [&](int chunk) { return window_of_chunks(Range{chunk, chunk + 1}); }, plan);
  if (plan.room_used() <= copy_room(count, nodes)) return;
  const int groups = std::min(plan.chunks, max_chunks);
  lay_out(groups, [&](int group) { return window_of_chunks(part_of(plan.chunks, groups, group)); }, plan);
}

/// A nodal field that the particles scatter into (P2G), with its buffer of zeroed copies (ScatterScratch::copies).
template <class T>
struct ScatterTarget {
  std::vector<T>& field;
  std::vector<T>& copies;
};

/// The buffer of copies of one field for scatters over `count` particles into `nodes` nodes, zeroed.
template <class T>
void prepare_copies(std::vector<T>& copies, int count, int nodes, const T& zero) {
  copies.assign(copy_room(count, nodes), zero);
}

/// Where part `part` of a scatter adds: the field, or its copy indexed by node number.
template <class T>
T* part_target(ScatterTarget<T>& target, const ScatterPlan& plan, int part) {
  return part == 0 ? target.field.data() : target.copies.data() + (plan.offset[part] - plan.window[part].begin);
}

/// Adds copies 1, 2, ... of `target` to its field, in part order, on the nodes of `block`, and zeroes them.
template <class T>
void add_copies(ScatterTarget<T>& target, const ScatterPlan& plan, Range block) {
  for (int part = 1; part < plan.parts; ++part) {
    T* copy = part_target(target, plan, part);
    const int end = std::min(block.end, plan.window[part].end);
    for (int node = std::max(block.begin, plan.window[part].begin); node < end; ++node) {
      target.field[node] += copy[node];
      set_zero(copy[node]);
    }
  }
}

/// Most blocks of nodes the copies are added in (on the team): each block looks at every part's window.
inline constexpr int most_node_blocks = 256;

/// Scatter into the nodes (P2G) for particles [0, count), into one or more nodal fields in one pass
/// over the particles: body(p, field...) adds particle p's share into field[I] of each target for the
/// nodes I of its stencil. The parts of plan_scatter add into the fields and into their copies, which are
/// then added to the fields node by node in part order (on the team too, by blocks of nodes) and zeroed
/// again. `work_per_item`: the stencil entries per particle; `reached`: the nodes each chunk's stencils reach;
/// `plan`: where the plan is formed (the workers read it).
template <class Body, class... T>
void scatter_to_nodes(int count, long work_per_item, const ChunkNodes& reached, ScatterPlan& plan, Body body,
                      ScatterTarget<T>... targets) {
  // The nodes of the first target: every target is a nodal field of the same grid.
  const int nodes = static_cast<int>(std::get<0>(std::forward_as_tuple(targets...)).field.size());
  plan_scatter(count, nodes, reached, plan);
  if (((static_cast<long>(targets.copies.size()) < plan.room_used()) || ...))
    throw std::logic_error("scatter_to_nodes: too few copies");
  for_each_part(plan.parts, count * work_per_item, [&](int part) {
    const Range chunks = part_of(plan.chunks, plan.parts, part);
    const int end = chunk_of(count, chunks.end - 1).end;
    for (int p = chunk_of(count, chunks.begin).begin; p < end; ++p) body(p, part_target(targets, plan, part)...);
  });
  if (plan.parts == 1) return;
  const int blocks = std::min(chunks_of(nodes), most_node_blocks);
  for_each_part(blocks, plan.room_used() * static_cast<long>(sizeof...(T)), [&](int block) {
    (add_copies(targets, plan, part_of(nodes, blocks, block)), ...);
  });
}

/// The fast layer's workspace for its chunked sums, held by FastKernels (one per run, mpm/fast/fast_kernels.hpp)
/// and by no type of the method's data: the buffers of copies that the scatters' chunks add into, the nodes each
/// chunk of particles reaches and the plan of the current scatter. Between two scatters every copy is zero.
class ScatterScratch {
 public:
  ScatterScratch() = default;
  /// Not copied: a kernel that took the fast layer by value would copy the buffers at every call.
  ScatterScratch(const ScatterScratch&) = delete;
  ScatterScratch& operator=(const ScatterScratch&) = delete;
  ScatterScratch(ScatterScratch&&) = default;
  ScatterScratch& operator=(ScatterScratch&&) = default;

  /// For each chunk of the particles, the nodes its stencils reach, as fast::compute_stencils noted them for the
  /// stencils at `noted_for` (null: noted for none; the scatters over other stencils search them).
  ChunkNodes reached;
  const void* noted_for = nullptr;
  ScatterPlan plan;  ///< how the current scatter adds (plan_scatter)

  /// Buffer number `index` of the copies of values of type T (a double, or a vector of 1 or 2 components):
  /// `room` values, all zero, allocated by its first use in a run (and again should the room change); later uses
  /// allocate nothing. A buffer returned stays where it is when a later call adds another (the buffers are a
  /// std::deque): a scatter asks for all of its fields' buffers in one argument list, in no fixed order.
  template <class T>
  std::vector<T>& copies(std::size_t index, long room) {
    std::deque<std::vector<T>>& buffers = std::get<std::deque<std::vector<T>>>(buffers_);
    if (buffers.size() <= index) buffers.resize(index + 1);
    if (static_cast<long>(buffers[index].size()) != room) {
      T zero;
      set_zero(zero);
      buffers[index].assign(room, zero);
    }
    return buffers[index];
  }

 private:
  std::tuple<std::deque<std::vector<double>>, std::deque<std::vector<Vector<1>>>,
             std::deque<std::vector<Vector<2>>>> buffers_;
};

}  // namespace mpm::fast

namespace mpm::testing {

/// A random 2D scatter: `count` particles in a grid of `columns` x `rows` cells (unit cells, nodes numbered
/// row by row), each adding its weight to the 4 nodes of its cell with bilinear shares; in spatial order
/// (by cell row, as the scenes make them) or shuffled.
struct RandomScatter {
  int columns, rows, nodes;
  std::vector<int> cell;                // the node at the lower left of each particle's cell
  std::vector<std::array<double, 4>> share;
  fast::ChunkNodes reached;

  RandomScatter(int count, int columns_, int rows_, bool in_order)
      : columns(columns_), rows(rows_), nodes((columns_ + 1) * (rows_ + 1)) {
    std::mt19937 generator(7);
    std::uniform_real_distribution<double> x(0.0, columns), y(0.0, rows), exponent(-7.0, 7.0);
    std::vector<std::pair<double, double>> at(count);
    for (auto& point : at) point = {x(generator), y(generator)};
    if (in_order) std::sort(at.begin(), at.end(), [](auto a, auto b) { return int(a.second) < int(b.second); });
    for (const auto& [px, py] : at) {
      const int i = static_cast<int>(px), j = static_cast<int>(py);
      const double fx = px - i, fy = py - j, weight = std::sin(7.0 * px) * std::pow(10.0, exponent(generator));
      cell.push_back(j * (columns + 1) + i);
      share.push_back({weight * (1 - fx) * (1 - fy), weight * fx * (1 - fy), weight * (1 - fx) * fy, weight * fx * fy});
    }
    reached.assign(chunks_of(count), Range{nodes, 0});
    for (int chunk = 0; chunk < chunks_of(count); ++chunk)
      for (int p = chunk_of(count, chunk).begin; p < chunk_of(count, chunk).end; ++p)
        reached[chunk] = {std::min(reached[chunk].begin, cell[p]), std::max(reached[chunk].end, cell[p] + columns + 3)};
  }
  int count() const { return static_cast<int>(cell.size()); }
  void add(int p, double* into, bool magnitude = false) const {  // magnitude: |each share|
    const int corners[4] = {cell[p], cell[p] + 1, cell[p] + columns + 1, cell[p] + columns + 2};
    for (int k = 0; k < 4; ++k) into[corners[k]] += magnitude ? std::abs(share[p][k]) : share[p][k];
  }
  /// The scatter on `threads` threads (every loop on the team).
  std::vector<double> on(int threads) const {
    const TeamAlways on_the_team;
    use_threads(threads);
    std::vector<double> field(nodes, 0.0), copies;
    fast::prepare_copies(copies, count(), nodes, 0.0);
    fast::ScatterPlan plan;
    fast::scatter_to_nodes(count(), parallel_work, reached, plan, [&](int p, double* into) { add(p, into); },
                           fast::ScatterTarget<double>{field, copies});
    use_threads(1);
    CHECK(std::all_of(copies.begin(), copies.end(), [](double left) { return left == 0.0; }));  // zeroed for the next
    return field;
  }
};

}  // namespace mpm::testing

namespace mpm::fast {

TEST_CASE("Scatter: 10^5 particles in spatial order, the same bits on 1, 2, 3 and 7 threads, chunk by chunk") {
  const testing::RandomScatter scatter(100000, 160, 160, true);
  ScatterPlan plan;
  plan_scatter(scatter.count(), scatter.nodes, scatter.reached, plan);
  REQUIRE(plan.parts == chunks_of(scatter.count()));  // one part per chunk: the windows fit
  // The reduction's cost: the windows together hold the grid once plus, per chunk, at most the row of
  // nodes it shares with the chunk before and the two rows of its stencils' width; far below copy_room.
  CHECK(plan.room_used() <= scatter.nodes + plan.chunks * 3L * (scatter.columns + 1));
  CHECK(plan.room_used() <= copy_room(scatter.count(), scatter.nodes));
  const std::vector<double> one = scatter.on(1);
  for (int threads : {2, 3, 7}) CHECK(scatter.on(threads) == one);
  // By hand: each chunk's sum from zero, added node by node in chunk order; and the plain loop to 1e-12.
  std::vector<double> by_chunks(scatter.nodes, 0.0), serial(scatter.nodes, 0.0), magnitude(scatter.nodes, 0.0);
  for (int chunk = 0; chunk < plan.chunks; ++chunk) {
    std::vector<double> part(scatter.nodes, 0.0);
    const Range items = chunk_of(scatter.count(), chunk);
    for (int p = items.begin; p < items.end; ++p) scatter.add(p, part.data());
    for (int node = 0; node < scatter.nodes; ++node)
      by_chunks[node] = chunk == 0 ? part[node] : by_chunks[node] + part[node];
  }
  for (int p = 0; p < scatter.count(); ++p) scatter.add(p, serial.data());
  for (int p = 0; p < scatter.count(); ++p) scatter.add(p, magnitude.data(), true);
  CHECK(one == by_chunks);
  CHECK(one != serial);  // the weights tell the order of the additions apart
  for (int node = 0; node < scatter.nodes; ++node)
    REQUIRE(std::abs(one[node] - serial[node]) <= 1e-12 * magnitude[node]);
}

TEST_CASE("Scatter: particles in no order overflow the room, add in max_chunks groups, the same bits on any threads") {
  const testing::RandomScatter scatter(30000, 40, 40, false);  // 29 chunks, each reaching nearly the whole grid
  ScatterPlan plan;
  plan_scatter(scatter.count(), scatter.nodes, scatter.reached, plan);
  CHECK(plan.chunks == 29);
  CHECK(plan.parts == max_chunks);
  CHECK(plan.room_used() <= copy_room(scatter.count(), scatter.nodes));
  const std::vector<double> one = scatter.on(1);
  for (int threads : {2, 3, 7}) CHECK(scatter.on(threads) == one);
  std::vector<double> by_groups(scatter.nodes, 0.0);  // each group's sum over its particles, in group order
  for (int group = 0; group < max_chunks; ++group) {
    std::vector<double> part(scatter.nodes, 0.0);
    const Range chunks = part_of(plan.chunks, max_chunks, group);
    for (int p = chunk_of(scatter.count(), chunks.begin).begin; p < chunk_of(scatter.count(), chunks.end - 1).end; ++p)
      scatter.add(p, part.data());
    for (int node = 0; node < scatter.nodes; ++node)
      by_groups[node] = group == 0 ? part[node] : by_groups[node] + part[node];
  }
  CHECK(one == by_groups);
}

TEST_CASE("Scatter: the copies' layout never points before the buffer and fits max_chunks - 1 grids, in any order") {
  ScatterPlan plan;
  const int count = 8 * items_per_chunk, nodes = 100;  // 8 chunks: each window may be the whole grid
  ChunkNodes reached{{0, 10}, {90, 100}, {0, 100}, {50, 60}, {5, 6}, {1 << 20, 0}, {-5, 1 << 30}, {99, 100}};
  plan_scatter(count, nodes, reached, plan);
  REQUIRE(plan.parts == 8);
  CHECK(plan.window[5].begin == plan.window[5].end);  // a chunk that reached no node
  CHECK(plan.window[6].begin == 0);
  CHECK(plan.window[6].end == nodes);  // clamped to the grid
  for (int part = 1; part < plan.parts; ++part) {
    CHECK(plan.offset[part] >= plan.window[part].begin);
    CHECK(plan.offset[part + 1] - plan.offset[part] == plan.window[part].end - plan.window[part].begin);
  }
  CHECK(plan.room_used() == 90 + 10 + 100 + 10 + 1 + 0 + 100 + 1);
  CHECK(plan.room_used() <= copy_room(count, nodes));
  plan_scatter(count, nodes, ChunkNodes(3, Range{0, 1}), plan);  // a list of another length: every node
  CHECK(plan.room_used() == 7 * nodes);
}

TEST_CASE("Scatter: two fields of different types in one pass, too few copies is an error, not a crash") {
  const int count = 3000;
  std::vector<double> field(10, 0.0), copies;
  std::vector<Vector<2>> vectors(10, Vector<2>::Zero()), vector_copies;
  prepare_copies(copies, count, 10, 0.0);
  prepare_copies(vector_copies, count, 10, Vector<2>(Vector<2>::Zero()));
  const ChunkNodes everywhere(chunks_of(count), all_nodes);
  const TeamAlways on_the_team;
  use_threads(2);
  ScatterPlan plan;
  scatter_to_nodes(
      count, parallel_work, everywhere, plan,
      [](int p, double* f, Vector<2>* g) {
        f[p % 10] += 2.0;
        g[p % 5] += Vector<2>(1.0, double(p % 3));
      },
      ScatterTarget<double>{field, copies}, ScatterTarget<Vector<2>>{vectors, vector_copies});
  use_threads(1);
  for (int node = 0; node < 10; ++node) CHECK(field[node] == 2 * (count / 10));
  long ones = 0, residues = 0;  // the sums over p with p % 5 == 0: count / 5 ones, and the sum of p % 3
  for (int p = 0; p < count; p += 5) ++ones, residues += p % 3;
  CHECK(vectors[0] == Vector<2>(double(ones), double(residues)));
  for (const Vector<2>& left : vector_copies) CHECK(left.isZero(0.0));
  copies.pop_back();
  auto nothing = [](int, double*) {};
  CHECK_THROWS_AS(scatter_to_nodes(count, 1, everywhere, plan, nothing, ScatterTarget<double>{field, copies}),
                  std::logic_error);
}

TEST_CASE("Scatter: the workspace's buffers of copies, zero, allocated at their first use and kept") {
  ScatterScratch scratch;
  std::vector<Vector<2>>& copies = scratch.copies<Vector<2>>(2, 30);
  CHECK(copies.size() == 30);
  for (const Vector<2>& value : copies) CHECK(value.isZero(0.0));
  copies[7] = Vector<2>(1.0, 2.0);  // a scatter leaves them zero; a value left here shows whether they are kept
  const Vector<2>* kept = copies.data();
  CHECK(scratch.copies<Vector<2>>(2, 30).data() == kept);
  CHECK(scratch.copies<Vector<2>>(2, 30)[7] == Vector<2>(1.0, 2.0));
  CHECK(scratch.copies<double>(0, 5) == std::vector<double>(5, 0.0));  // a buffer of each type and number of its own
  CHECK(scratch.copies<Vector<2>>(0, 4).size() == 4);
  CHECK(scratch.copies<Vector<2>>(2, 40).size() == 40);  // another room: allocated again, zero
  CHECK(scratch.copies<Vector<2>>(2, 40)[7].isZero(0.0));
  // A buffer added later moves none of those handed out before (a scatter asks for them in no fixed order).
  ScatterScratch fresh;
  std::vector<double>& first = fresh.copies<double>(0, 3);
  first[1] = 4.0;
  for (std::size_t index = 1; index < 40; ++index) fresh.copies<double>(index, 3);
  CHECK(&fresh.copies<double>(0, 3) == &first);
  CHECK(first[1] == 4.0);
}

}  // namespace mpm::fast
