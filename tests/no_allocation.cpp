/// \file
/// Nothing is allocated inside the time step once it has run: every array is sized before the first step, but
/// for the fast layer's copies of the scatter, allocated by the first step (mpm/fast/scatter.hpp, ScatterScratch). This test replaces the global operator new with a counting one and checks that no
/// allocation happens between the first and the last sample of a run, for every shape function
/// and integrator, in 1D and 2D.
#include <doctest/doctest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "tests/support.hpp"

namespace {
std::atomic<long> allocations{0};
}  // namespace

// GCC cannot see that this operator delete pairs with the malloc of the operator new above.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  ++allocations;
  if (void* memory = std::malloc(size ? size : 1)) return memory;
  throw std::bad_alloc();
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { operator delete(memory); }
// The nothrow pair too (std::stable_sort's buffer): under AddressSanitizer the default one is the sanitizer's own,
// whose memory the free above may not release.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  ++allocations;
  return std::malloc(size ? size : 1);
}
void operator delete(void* memory, const std::nothrow_t&) noexcept { std::free(memory); }

namespace {

/// Notes the allocation count at the first and at the last sample; allocates nothing itself.
template <int Dim>
struct AllocationWatch : mpm::Monitor<Dim> {
  void sample(long step, double, const mpm::Particles<Dim>&, const mpm::Balances<Dim>&) override {
    if (step >= 1 && at_first_step < 0) at_first_step = allocations.load();  // after the first sampled step
    at_last_sample = allocations.load();
    last_step = step;
  }
  long at_first_step = -1, at_last_sample = -1, last_step = 0;
};

template <int Dim>
void check_no_allocation(const std::string& scene_file, const std::vector<std::string>& overrides) {
  for (const std::string shape : {"linear", "ugimp", "lme"})
    for (const std::string integrator : {"fe", "npc"}) {
      std::vector<std::string> all = overrides;
      all.push_back("solver.shape=\"" + shape + "\"");
      all.push_back("solver.integrator=\"" + integrator + "\"");
      const auto scene = mpm::load_scene(mpm::testing::source_path(scene_file), all);
      const auto setup = mpm::build_setup<Dim>(scene);
      AllocationWatch<Dim> watch;
      mpm::run_setup<Dim>(scene, setup, watch);
      INFO(scene_file, " ", shape, " + ", integrator, ": ", watch.last_step, " steps");
      REQUIRE(watch.last_step > 50);
      CHECK(watch.at_last_sample - watch.at_first_step == 0);
    }
}

}  // namespace

TEST_CASE("No allocation inside the time step: 1D Dyka bar and 2D soil block, every shape and integrator") {
  check_no_allocation<1>("scenes/dyka_bar.toml", {"output.snapshots=[]"});
  check_no_allocation<2>("scenes/soil_block.toml", {"output.snapshots=[]", "solver.end_time=1.0"});
}
