// A claim of the report: what the paper (or the theory) says, what we measured, and whether it holds.
// Hard claims are bounds the theory gives: one that does not hold fails the suite (exit 1).
// Soft claims are the paper's: one that does not hold is reported, with its numbers, and nothing more.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "mpm/analysis/verdict.hpp"

namespace verification {

struct Claim {
  std::string text;      ///< the claim, with its tolerance
  std::string measured;  ///< the numbers we measured
  bool holds = false;
  bool hard = false;     ///< a theory bound: failing it fails the suite
  /// decided by the one rule (mpm::judge) as undecided (within its numbers' bands) or stopped (a run stopped):
  /// neither holds nor fails
  bool undecided = false, stopped = false;
};

/// A claim decided by the one rule: holds, does not hold, undecided or stopped, as `outcome`.
inline Claim judged_claim(const std::string& text, const std::string& measured, mpm::Outcome outcome, bool hard = false) {
  return {text, measured, outcome == mpm::Outcome::holds, hard, outcome == mpm::Outcome::undecided,
          outcome == mpm::Outcome::stopped};
}

/// A table cell's text with each bar escaped (\\|): "|e(h/2)|" would otherwise split the cell.
inline std::string cell(const std::string& text) {
  std::string escaped;
  for (char c : text) escaped += c == '|' ? std::string("\\|") : std::string(1, c);
  return escaped;
}

/// A Markdown table of claims: | claim | measured | verdict |.
inline void write_claims(std::ostream& out, const std::vector<Claim>& claims) {
  out << "| claim | measured | verdict |\n|---|---|---|\n";
  for (const Claim& claim : claims)
    out << "| " << cell(claim.text) << (claim.hard ? " *(hard check)*" : "") << " | " << cell(claim.measured) << " | "
        << (claim.undecided ? "**undecided**" : claim.stopped ? "**stopped**" : claim.holds ? "**holds**" : "**does not hold**")
        << " |\n";
  out << "\n";
}

/// True when every hard claim holds.
/// True when every hard claim holds or is undecided (within its numbers' bands a bound is not shown broken: the same
/// as a DomainClaim's undecided sample); a stopped hard claim fails.
inline bool hard_claims_hold(const std::vector<Claim>& claims) {
  for (const Claim& claim : claims)
    if (claim.hard && !claim.holds && !claim.undecided) return false;
  return true;
}

/// One place of a study a claim is evaluated at (a run, or the pair of runs it compares): where it is, the
/// value measured there and whether the claim holds there.
struct Sample {
  std::string where;  ///< "linear, 640 cells, CFL 0.5"
  double value = 0.0;
  bool holds = false;
  bool stopped = false;  ///< a run of the place stopped: its own outcome, not compared
  bool undecided = false;  ///< within the measurement's resolution (a timing spread, 2 s.e. of an order): neither
};

/// The sample's outcome by the one rule, as a word: "holds", "fails", "undecided" or "stopped".
inline const char* outcome_word(const Sample& sample) {
  return sample.stopped ? "stopped" : sample.undecided ? "undecided" : sample.holds ? "holds" : "fails";
}

/// A claim evaluated on every place of its study, so that the report says where it holds and where it fails,
/// never "holds" over a chosen subset. A stopped run is its own outcome (add_stopped): listed as not compared and
/// left out of "holds on k of n" -- except in a hard claim, where it fails.
struct DomainClaim {
  std::string statement;         ///< what is claimed, in words
  std::string measure;           ///< what each sample measures, with the threshold: "RMS_NPC / RMS_FE < 1"
  std::vector<Sample> samples;   ///< every place of the study
  bool hard = false;             ///< a theory bound: failing it anywhere fails the suite
  /// false for a claim over hundreds of runs: the report names the places where it fails, is undecided or stopped, and
  /// counts those where it holds ("205 runs, largest 1.2e-15") instead of naming each
  bool name_holds = true;

  void add(const std::string& where, double value, bool holds) { samples.push_back({where, value, holds, false}); }
  /// A place decided by the one rule (mpm::judge, mpm/analysis/verdict.hpp): holds, fails, undecided or stopped.
  void add(const std::string& where, double value, mpm::Outcome outcome) {
    samples.push_back({where, value, outcome == mpm::Outcome::holds, outcome == mpm::Outcome::stopped,
                       outcome == mpm::Outcome::undecided});
  }
  /// A place where a run stopped, named by `where` ("2560 cells: NPC stopped at 156 µs: ...").
  void add_stopped(const std::string& where) { samples.push_back({where, std::nan(""), false, true}); }
  /// A place decided by less than its measurement resolves (`where` says which: a tie within the timings' spread, an
  /// order within 2 standard errors of its threshold): listed as undecided, neither holds nor fails.
  void add_undecided(const std::string& where, double value) { samples.push_back({where, value, false, false, true}); }
  /// True if `sample` is compared: decided, and no run of it stopped or the claim is hard (a stop fails a bound).
  bool compared(const Sample& sample) const { return !sample.undecided && (hard || !sample.stopped); }
  std::size_t count(bool holds) const {
    std::size_t n = 0;
    for (const Sample& sample : samples) n += compared(sample) && sample.holds == holds;
    return n;
  }
  std::size_t holding() const { return count(true); }
  /// "holds on all 12", "fails on all 12", "holds on 8 of 12", "undecided on all 2" (none decided, some within their
  /// bands), "no samples compared", then the four counts of the
  /// one rule: "(8 hold, 4 fail, 1 undecided, 0 stopped)". In a hard claim a stopped run fails (it is counted so).
  std::string verdict() const {
    std::size_t undecided = 0;
    for (const Sample& sample : samples) undecided += sample.undecided;
    const std::size_t k = count(true), n = k + count(false), stopped = samples.size() - n - undecided;
    std::string text = n == 0 && undecided > 0 ? "undecided on all " + std::to_string(undecided)
                       : n == 0                  ? "no samples compared"
                       : k == n ? "holds on all " + std::to_string(n)
                       : k == 0 ? "fails on all " + std::to_string(n)
                                : "holds on " + std::to_string(k) + " of " + std::to_string(n);
    return text + " (" + std::to_string(k) + " hold, " + std::to_string(n - k) + " fail, " + std::to_string(undecided) +
           " undecided, " + std::to_string(stopped) + " stopped)";
  }
};

/// A verdict's class, its words without the counts: "holds on all", "holds on some", "fails on all", "undecided on
/// all" or "no samples compared". Two verdicts of one claim under two rules differ in direction when their classes do.
inline std::string verdict_class(const DomainClaim& claim) {
  const std::size_t k = claim.count(true), n = k + claim.count(false);
  std::size_t undecided = 0;
  for (const Sample& sample : claim.samples) undecided += sample.undecided;
  return n == 0 ? (undecided > 0 ? "undecided on all" : "no samples compared")
                : k == n ? "holds on all" : k == 0 ? "fails on all" : "holds on some";
}

inline std::string number(double value, const char* format = "%.4g");

/// The compared samples where a claim holds (holds = true) or fails, as "where (value)" joined by "; ", "-" if none.
inline std::string places(const DomainClaim& claim, bool holds, const char* format = "%.4g") {
  if (holds && !claim.name_holds) {  // counted, with the largest value, not named
    std::size_t n = 0;
    double largest = -HUGE_VAL;
    for (const Sample& sample : claim.samples)
      if (claim.compared(sample) && sample.holds) ++n, largest = std::max(largest, sample.value);
    return n == 0 ? "-" : "all " + std::to_string(n) + " not named elsewhere in this row (largest value " + number(largest, "%.3g") + ")";
  }
  std::string text;
  for (const Sample& sample : claim.samples) {
    if (!claim.compared(sample) || sample.holds != holds) continue;
    char value[64];  // a sample without a value (NaN: a shape that finished where linear stopped) shows its place alone
    std::snprintf(value, sizeof value, format, sample.value);
    text += (text.empty() ? "" : "; ") + sample.where + (std::isnan(sample.value) ? std::string() : " (" + std::string(value) + ")");
  }
  return text.empty() ? "-" : text;
}

/// The samples not compared (stopped runs; undecided ones marked so), as their `where` joined by "; ", "-" if none.
inline std::string stopped_places(const DomainClaim& claim) {
  std::string text;
  for (const Sample& sample : claim.samples)
    if (!claim.compared(sample)) text += (text.empty() ? "" : "; ") + sample.where + (sample.undecided ? " (undecided)" : "");
  return text.empty() ? "-" : text;
}

/// A Markdown table of claims over their domains: | claim | measure | holds on | fails on | not compared | verdict |.
inline void write_domain_claims(std::ostream& out, const std::vector<DomainClaim>& claims) {
  out << "| claim | measure | holds on | fails on | not compared (stopped, undecided) | verdict |\n|---|---|---|---|---|---|\n";
  for (const DomainClaim& claim : claims)
    out << "| " << cell(claim.statement) << (claim.hard ? " *(hard check)*" : "") << " | " << cell(claim.measure) << " | "
        << cell(places(claim, true)) << " | " << cell(places(claim, false)) << " | " << cell(stopped_places(claim)) << " | **"
        << claim.verdict() << "** |\n";
  out << "\n";
}

/// True when every hard claim holds on every decided sample (and has at least one): an undecided sample does not fail it,
/// a stopped one does.
inline bool hard_claims_hold(const std::vector<DomainClaim>& claims) {
  for (const DomainClaim& claim : claims)
    if (claim.hard && (claim.samples.empty() || claim.count(false) > 0)) return false;
  return true;
}

/// "A method of the paper is still the most accurate": the smallest value of each group, the paper's methods' and the
/// others', among its runs that did not stop, compared by the one rule (mpm::judge: the paper's best below the others'
/// beyond their bands). `paper` and `others` are the groups' measured numbers (an error: smaller is better); the indices
/// of the two bests, npos where a group has no run that finished (the outcome is then stopped).
struct BestOfGroups {
  static constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::size_t paper = none, other = none;
  mpm::Outcome outcome = mpm::Outcome::stopped;
};
inline std::size_t smallest_finished(const std::vector<mpm::Measured>& group) {
  std::size_t best = BestOfGroups::none;
  for (std::size_t k = 0; k < group.size(); ++k)
    if (group[k].ending != mpm::Ending::stopped && (best == BestOfGroups::none || group[k].value < group[best].value)) best = k;
  return best;
}
inline BestOfGroups judge_best(const std::vector<mpm::Measured>& paper, const std::vector<mpm::Measured>& others) {
  BestOfGroups best{smallest_finished(paper), smallest_finished(others), mpm::Outcome::stopped};
  if (best.paper != BestOfGroups::none && best.other != BestOfGroups::none)
    best.outcome = mpm::judge(paper[best.paper], mpm::Side::below, others[best.other]);
  return best;
}

/// The places where one claim, scored at point A (`at_a`) and on all particles (`all`), has another outcome, sample
/// by sample, added to `list` ("; "-separated) as "NAME, PLACE: OUTCOME at point A, OUTCOME on all particles" (PLACE:
/// the sample's `where` up to its first colon). The Dyka studies' scoring of the same runs by two norms.
inline void add_changed_verdicts(std::string& list, const std::string& name, const DomainClaim& at_a, const DomainClaim& all) {
  for (std::size_t k = 0; k < at_a.samples.size() && k < all.samples.size(); ++k) {
    const Sample &a = at_a.samples[k], &b = all.samples[k];
    if (std::string(outcome_word(a)) != outcome_word(b))
      list += (list.empty() ? "" : "; ") + name + ", " + a.where.substr(0, a.where.find(':')) + ": " + outcome_word(a) +
              " at point A, " + outcome_word(b) + " on all particles";
  }
}

TEST_CASE("add_changed_verdicts: only the places whose outcome differs, named up to their colon") {
  DomainClaim at_a{"c", "m", {}, false}, all{"c", "m", {}, false};
  at_a.add("40 cells: x", 1.0, mpm::Outcome::holds);
  all.add("40 cells: x", 1.0, mpm::Outcome::holds);
  at_a.add("160 cells: y", 1.0, mpm::Outcome::undecided);
  all.add("160 cells: y", 1.0, mpm::Outcome::fails);
  std::string list;
  add_changed_verdicts(list, "claim", at_a, all);
  CHECK(list == "claim, 160 cells: undecided at point A, fails on all particles");
  add_changed_verdicts(list, "again", at_a, all);
  CHECK(list.find("; again, 160 cells") != std::string::npos);
}

TEST_CASE("DomainClaim::verdict: the four counts, and a row of undecided samples named so") {
  DomainClaim claim{"c", "m", {}, false};
  claim.add("a", 1.0, mpm::Outcome::undecided);
  claim.add_stopped("b");
  CHECK(claim.verdict() == "undecided on all 1 (0 hold, 0 fail, 1 undecided, 1 stopped)");
  claim.add("c", 1.0, mpm::Outcome::holds);
  claim.add("d", 1.0, mpm::Outcome::fails);
  CHECK(claim.verdict() == "holds on 1 of 2 (1 hold, 1 fail, 1 undecided, 1 stopped)");
  CHECK(verdict_class(claim) == "holds on some");
}

TEST_CASE("judge_best: each group's smallest finished value, by the one rule") {
  using mpm::Ending;
  const std::vector<mpm::Measured> paper{{0.30, 0.01, Ending::done}, {0.05, 0.0, Ending::stopped}, {0.20, 0.01, Ending::done}};
  const BestOfGroups held = judge_best(paper, {{0.25, 0.01, Ending::done}, {0.40, 0.01, Ending::failed}});
  CHECK(held.paper == 2);  // the stopped run's 0.05 is no best
  CHECK(held.other == 0);
  CHECK(held.outcome == mpm::Outcome::holds);
  CHECK(judge_best(paper, {{0.21, 0.01, Ending::done}}).outcome == mpm::Outcome::undecided);
  CHECK(judge_best(paper, {{0.10, 0.01, Ending::done}}).outcome == mpm::Outcome::fails);
  CHECK(judge_best(paper, {{0.10, 0.0, Ending::stopped}}).outcome == mpm::Outcome::stopped);
  CHECK(judge_best({}, {{0.10, 0.0, Ending::done}}).paper == BestOfGroups::none);
}

/// printf-style formatting of one number, for the report.
inline std::string number(double value, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace verification
