/// \file
/// The particle-parallel loops of the time step, on the machine's cores, with results that do not
/// depend on how many threads run them.
///
/// **Chunks.** Every loop cuts [0, count) into chunks_of(count) contiguous chunks: at most max_chunks,
/// of at least items_per_chunk items, a number set by `count` alone, never by the threads. A sum over
/// the particles (parallel_sum, and the particle-to-grid scatter into the nodes) is formed chunk by
/// chunk, each chunk's part from zero, and the parts are added in chunk order. One thread does
/// exactly the same additions in the same order, so a run gives the same bits on 1, 2 or 64 threads,
/// on any machine. (A loop of fewer than 2 items_per_chunk items is one chunk: the plain serial loop.)
///
/// **Hand-out on demand.** The calling thread and the workers of its Team each take the next chunk
/// when they are free. A thread that the operating system sets aside (another program needs the
/// core) holds up at most the chunk it is working on; the others take the rest. The calling thread
/// never waits for a worker that has not taken a chunk, only for chunks taken and not yet finished,
/// and it waits asleep, so that the core goes to the worker it waits for. (OpenMP's parallel regions
/// end in a barrier that every thread of the team must reach, and their threads spin while they wait:
/// on two cores with one other busy program, that made a run on two threads up to 20 times slower
/// than on one.)
///
/// **When to go parallel.** A loop runs on the team when its estimated work is worth it: the work is
/// counted in stencil entries (a particle's loop over its nodes), and below parallel_work entries
/// waking the workers costs more than they would save.
///
/// **When the team does not pay.** On a machine where another program keeps a core busy, the team's
/// loops can take longer than the calling thread alone would: a worker set aside in the middle of its
/// chunk holds the loop up for the system's time slice. The team measures every loop it runs against
/// the calling thread's own pace (its time per chunk, times the chunks) and, when its loops are on
/// average no faster than that, runs the next serial_period loops on the calling thread alone, then
/// tries again (TeamGovernor). The chunks, and so the bits of every result, stay the same.
#pragma once
#include <doctest/doctest.h>
#include <sched.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <tuple>
#include <vector>

#include "mpm/core/types.hpp"

namespace mpm {

inline constexpr int max_threads = 64;
/// Most chunks per loop: enough that a thread slowed down by another program leaves its share to the
/// others (on 2 threads, each takes about 4), few enough that the scatter's nodal copies, one per chunk
/// beyond the first, stay a small part of the memory of a run.
inline constexpr int max_chunks = 8;
/// Fewest items per chunk (below it the partial sums cost more than the items).
inline constexpr int items_per_chunk = 128;
/// Least work, in stencil entries, of a loop run on the team: on the 2-core development machine waking
/// the workers and waiting for the last chunk costs about 10 microseconds, the work of some 5,000
/// entries of a linear transfer; at 16,384 entries the team's cost is below a tenth of the loop's.
inline constexpr long parallel_work = 16384;

/// The machine's cores that this process may run on (at most max_threads).
inline int available_cores() {
  cpu_set_t allowed;
  const int cores = sched_getaffinity(0, sizeof allowed, &allowed) == 0 ? CPU_COUNT(&allowed)
                                                                         : static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(cores, 1, max_threads);
}

/// [begin, end): a chunk of items, or of nodes.
struct Range {
  int begin, end;
};

/// The number of chunks of a loop over `count` items.
inline int chunks_of(int count) { return std::clamp(count / items_per_chunk, 1, max_chunks); }

/// Chunk `chunk` of [0, count): chunks_of(count) nearly equal contiguous chunks, in order.
inline Range chunk_of(int count, int chunk) {
  const int chunks = chunks_of(count);
  return {static_cast<int>(static_cast<long>(count) * chunk / chunks),
          static_cast<int>(static_cast<long>(count) * (chunk + 1) / chunks)};
}

/// The index of the thread that runs the current chunk: 0 for the calling thread, 1, 2, ... for the
/// workers. A slot for per-thread counters (ShapeDiagnostics), read without a function call.
inline int& worker_index() {
  static thread_local int index = 0;
  return index;
}

/// Whether the team pays for itself, from the loops it ran: each loop's wall time over the calling thread's
/// own pace, ratio = loop time / (the caller's time per chunk x chunks), averaged over the recent loops
/// (weight 1/4 for the newest). Above 1 the team was no faster than one thread: the next serial_period
/// loops run on the calling thread, then one loop on the team tests the machine again.
class TeamGovernor {
 public:
  static constexpr int serial_period = 64;
  /// Whether the next loop goes to the team.
  bool use_team() {
    if (serial_left_ == 0) return true;
    --serial_left_;
    return false;
  }
  /// A loop that ran on the team: `ratio` = its wall time over the calling thread's pace.
  void record(double ratio) {
    average_ = 0.75 * average_ + 0.25 * ratio;
    if (average_ > 1.0) serial_left_ = serial_period, average_ = 1.0;  // the test after the pause decides alone
  }
  int serial_loops_left() const { return serial_left_; }

 private:
  double average_ = 0.5;  // the ratio of two threads that share the work evenly
  int serial_left_ = 0;
};

/// The calling thread and `workers` threads that wait for chunks to run. A worker waits asleep for
/// the next loop; run() wakes it, and it takes chunks until none is left.
class Team {
 public:
  explicit Team(int workers) {
    for (int worker = 1; worker <= workers; ++worker) threads_.emplace_back([this, worker] { serve(worker); });
  }
  ~Team() {
    {
      std::lock_guard<std::mutex> guard(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& thread : threads_) thread.join();
  }
  Team(const Team&) = delete;
  Team& operator=(const Team&) = delete;

  int threads() const { return static_cast<int>(threads_.size()) + 1; }

  /// Runs work(chunk) for every chunk in [0, chunks), on the calling thread and on the workers, each
  /// taking the next chunk when it is free; returns when every chunk has run. work must not throw.
  template <class Work>
  void run(int chunks, Work& work) {
    bool asleep;
    {
      std::lock_guard<std::mutex> guard(mutex_);
      job_ = Job{&call<Work>, &work, chunks};
      ++generation_;
      finished_.store(0);
      next_.store(std::uint64_t(generation_) << 32);
      asleep = sleeping_ > 0;
    }
    if (asleep) wake_.notify_all();
    const auto start = std::chrono::steady_clock::now();
    const int own = take_chunks(job_, generation_);
    const auto own_end = std::chrono::steady_clock::now();
    if (finished_.load() < chunks) {  // chunks still running on workers: wait asleep
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, [&] { return finished_.load() == chunks; });
    }
    if (own > 0) {  // the caller's pace: its time per chunk
      const double pace = std::chrono::duration<double>(own_end - start).count() / own;
      governor_.record(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / (pace * chunks));
    }
  }

  /// Whether the next loop should run on the team (TeamGovernor); false: the calling thread runs it alone.
  bool pays() { return team_always().load(std::memory_order_relaxed) > 0 || governor_.use_team(); }

  /// Above 0 in the tests that compare the team's bits with one thread's: every loop above parallel_work then
  /// runs on the team, whatever the governor measured. (Each TeamAlways adds 1 for its scope, so scopes nest.)
  static std::atomic<int>& team_always() {
    static std::atomic<int> always{0};
    return always;
  }

 private:
  struct Job {
    void (*work)(void*, int) = nullptr;
    void* context = nullptr;
    int chunks = 0;
  };
  template <class Work>
  static void call(void* work, int chunk) { (*static_cast<Work*>(work))(chunk); }

  /// Takes the chunks of loop `generation` one at a time until none is left. next_ holds the
  /// generation (high 32 bits) and the next chunk (low 32 bits) in one word, so that a worker that
  /// wakes late, after its loop ended, cannot take a chunk of the next loop.
  int take_chunks(const Job& job, std::uint32_t generation) {  // returns the chunks it ran
    int taken = 0;
    for (std::uint64_t next = next_.load();;) {
      if (next >> 32 != generation || static_cast<int>(next & 0xffffffffu) >= job.chunks) return taken;
      if (!next_.compare_exchange_weak(next, next + 1)) continue;  // another thread took it: try the next
      job.work(job.context, static_cast<int>(next & 0xffffffffu));
      ++taken;
      if (finished_.fetch_add(1) + 1 == job.chunks) {  // the last chunk: wake the calling thread if it waits
        { std::lock_guard<std::mutex> guard(mutex_); }
        done_.notify_one();
      }
      next = next_.load();
    }
  }

  void serve(int worker) {
    worker_index() = worker;
    std::uint32_t seen = 0;
    for (;;) {
      // The next loop of a step often follows within microseconds: look for it for spin_time before
      // going to sleep (a sleeping worker takes tens of microseconds to wake), yielding the core to
      // any other thread that wants it meanwhile.
      const auto until = std::chrono::steady_clock::now() + spin_time;
      while (next_.load() >> 32 == seen && std::chrono::steady_clock::now() < until) std::this_thread::yield();
      Job job;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        ++sleeping_;
        wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        --sleeping_;
        if (stopping_) return;
        seen = generation_;
        job = job_;
      }
      take_chunks(job, seen);
    }
  }

  /// How long a worker looks for the next loop before it sleeps. With another program busy on one of
  /// two cores, runs on two threads took the same time with 0, 20 and 50 microseconds (within 3 %).
  static constexpr std::chrono::microseconds spin_time{50};

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  Job job_;                               // the current loop (guarded by mutex_)
  std::uint32_t generation_ = 0;          // loops started (guarded by mutex_)
  bool stopping_ = false;                 // guarded by mutex_
  int sleeping_ = 0;                      // workers waiting on wake_ (guarded by mutex_)
  std::atomic<std::uint64_t> next_{0};    // generation << 32 | next chunk to take
  std::atomic<int> finished_{0};          // chunks of the current loop that have run
  TeamGovernor governor_;                 // used by the calling thread only
};

/// For a test's scope: every loop above parallel_work runs on the team (Team::team_always()).
struct TeamAlways {
  TeamAlways() { ++Team::team_always(); }
  ~TeamAlways() { --Team::team_always(); }
  TeamAlways(const TeamAlways&) = delete;
  TeamAlways& operator=(const TeamAlways&) = delete;
};

/// The team of the calling thread (none: the loops run on it alone). Each thread that runs a
/// simulation has its own, so that the verification suites can run simulations side by side.
inline std::unique_ptr<Team>& calling_team() {
  static thread_local std::unique_ptr<Team> team;
  return team;
}

/// Sets the threads of the loops below for the calling thread (1 until it is called); 0 means every
/// available core. Starts or stops the workers (once per run, never inside a time step).
inline void use_threads(int threads) {
  const int wanted = threads > 0 ? std::min(threads, max_threads) : available_cores();
  std::unique_ptr<Team>& team = calling_team();
  if (wanted == 1) team.reset();
  else if (!team || team->threads() != wanted) team = std::make_unique<Team>(wanted - 1);
}

/// The threads the loops of the calling thread may run on.
inline int team_threads() { return calling_team() ? calling_team()->threads() : 1; }

/// work(chunk, items) for every chunk of [0, count), in chunk order on the calling thread, or on
/// its team when `work_estimate` (in stencil entries) reaches parallel_work. work must not throw.
template <class Work>
void for_each_chunk(int count, long work_estimate, Work work) {
  const int chunks = chunks_of(count);
  auto run_chunk = [&](int chunk) { work(chunk, chunk_of(count, chunk)); };
  Team* team = calling_team().get();
  if (team && chunks > 1 && work_estimate >= parallel_work && team->pays()) return team->run(chunks, run_chunk);
  for (int chunk = 0; chunk < chunks; ++chunk) run_chunk(chunk);
}

/// body(p) for every p in [0, count); `work_per_item`: the stencil entries each p visits.
template <class Body>
void parallel_for(int count, long work_per_item, Body body) {
  for_each_chunk(count, count * work_per_item, [&](int, Range items) {
    for (int p = items.begin; p < items.end; ++p) body(p);
  });
}

/// The sum over p in [0, count) of what body(p, part) adds into `part`: formed per chunk from `zero`,
/// the chunks' parts then combined in chunk order by combine(total, part).
template <class T, class Body, class Combine>
T parallel_sum(int count, long work_per_item, const T& zero, Body body, Combine combine) {
  std::array<T, max_chunks> part;
  part.fill(zero);
  for_each_chunk(count, count * work_per_item, [&](int chunk, Range items) {
    T running = zero;  // on the thread's own stack: neighbouring parts share cache lines, which two threads would fight over
    for (int p = items.begin; p < items.end; ++p) body(p, running);
    part[chunk] = running;
  });
  T total = part[0];
  for (int chunk = 1; chunk < chunks_of(count); ++chunk) combine(total, part[chunk]);
  return total;
}

inline void set_zero(double& value) { value = 0.0; }
template <class Derived>
void set_zero(Eigen::MatrixBase<Derived>& value) { value.setZero(); }

/// For each chunk of the particles, the nodes its stencils reach (compute_stencils sets them): the
/// scatter reads and clears a chunk's copy of a field on these nodes only. The whole grid by default.
using ChunkNodes = std::array<Range, max_chunks>;
inline constexpr Range all_nodes{0, 1 << 30};

/// A nodal field that the particles scatter into (P2G), with its zeroed copies, one per chunk beyond
/// the first (GridFields::prepare_chunks), each the size of the field.
template <class T>
struct ScatterTarget {
  std::vector<T>& field;
  std::vector<std::vector<T>>& copies;
};

/// The copies of one field that a scatter over `count` particles needs: one per chunk beyond the first.
template <class T>
void prepare_copies(std::vector<std::vector<T>>& copies, int count, int nodes, const T& zero) {
  copies.assign(chunks_of(count) - 1, std::vector<T>(nodes, zero));
}

/// Adds chunk copies 1, 2, ... of `target` to its field, in chunk order, on the nodes of `block`
/// that each chunk reached, and zeroes them again.
template <class T>
void add_copies(ScatterTarget<T>& target, int chunks, const ChunkNodes& reached, Range block) {
  for (int chunk = 1; chunk < chunks; ++chunk) {
    std::vector<T>& copy = target.copies[chunk - 1];
    const int end = std::min({block.end, reached[chunk].end, static_cast<int>(copy.size())});
    for (int node = std::max(block.begin, reached[chunk].begin); node < end; ++node) {
      target.field[node] += copy[node];
      set_zero(copy[node]);
    }
  }
}

/// Scatter into the nodes (P2G) for particles [0, count), into one or more nodal fields in one pass
/// over the particles: body(p, field...) adds particle p's share into field[I] of each target for the
/// nodes I of its stencil. Chunk 0 adds into the fields themselves, chunk c > 0 into their copies[c - 1];
/// the copies are then added to the fields node by node in chunk order (on the team too, by blocks of
/// nodes) and zeroed again. `work_per_item`: the stencil entries per particle; `reached`: the nodes
/// each chunk's stencils reach.
template <class Body, class... T>
void scatter_to_nodes(int count, long work_per_item, const ChunkNodes& reached, Body body, ScatterTarget<T>... targets) {
  const int chunks = chunks_of(count);
  if (((static_cast<int>(targets.copies.size()) < chunks - 1) || ...)) throw std::logic_error("scatter_to_nodes: too few copies");
  for_each_chunk(count, count * work_per_item, [&](int chunk, Range items) {
    for (int p = items.begin; p < items.end; ++p)
      body(p, (chunk == 0 ? targets.field.data() : targets.copies[chunk - 1].data())...);
  });
  if (chunks == 1) return;
  // The nodes of the first target: every target is a nodal field of the same grid.
  const int nodes = static_cast<int>(std::get<0>(std::forward_as_tuple(targets...)).field.size());
  long copied = 0;  // the work of adding the copies: the nodes they reached
  for (int chunk = 1; chunk < chunks; ++chunk) copied += std::max(0, std::min(reached[chunk].end, nodes) - std::max(reached[chunk].begin, 0));
  for_each_chunk(nodes, copied * static_cast<long>(sizeof...(T)), [&](int, Range block) {
    (add_copies(targets, chunks, reached, block), ...);
  });
}

/// The same for one field: body(p, field).
template <class T, class Body>
void scatter_to_nodes(int count, long work_per_item, const ChunkNodes& reached, std::vector<T>& field,
                      std::vector<std::vector<T>>& copies, Body body) {
  scatter_to_nodes(count, work_per_item, reached, body, ScatterTarget<T>{field, copies});
}

TEST_CASE("Parallel loops: the chunks cover every item once, in order, and depend on the count alone") {
  for (int count : {0, 1, 127, 256, 1000, 5000, 1 << 20}) {
    int covered = 0;
    for (int chunk = 0; chunk < chunks_of(count); ++chunk) {
      const Range items = chunk_of(count, chunk);
      CHECK(items.begin == covered);
      CHECK(items.end - items.begin >= std::min(count, items_per_chunk));
      covered = items.end;
    }
    CHECK(covered == count);
  }
  CHECK(chunks_of(255) == 1);  // the plain serial loop
  CHECK(chunks_of(256) == 2);
  CHECK(chunks_of(1 << 20) == max_chunks);
}

TEST_CASE("Parallel loops: every chunk runs once on the team, loop after loop, worker_index names the thread") {
  const TeamAlways on_the_team;
  use_threads(3);
  REQUIRE(team_threads() == 3);
  const int count = 8 * items_per_chunk;
  std::array<std::atomic<int>, max_chunks> runs;
  std::array<int, max_chunks> thread_of{};
  for (int loop = 0; loop < 2000; ++loop) {  // many short loops: a worker that woke late must not run a chunk twice
    for (auto& run : runs) run.store(0);
    for_each_chunk(count, parallel_work, [&](int chunk, Range) {
      ++runs[chunk];
      thread_of[chunk] = worker_index();
    });
    for (int chunk = 0; chunk < max_chunks; ++chunk) REQUIRE(runs[chunk].load() == 1);
    for (int chunk = 0; chunk < max_chunks; ++chunk) REQUIRE((thread_of[chunk] >= 0 && thread_of[chunk] < 3));
  }
  // Below parallel_work the calling thread runs every chunk itself.
  for_each_chunk(count, parallel_work - 1, [&](int chunk, Range) { thread_of[chunk] = worker_index() + 10; });
  for (int chunk = 0; chunk < max_chunks; ++chunk) CHECK(thread_of[chunk] == 10);
  use_threads(1);
  CHECK(team_threads() == 1);
}

TEST_CASE("Parallel loops: sums and scatters give the same bits on 1, 2 and 3 threads, and the serial loop's sum to 1e-12") {
  // Terms of 14 orders of magnitude and both signs: their sum depends on the order of the additions.
  const int count = 5000, nodes = 50;
  std::vector<double> term(count);
  for (int p = 0; p < count; ++p) term[p] = std::sin(0.7 * p) * std::pow(10.0, p % 15 - 7);
  double serial = 0.0, scale = 0.0;
  for (int p = 0; p < count; ++p) serial += term[p], scale += std::abs(term[p]);
  // Particle p reaches nodes p / 100 and p / 100 + 1 (particles in spatial order, as the scenes make them).
  ChunkNodes reached;
  reached.fill(Range{0, 0});
  for (int chunk = 0; chunk < chunks_of(count); ++chunk)
    reached[chunk] = Range{chunk_of(count, chunk).begin / 100, (chunk_of(count, chunk).end - 1) / 100 + 2};
  std::vector<double> serial_field(nodes + 1, 0.0);
  for (int p = 0; p < count; ++p) serial_field[p / 100] += term[p], serial_field[p / 100 + 1] += 0.5 * term[p];

  std::vector<double> sums;
  std::vector<std::vector<double>> fields;
  const TeamAlways on_the_team;
  for (int threads : {1, 2, 3}) {
    use_threads(threads);
    sums.push_back(parallel_sum(count, parallel_work, 0.0, [&](int p, double& sum) { sum += term[p]; },
                                [](double& total, double part) { total += part; }));
    std::vector<double> field(nodes + 1, 0.0);
    std::vector<std::vector<double>> copies;
    prepare_copies(copies, count, nodes + 1, 0.0);
    scatter_to_nodes(count, parallel_work, reached, field, copies, [&](int p, double* into) {
      into[p / 100] += term[p];
      into[p / 100 + 1] += 0.5 * term[p];
    });
    for (const auto& copy : copies)
      for (double left : copy) CHECK(left == 0.0);  // the copies are left zeroed for the next scatter
    fields.push_back(field);
  }
  use_threads(1);
  CHECK(sums[0] != serial);  // the terms do tell the order of the additions apart...
  CHECK(sums[1] == sums[0]);  // ...and every thread count adds in the same order
  CHECK(sums[2] == sums[0]);
  CHECK(std::abs(sums[0] - serial) <= 1e-12 * scale);
  // The chunks' parts, each from zero, added in chunk order.
  double by_chunks = 0.0;
  for (int chunk = 0; chunk < chunks_of(count); ++chunk) {
    double part = 0.0;
    for (int p = chunk_of(count, chunk).begin; p < chunk_of(count, chunk).end; ++p) part += term[p];
    by_chunks = chunk == 0 ? part : by_chunks + part;
  }
  CHECK(sums[0] == by_chunks);
  for (int node = 0; node <= nodes; ++node) {
    CHECK(fields[1][node] == fields[0][node]);
    CHECK(fields[2][node] == fields[0][node]);
    CHECK(std::abs(fields[0][node] - serial_field[node]) <= 1e-12 * scale);
  }
}

TEST_CASE("Parallel loops: a scatter into two fields of different types in one pass, too few copies is an error, not a crash") {
  const int count = 3000;
  std::vector<double> field(10, 0.0);
  std::vector<Vector<2>> vectors(10, Vector<2>::Zero());
  std::vector<std::vector<double>> copies;
  std::vector<std::vector<Vector<2>>> vector_copies;
  prepare_copies(copies, count, 10, 0.0);
  prepare_copies(vector_copies, count, 10, Vector<2>(Vector<2>::Zero()));
  ChunkNodes everywhere;
  everywhere.fill(all_nodes);
  const TeamAlways on_the_team;
  use_threads(2);
  scatter_to_nodes(
      count, parallel_work, everywhere,
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
  for (const auto& copy : vector_copies)
    for (const Vector<2>& left : copy) CHECK(left.isZero(0.0));
  copies.pop_back();
  CHECK_THROWS_AS(scatter_to_nodes(count, 1, everywhere, field, copies, [](int, double*) {}), std::logic_error);
}

TEST_CASE("Team governor: a team as fast as one thread goes serial for serial_period loops, then tests again, a quiet team never") {
  TeamGovernor quiet;
  for (int loop = 0; loop < 1000; ++loop) {
    REQUIRE(quiet.use_team());
    quiet.record(0.6);  // two threads at 1.7 x
  }
  TeamGovernor busy;  // a worker set aside: the team's loops take 1.5 times the caller's pace
  int loops_to_pause = 0;
  while (busy.use_team() && loops_to_pause < 100) busy.record(1.5), ++loops_to_pause;
  CHECK(loops_to_pause == 3);  // the average 0.5 -> 0.75 -> 0.9375 -> 1.078 (> 1): three loops on the team
  CHECK(busy.serial_loops_left() == TeamGovernor::serial_period - 1);
  int serial = 1;
  while (!busy.use_team()) ++serial;
  CHECK(serial == TeamGovernor::serial_period);
  busy.record(0.9);  // the test loop after the pause was faster than one thread: the team stays
  CHECK(busy.use_team());
  busy.record(1.2);  // the average (3 x 1.0 + 0.9) / 4 = 0.975, then (3 x 0.975 + 1.2) / 4 = 1.03: a pause again
  CHECK(!busy.use_team());
}

}  // namespace mpm
