/// \file
/// The particle-parallel loops of the time step, on the machine's cores, with results that do not
/// depend on how many threads run them.
///
/// **Chunks.** Every loop cuts [0, count) into chunks_of(count) contiguous chunks, a number set by `count`
/// alone, never by the threads. A loop of up to small_loop items has at most max_chunks chunks of at least
/// items_per_chunk items (a loop of fewer than 2 items_per_chunk items is one chunk: the plain serial
/// loop); a longer loop has one chunk per large_chunk_items items, so that the chunks grow with the work
/// and keep many threads busy. A sum over the particles (parallel_sum, and the particle-to-grid scatter
/// into the nodes, mpm/fast/scatter.hpp) is formed chunk by chunk, each chunk's part from zero, and the
/// parts are added in chunk order. One thread does exactly the same additions in the same order, so a
/// run gives the same bits on 1, 2 or 64 threads, on any machine.
///
/// **The model that sets the chunks.** Let a loop of count items have C = chunks_of(count) chunks of
/// nearly equal work w = count / C items (at least 1024 items above small_loop). Threads that take chunks
/// on demand finish a loop of equal chunks in ceil(C / P) chunk times, so P threads speed it up by at most
/// balanced_speedup(C, P) = C / ceil(C / P): P itself when C is a multiple of P, and at least C / (C / P + 1)
/// otherwise. 8 chunks cap every loop at 8 threads and leave a thread idle for any chunk slower than the
/// rest; the 102,400 particles of the soil block at 160 x 160 cells make 100 chunks: at most 7.7 on 8
/// threads, 11.1 on 12, 14.3 on 16. What more chunks cost is the scatter's reduction: each chunk beyond the
/// first adds into a copy of the nodal fields that covers only the nodes its particles reach (a window),
/// and the copies are added to the fields node by node. With the particles in spatial order (as the
/// scenes make them) a window holds the rows of nodes of its own particles plus a stencil's width, so the
/// copies together hold about nodes + C x (stencil rows x nodes per row): for the soil block with LME about
/// 3.4 % of the scatter's own stencil entries, 10 % for linear shapes (estimates of this formula). Their
/// memory is capped at max_chunks - 1 copies of the grid, what a loop of small_loop items needs; particles
/// out of order, whose windows would exceed it, are scattered in max_chunks groups of chunks instead
/// (mpm/fast/scatter.hpp).
///
/// **Hand-out on demand.** The calling thread and the workers of its Team each take the next chunk
/// when they are free. A thread that the operating system sets aside (another program needs the
/// core) holds up at most the chunk it is working on; the others take the rest. The calling thread
/// never waits for a worker that has not taken a chunk, only for chunks taken and not yet finished,
/// and it waits asleep, so that the core goes to the worker it waits for. (OpenMP's parallel regions
/// end in a barrier that every thread of the team must reach, and their threads spin while they wait:
/// on two cores with one other busy program, that made a run on two threads up to 20 times slower
/// than on one. oneTBB's task arena, which takes the same chunks on demand, was measured against this team:
/// benchmarks/README.md, "A threading library instead of the team"; CMake's MPM_THREADS=onetbb builds it.)
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
#include "mpm/core/worker_index.hpp"
#ifdef MPM_THREADS_ONETBB  // the trial of oneTBB (benchmarks/threads_library.sh): CMake -DMPM_THREADS=onetbb
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#endif

namespace mpm {

inline constexpr int max_threads = 64;
/// Most chunks of a loop of up to small_loop items: enough that a thread slowed down by another program
/// leaves its share to the others (on 2 threads, each takes about 4), and the most copies of the whole grid
/// (one per chunk beyond the first) that the particle-to-grid scatter keeps.
inline constexpr int max_chunks = 8;
/// Fewest items per chunk (below it the partial sums cost more than the items).
inline constexpr int items_per_chunk = 128;
/// Items per chunk of a loop longer than small_loop: about a millisecond of LME stencils, 20 microseconds
/// of a linear transfer, against the fraction of a microsecond it costs a thread to take a chunk.
inline constexpr int large_chunk_items = 1024;
/// The longest loop cut by the rule of the small loops (at most max_chunks chunks).
inline constexpr int small_loop = max_chunks * large_chunk_items;
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

/// The number of chunks of a loop over `count` items: up to small_loop items, count / items_per_chunk
/// within [1, max_chunks]; beyond, count / large_chunk_items (which is max_chunks at small_loop, so the
/// rule has no jump). Never the threads: a result's bits depend on its chunks.
inline int chunks_of(int count) {
  return count <= small_loop ? std::clamp(count / items_per_chunk, 1, max_chunks) : count / large_chunk_items;
}

/// The model's speed-up of a loop of `chunks` chunks of equal work on `threads` threads that take them on
/// demand: the chunks over the chunk times the busiest thread needs, chunks / ceil(chunks / threads).
inline double balanced_speedup(int chunks, int threads) {
  return static_cast<double>(chunks) / ((chunks + threads - 1) / threads);
}

/// Part `part` of [0, count) cut into `parts` nearly equal contiguous parts, in order.
inline Range part_of(int count, int parts, int part) {
  return {static_cast<int>(static_cast<long>(count) * part / parts),
          static_cast<int>(static_cast<long>(count) * (part + 1) / parts)};
}

/// Chunk `chunk` of [0, count): chunks_of(count) nearly equal contiguous chunks, in order.
inline Range chunk_of(int count, int chunk) { return part_of(count, chunks_of(count), chunk); }


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
#ifdef MPM_THREADS_ONETBB
    arena_.initialize(workers + 1);
    arena_workers_ = workers;
    return;
#endif
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

#ifdef MPM_THREADS_ONETBB
  int threads() const { return arena_workers_ + 1; }
#else
  int threads() const { return static_cast<int>(threads_.size()) + 1; }
#endif

  /// Runs work(chunk) for every chunk in [0, chunks), on the calling thread and on the workers, each
  /// taking the next chunk when it is free; returns when every chunk has run. work must not throw.
  template <class Work>
  void run(int chunks, Work& work) {
#ifdef MPM_THREADS_ONETBB  // oneTBB's arena of threads() slots takes the chunks (one per task) in place of the workers
    arena_.execute([&] {
      oneapi::tbb::parallel_for(0, chunks, 1, [&](int chunk) {
        worker_index() = std::max(0, oneapi::tbb::this_task_arena::current_thread_index());
        work(chunk);
      }, oneapi::tbb::simple_partitioner());
    });
    worker_index() = 0;
    return;
#endif
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
#ifdef MPM_THREADS_ONETBB
  oneapi::tbb::task_arena arena_;
  int arena_workers_ = 0;
#endif
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

/// work(part) for every part in [0, parts), in order on the calling thread, or on its team when
/// `work_estimate` (in stencil entries) reaches parallel_work. work must not throw.
template <class Work>
void for_each_part(int parts, long work_estimate, Work work) {
  Team* team = calling_team().get();
  if (team && parts > 1 && work_estimate >= parallel_work && team->pays()) return team->run(parts, work);
  for (int part = 0; part < parts; ++part) work(part);
}

/// work(chunk, items) for every chunk of [0, count), in chunk order on the calling thread, or on
/// its team when `work_estimate` (in stencil entries) reaches parallel_work. work must not throw.
template <class Work>
void for_each_chunk(int count, long work_estimate, Work work) {
  for_each_part(chunks_of(count), work_estimate, [&](int chunk) { work(chunk, chunk_of(count, chunk)); });
}

/// body(p) for every p in [0, count); `work_per_item`: the stencil entries each p visits.
template <class Body>
void parallel_for(int count, long work_per_item, Body body) {
  for_each_chunk(count, count * work_per_item, [&](int, Range items) {
    for (int p = items.begin; p < items.end; ++p) body(p);
  });
}

/// Room for `size` values of type T for the calling thread's loops, kept from call to call so that a loop in
/// the time step allocates only the first time it needs more.
template <class T>
std::vector<T>& scratch(std::size_t size) {
  static thread_local std::vector<T> room;
  if (room.size() < size) room.resize(size);
  return room;
}

/// The sum over p in [0, count) of what body(p, part) adds into `part`: formed per chunk from `zero`,
/// the chunks' parts then combined in chunk order by combine(total, part).
template <class T, class Body, class Combine>
T parallel_sum(int count, long work_per_item, const T& zero, Body body, Combine combine) {
  const int chunks = chunks_of(count);
  std::vector<T>& part = scratch<T>(chunks);
  for_each_chunk(count, count * work_per_item, [&](int chunk, Range items) {
    T running = zero;  // on the thread's own stack: neighbouring parts share cache lines, which two threads would fight over
    for (int p = items.begin; p < items.end; ++p) body(p, running);
    part[chunk] = running;
  });
  T total = part[0];
  for (int chunk = 1; chunk < chunks; ++chunk) combine(total, part[chunk]);
  return total;
}

TEST_CASE("Parallel loops: the chunks cover every item once, in order, and depend on the count alone") {
  for (int count : {0, 1, 127, 256, 1000, 5000, small_loop, small_loop + 1, 102400, 1 << 20}) {
    int covered = 0;
    for (int chunk = 0; chunk < chunks_of(count); ++chunk) {
      const Range items = chunk_of(count, chunk);
      CHECK(items.begin == covered);
      CHECK(items.end - items.begin >= std::min(count, items_per_chunk));
      if (count > small_loop) CHECK(items.end - items.begin >= large_chunk_items);
      covered = items.end;
    }
    CHECK(covered == count);
  }
  CHECK(chunks_of(255) == 1);  // the plain serial loop
  CHECK(chunks_of(256) == 2);
  CHECK(chunks_of(small_loop) == max_chunks);  // the small loops' rule, as it was
  CHECK(chunks_of(small_loop + large_chunk_items - 1) == max_chunks);  // no jump where the rules meet
  CHECK(chunks_of(small_loop + large_chunk_items) == max_chunks + 1);
  CHECK(chunks_of(102400) == 100);  // the soil block at 160 x 160 cells
  CHECK(chunks_of(1 << 20) == 1024);
  for (int count = 1; count < 1 << 17; count += 97) REQUIRE(chunks_of(count) <= chunks_of(count + 97));  // grows
}

TEST_CASE("Parallel loops: the model's speed-up of 10^5 items, at least 0.7 x threads up to 8, rises to 16") {
  CHECK(balanced_speedup(8, 8) == 8.0);
  CHECK(balanced_speedup(8, 16) == 8.0);  // the cap of max_chunks chunks
  CHECK(balanced_speedup(100, 8) == doctest::Approx(100.0 / 13));
  CHECK(balanced_speedup(100, 16) == doctest::Approx(100.0 / 7));
  for (int count : {100000, 102400, 1 << 20}) {
    std::array<double, 17> speedup{};
    for (int threads = 1; threads <= 16; ++threads) {
      speedup[threads] = balanced_speedup(chunks_of(count), threads);
      INFO(count, " items on ", threads, " threads: ", speedup[threads]);
      if (threads <= 8) CHECK(speedup[threads] >= 0.7 * threads);
      CHECK(speedup[threads] >= speedup[threads - 1]);  // never lower with more threads
      if (threads > 4) CHECK(speedup[threads] > speedup[threads - 4]);  // and rising beyond 8
    }
    CHECK(speedup[16] >= 0.75 * 16);
  }
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

TEST_CASE("Parallel loops: sums give the same bits on 1, 2, 3 and 7 threads, and the serial loop's sum to 1e-12") {
  // Terms of 14 orders of magnitude and both signs: their sum depends on the order of the additions.
  for (int count : {5000, 3 * small_loop + 77}) {
    std::vector<double> term(count);
    for (int p = 0; p < count; ++p) term[p] = std::sin(0.7 * p) * std::pow(10.0, p % 15 - 7);
    double serial = 0.0, scale = 0.0;
    for (int p = 0; p < count; ++p) serial += term[p], scale += std::abs(term[p]);
    std::vector<double> sums;
    const TeamAlways on_the_team;
    for (int threads : {1, 2, 3, 7}) {
      use_threads(threads);
      sums.push_back(parallel_sum(count, parallel_work, 0.0, [&](int p, double& sum) { sum += term[p]; },
                                  [](double& total, double part) { total += part; }));
    }
    use_threads(1);
    CHECK(sums[0] != serial);  // the terms do tell the order of the additions apart...
    for (double sum : sums) CHECK(sum == sums[0]);  // ...and every thread count adds in the same order
    CHECK(std::abs(sums[0] - serial) <= 1e-12 * scale);
    // The chunks' parts, each from zero, added in chunk order.
    double by_chunks = 0.0;
    for (int chunk = 0; chunk < chunks_of(count); ++chunk) {
      double part = 0.0;
      for (int p = chunk_of(count, chunk).begin; p < chunk_of(count, chunk).end; ++p) part += term[p];
      by_chunks = chunk == 0 ? part : by_chunks + part;
    }
    CHECK(sums[0] == by_chunks);
  }
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
