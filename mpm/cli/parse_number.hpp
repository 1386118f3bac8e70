/// \file
/// The one reading of a number on the command line, shared by every command.
#pragma once
#include <cctype>
#include <cmath>
#include <optional>
#include <string>

namespace mpm::cli {

/// The whole text as a finite number; nullopt for anything else ("1e-3" yes, "1e-3s", "", "nan" no).
inline std::optional<double> parse_number(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
  std::size_t end = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &end);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (end != text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace mpm::cli
