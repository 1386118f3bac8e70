// The Dyka bar's profiles: v and sigma along the whole bar (every particle) at the steps the runs land on anyway,
// nearest to chosen times (an extra snapshot time would shorten a step and move every RMS the book quotes), each
// against the exact solution at that step's own t; scored like the histories of particle A: RMS, ringing (total
// variation over the exact profile's, along the bar) and amplitude (the spread about the mean over the exact's: the
// damping), each with the band of its sampling (the even and the odd particles alone).
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/analysis/rms_error.hpp"
#include "mpm/analysis/verdict.hpp"

namespace verification {

/// The chosen times of the profiles, as fractions of the run's end time (200 µs on the Dyka bar: 50, 100, 150 µs,
/// after the first reflection at the fixed end, after the pulse's return, and in the bar's second traverse).
inline const std::vector<double> profile_fractions{0.25, 0.5, 0.75};

/// One profile: the step's own time, every particle's reference position, v and sigma_xx; the exact ones are set after
/// the run (DykaResult::profiles, run_dyka).
struct Profile {
  double target = 0.0, time = 0.0;
  std::vector<double> position, velocity, stress, exact_velocity, exact_stress;
};

/// Captures the profiles at the steps nearest to `targets`: at each sample it keeps the last profile while the next
/// step may reach a target (t + the last step >= target), and when a sample reaches it takes the nearer of the two.
struct ProfileCapture {
  std::vector<double> targets;
  std::vector<Profile> profiles;
  Profile previous;
  double previous_time = -1.0;

  template <class Particles>
  void sample(double t, const Particles& particles) {
    const std::size_t next = profiles.size();
    if (next >= targets.size()) return;
    const double target = targets[next], last_step = previous_time < 0.0 ? 0.0 : t - previous_time;
    if (t >= target) {
      Profile here = take(t, target, particles);
      profiles.push_back(previous_time >= 0.0 && target - previous.time < t - target ? previous : here);
      profiles.back().target = target;
    } else if (t + last_step >= target) {
      previous = take(t, target, particles);
    }
    previous_time = t;
  }

  template <class Particles>
  static Profile take(double t, double target, const Particles& particles) {
    Profile profile{target, t, {}, {}, {}, {}, {}};
    for (int p = 0; p < particles.size(); ++p) {
      profile.position.push_back(particles.reference_position[p][0]);
      profile.velocity.push_back(particles.velocity[p][0]);
      profile.stress.push_back(particles.stress[p](0, 0));
    }
    return profile;
  }
};

/// One measure of a profile with its band: the whole, the even particles', the odd particles'.
struct ProfileScore {
  double whole = std::nan(""), even = std::nan(""), odd = std::nan("");
  /// the band of the halves that have a value (a half whose exact profile is flat has no ringing); 0 if neither has
  double band() const {
    return mpm::band_of_halves(whole, std::isfinite(even) ? even : whole, std::isfinite(odd) ? odd : whole);
  }
};

/// RMS (over the exact profile's largest magnitude), ringing and amplitude of `computed` against `exact` along the bar.
struct ProfileScores {
  ProfileScore rms, ringing, amplitude;
};

/// `measure` on every value, on the even-indexed and on the odd-indexed ones.
template <class Measure>
ProfileScore score_halves(const std::vector<double>& computed, const std::vector<double>& exact, Measure measure) {
  auto value = [&](const std::vector<double>& a, const std::vector<double>& b) {
    try {
      return a.size() >= 2 ? measure(a, b) : std::nan("");
    } catch (const std::invalid_argument&) {  // a flat exact half: no ringing, no amplitude there
      return std::nan("");
    }
  };
  return {value(computed, exact), value(mpm::every_other(computed, 0), mpm::every_other(exact, 0)),
          value(mpm::every_other(computed, 1), mpm::every_other(exact, 1))};
}

inline ProfileScores score_profile(const std::vector<double>& computed, const std::vector<double>& exact) {
  double scale = 0.0;
  for (double value : exact) scale = std::max(scale, std::abs(value));
  auto relative_rms = [scale](const std::vector<double>& a, const std::vector<double>& b) { return mpm::rms_error(a, b) / scale; };
  auto ringing = [](const std::vector<double>& a, const std::vector<double>& b) { return mpm::total_variation_ratio(a, b); };
  auto amplitude = [](const std::vector<double>& a, const std::vector<double>& b) { return mpm::amplitude_ratio(a, b); };
  return {score_halves(computed, exact, relative_rms), score_halves(computed, exact, ringing), score_halves(computed, exact, amplitude)};
}

TEST_CASE("Dyka profiles: the capture takes the step nearest to each target; the scores by hand") {
  struct Particles {  // two particles, both at v = t
    std::vector<std::array<double, 1>> reference_position{{0.0}, {1.0}}, velocity{{0.0}, {0.0}};
    struct Stress {
      double value = 0.0;
      double operator()(int, int) const { return value; }
    };
    std::vector<Stress> stress{Stress{}, Stress{}};
    int size() const { return 2; }
  };
  ProfileCapture capture{{1.0, 2.5}, {}, {}, -1.0};
  Particles particles;
  for (double t : {0.0, 0.7, 1.2, 1.9, 2.6, 3.3}) {  // 1.0 lies nearer 1.2 than 0.7; 2.5 nearer 2.6 than 1.9
    particles.velocity[0][0] = particles.velocity[1][0] = t;
    capture.sample(t, particles);
  }
  REQUIRE(capture.profiles.size() == 2);
  CHECK(capture.profiles[0].time == 1.2);
  CHECK(capture.profiles[0].velocity[0] == 1.2);
  CHECK(capture.profiles[1].time == 2.6);
  capture = ProfileCapture{{1.0}, {}, {}, -1.0};
  for (double t : {0.0, 0.9, 1.3}) particles.velocity[0][0] = t, capture.sample(t, particles);  // 0.9 nearer
  CHECK(capture.profiles.at(0).time == 0.9);
  CHECK(capture.profiles.at(0).velocity[0] == 0.9);
  // a jump of 1 followed with one overshoot of 0.5: ringing (1 + 0.5 + 0.5) / 1 = 2, RMS sqrt(0.25 / 4) / 1
  const ProfileScores s = score_profile({0.0, 1.5, 1.0, 1.0}, {0.0, 1.0, 1.0, 1.0});
  CHECK(s.ringing.whole == doctest::Approx(2.0));
  CHECK(s.rms.whole == doctest::Approx(0.25));
  CHECK(s.rms.even == doctest::Approx(0.0));                 // particles 0 and 2: exact
  CHECK(s.rms.odd == doctest::Approx(std::sqrt(0.125)));     // particles 1 and 3: 0.5 and 0 off
  CHECK(s.rms.band() == doctest::Approx(0.25));
  CHECK(std::isnan(s.ringing.odd));                          // particles 1 and 3: the exact 1, 1 is flat
  CHECK(s.ringing.even == doctest::Approx(1.0));             // 0 -> 1 followed
  CHECK(s.ringing.band() == doctest::Approx(1.0));           // from the even half alone
}

}  // namespace verification
