// A claim of the report: what the paper (or the theory) says, what we measured, and whether it holds.
// Hard claims are bounds the theory gives: one that does not hold fails the suite (exit 1).
// Soft claims are the paper's: one that does not hold is reported, with its numbers, and nothing more.
#pragma once
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace verification {

struct Claim {
  std::string text;      ///< the claim, with its tolerance
  std::string measured;  ///< the numbers we measured
  bool holds = false;
  bool hard = false;     ///< a theory bound: failing it fails the suite
};

/// A Markdown table of claims: | claim | measured | verdict |.
inline void write_claims(std::ostream& out, const std::vector<Claim>& claims) {
  out << "| claim | measured | verdict |\n|---|---|---|\n";
  for (const Claim& claim : claims)
    out << "| " << claim.text << (claim.hard ? " *(hard check)*" : "") << " | " << claim.measured << " | "
        << (claim.holds ? "**holds**" : "**does not hold**") << " |\n";
  out << "\n";
}

/// True when every hard claim holds.
inline bool hard_claims_hold(const std::vector<Claim>& claims) {
  for (const Claim& claim : claims)
    if (claim.hard && !claim.holds) return false;
  return true;
}

/// printf-style formatting of one number, for the report.
inline std::string number(double value, const char* format = "%.4g") {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace verification
