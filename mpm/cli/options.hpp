/// \file
/// The one argument parser of every command: CLI11 (Debian's libcli11-dev), each option declared once with
/// its default, range and help (mpm COMMAND --help is CLI11's, from those declarations), and CLI11's errors
/// turned into the command's own: one line `error: --OPTION: what is wrong`, exit code 2.
#pragma once
#include <doctest/doctest.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace mpm::cli {

/// The whole text as a finite decimal number; nullopt for anything else ("1e-3" yes, "1e-3s", "", "nan", " 1",
/// "0x10" no).
inline std::optional<double> parse_number(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])) || text.find_first_of("xX") != std::string::npos)
    return std::nullopt;
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

/// A finite number in [low, high] (or [low, high) when `open_high`); CLI11's Range lets NaN through.
inline CLI::Validator number_in(double low, double high, bool open_high = false) {
  std::ostringstream text_of_range;
  text_of_range << "[" << low << ", " << high << (open_high ? ")" : "]");
  const std::string range = text_of_range.str();
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        const auto number = parse_number(text);
        if (number && *number >= low && (open_high ? *number < high : *number <= high)) return "";
        return "must be a number in " + range + ", got '" + text + "'";
      },
      "NUMBER in " + range);
}

/// A finite number > 0.
inline CLI::Validator positive() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        const auto number = parse_number(text);
        return number && *number > 0.0 ? "" : "must be a number > 0, got '" + text + "'";
      },
      "NUMBER > 0");
}

/// A whole number in [low, high], written as digits (no sign, point or exponent), whatever its length.
inline CLI::Validator whole_in(long low, long high) {
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        const bool digits = !text.empty() && text.size() <= 18 && std::all_of(text.begin(), text.end(), ::isdigit);
        if (digits && std::stol(text) >= low && std::stol(text) <= high) return "";
        return "must be a whole number from " + std::to_string(low) + " to " + std::to_string(high) + ", got '" + text + "'";
      },
      "INTEGER in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
}

/// One of `choices`.
inline CLI::Validator one_of(std::vector<std::string> choices) {
  std::string list;
  for (const auto& choice : choices) list += (list.empty() ? "" : " | ") + choice;
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        if (std::find(choices.begin(), choices.end(), text) != choices.end()) return "";
        return "must be one of " + list + ", got '" + text + "'";
      },
      list);
}

/// The help's left column: an option's values as its validator names them, and its default
/// (`--ppc INTEGER in [1, 4] (default 1)`), not CLI11's `INT:INTEGER in [1, 4]=1`.
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_opts(const CLI::Option* option) const override {
    if (option->get_type_size() == 0) return "";
    const std::string type = option->get_type_name();
    const auto colon = type.find(':');
    std::string text = " " + (colon == std::string::npos ? type : type.substr(colon + 1));
    const std::string fallback = option->get_default_str();
    if (!fallback.empty() && fallback != "[]" && !option->get_required()) text += " (default " + fallback + ")";
    if (option->get_expected_max() > 1) text += " ...";
    return text;
  }
};

/// A command's parser, `mpm NAME` with its description; its options show their defaults in its help.
class CommandParser : public CLI::App {
 public:
  CommandParser(const std::string& name, const std::string& description) : CLI::App(description, "mpm " + name) {
    formatter(std::make_shared<HelpFormatter>());
    get_formatter()->column_width(30);
    option_defaults()->always_capture_default();
    allow_extras();  // left over, in order: parse_arguments names the first
  }
};

/// An argument no option or positional took: `--bogus: unknown option`, `stray: unexpected argument`.
inline std::string extra_message(const std::string& extra, const std::string& command) {
  return extra + ": " + (extra.rfind("-", 0) == 0 ? "unknown option" : "unexpected argument") + " (mpm " + command +
         " --help lists the options)";
}

/// CLI11's message as the command's: `--OPTION: what`, the option named first.
inline std::string error_message(const CLI::ParseError& error, const std::string& command) {
  const std::string what = error.what();
  const auto mismatch = what.find(": ");
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) && mismatch != std::string::npos)
    return what.substr(0, mismatch) + (what.find("At Most") != std::string::npos ? ": given more than once" : ": needs a value");
  const auto equals = what.find(" = ");
  if (dynamic_cast<const CLI::ConversionError*>(&error) && mismatch != std::string::npos && equals != std::string::npos)
    return what.substr(mismatch + 2, equals - mismatch - 2) + ": '" + what.substr(equals + 3) + "' cannot be read";
  if (dynamic_cast<const CLI::ExcludesError*>(&error)) {
    const auto excludes = what.find(" excludes ");
    if (excludes != std::string::npos)
      return what.substr(0, excludes) + ": give it or " + what.substr(excludes + 10) + ", not both";
  }
  if (dynamic_cast<const CLI::RequiredError*>(&error)) {
    const std::string name = what.substr(0, what.find(' '));
    return name + ": required (mpm " + command + " --help)";
  }
  return what;
}

/// Parses `arguments` with `app`. Returns nullopt when the command should go on; otherwise its exit code:
/// 0 after printing the help asked for, 2 after `error: ...` on `err`.
inline std::optional<int> parse_arguments(CLI::App& app, std::vector<std::string> arguments, const std::string& command,
                                          std::ostream& out, std::ostream& err) {
  std::reverse(arguments.begin(), arguments.end());  // CLI11 takes them last first
  try {
    app.parse(arguments);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return 0;
  } catch (const CLI::ParseError& error) {  // an unknown option first: it may be what left a required one out
    err << "error: " << (app.remaining().empty() ? error_message(error, command) : extra_message(app.remaining().front(), command))
        << "\n";
    return 2;
  }
  if (!app.remaining().empty()) {
    err << "error: " << extra_message(app.remaining().front(), command) << "\n";
    return 2;
  }
  return std::nullopt;
}

TEST_CASE("options: numbers, ranges and choices as the commands read them, CLI11's errors as the command's own") {
  for (const char* text : {"", " 1", "1e-3s", "nan", "inf", "1e400", "0x", "0x10"}) CHECK(!parse_number(text));
  CHECK(number_in(0.0, 1.0)("0.5").empty());
  CHECK(number_in(0.0, 0.5, true)("0.5") == "must be a number in [0, 0.5), got '0.5'");
  CHECK(!number_in(0.0, 1.0)("nan").empty());
  CHECK(whole_in(1, 4)("4").empty());
  CHECK(!whole_in(1, 4)("5").empty());
  CHECK(!whole_in(1, 4)("1.0").empty());
  CHECK(!whole_in(1, 4)("99999999999999999999999").empty());
  CHECK(one_of({"fe", "npc"})("pc") == "must be one of fe | npc, got 'pc'");
  int ppc = 1;
  std::string kind = "fe";
  CommandParser app("try", "a trial");
  app.add_option("--ppc", ppc, "particles per cell")->check(whole_in(1, 4));
  app.add_option("--kind", kind, "integrator")->check(one_of({"fe", "npc"}));
  std::ostringstream out, err;
  CHECK(!parse_arguments(app, {"--ppc", "3", "--kind", "npc"}, "try", out, err));
  CHECK((ppc == 3 && kind == "npc"));
  const std::vector<std::pair<std::vector<std::string>, std::string>> wrong{
      {{"--ppc", "0"}, "error: --ppc: must be a whole number from 1 to 4, got '0'\n"},
      {{"--ppc"}, "error: --ppc: needs a value\n"},
      {{"--ppc", "1", "--ppc", "2"}, "error: --ppc: given more than once\n"},
      {{"--bogus", "1"}, "error: --bogus: unknown option (mpm try --help lists the options)\n"},
      {{"stray"}, "error: stray: unexpected argument (mpm try --help lists the options)\n"}};
  for (const auto& [arguments, message] : wrong) {
    CommandParser fresh("try", "a trial");
    fresh.add_option("--ppc", ppc, "particles per cell")->check(whole_in(1, 4));
    err.str("");
    CHECK(parse_arguments(fresh, arguments, "try", out, err) == 2);
    CHECK(err.str() == message);
  }
  CommandParser helped("try", "a trial");
  helped.add_option("--ppc", ppc, "particles per cell")->check(whole_in(1, 4));
  CHECK(parse_arguments(helped, {"--help"}, "try", out, err) == 0);
  CHECK(out.str().find("--ppc") != std::string::npos);
}

}  // namespace mpm::cli
