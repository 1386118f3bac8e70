/// \file
/// The one argument parser of every command: CLI11, each option declared once with its default, range and help
/// (`mpm COMMAND --help` is generated from them), and CLI11's errors turned into the command's own:
/// one line `error: --OPTION: what is wrong`, exit code 2.
#pragma once
#include <doctest/doctest.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/io/csv_file.hpp"

namespace mpm::cli {

/// A bad input, said whole after `error: ` (the option or `FILE:LINE` first): the command exits 2.
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The whole text as a finite decimal number (io::read_finite_number; no hexadecimal); nullopt for anything else.
/// A number beyond a double's normal range ('1e-310' is too small, '1e400' too large) sets `out_of_range` to why.
inline std::optional<double> parse_number(const std::string& text, std::string* out_of_range = nullptr) {
  double value = 0.0;
  const std::string why = text.find_first_of("xX") == std::string::npos ? io::read_finite_number(text, value) : "x";
  if (why.empty()) return value;
  if (out_of_range && why.find(" is too ") != std::string::npos) *out_of_range = why;
  return std::nullopt;
}

/// A validator of a number for which `accept` holds; `values` ("number in [0, 1]") names them in the help and
/// the error (`must be a number in [0, 1], got '2'`).
inline CLI::Validator number_where(const std::string& values, std::function<bool(double)> accept) {
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        std::string out_of_range;
        const auto number = parse_number(text, &out_of_range);
        if (number && accept(*number)) return "";
        return out_of_range.empty() ? "must be a " + values + ", got '" + text + "'" : out_of_range;
      },
      "NUMBER" + values.substr(6));
}

/// A finite number in [low, high] (or [low, high) when `open_high`); CLI11's Range lets NaN through.
inline CLI::Validator number_in(double low, double high, bool open_high = false) {
  std::ostringstream range;
  range << "number in [" << low << ", " << high << (open_high ? ")" : "]");
  return number_where(range.str(), [=](double x) { return x >= low && (open_high ? x < high : x <= high); });
}

/// A finite number > 0.
inline CLI::Validator positive() {
  return number_where("number > 0", [](double x) { return x > 0.0; });
}

/// A whole number in [low, high], written as digits (no sign, point or exponent), whatever its length.
inline CLI::Validator whole_in(long low, long high) {
  const std::string from = std::to_string(low), to = std::to_string(high);
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        const bool digits = !text.empty() && text.size() <= 18 && std::all_of(text.begin(), text.end(), ::isdigit);
        if (digits && std::stol(text) >= low && std::stol(text) <= high) return "";
        return "must be a whole number from " + from + " to " + to + ", got '" + text + "'";
      },
      "INTEGER in [" + from + ", " + to + "]");
}

/// One of `choices`.
inline CLI::Validator one_of(const std::vector<std::string>& choices) {
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
    const std::string type = option->get_type_name(), fallback = option->get_default_str();
    std::string text = " " + type.substr(type.find(':') + 1);
    if (!fallback.empty() && fallback != "[]" && !option->get_required()) text += " (default " + fallback + ")";
    return text + (option->get_expected_max() > 1 ? " ..." : "");
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

/// An argument no option took (`--bogus: unknown option`, `stray: unexpected argument`), or CLI11's error as the
/// command's: the option named first.
inline std::string error_message(const CLI::ParseError* error, const std::string& extra, const std::string& command) {
  if (!error || !extra.empty())
    return extra + ": " + (extra.rfind('-', 0) == 0 ? "unknown option" : "unexpected argument") + " (mpm " + command +
           " --help lists the options)";
  const std::string what = error->what(), first = what.substr(0, what.find(' '));
  const auto colon = what.find(": "), excludes = what.find(" excludes ");
  if (dynamic_cast<const CLI::ArgumentMismatch*>(error) && colon != std::string::npos)
    return what.substr(0, colon) +
           (what.find("At Most") != std::string::npos ? ": given more than once" : ": needs a value");
  if (dynamic_cast<const CLI::ExcludesError*>(error) && excludes != std::string::npos)
    return what.substr(0, excludes) + ": give it or " + what.substr(excludes + 10) + ", not both";
  if (dynamic_cast<const CLI::RequiredError*>(error)) return first + ": required (mpm " + command + " --help)";
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
    err << "error: " << error_message(&error, app.remaining().empty() ? "" : app.remaining().front(), command) << "\n";
    return 2;
  }
  if (app.remaining().empty()) return std::nullopt;
  err << "error: " << error_message(nullptr, app.remaining().front(), command) << "\n";
  return 2;
}

/// Parses `arguments` with `app` (parse_arguments), then runs `body`, which returns the exit code: what it
/// refuses (Refused, InputError, SceneError) is one line `error: ...` and exit 2, a file or picture it cannot
/// write (OutputFailure) exit 3.
template <class Body>
int run_parsed(CLI::App& app, const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err,
               Body body) {
  if (const auto code = parse_arguments(app, arguments, app.get_name().substr(4), out, err)) return *code;
  try {
    return body();
  } catch (const Refused& refused) {
    err << "error: " << refused.what() << "\n";
  } catch (const InputError& error) {
    err << error.message() << "\n";
  } catch (const SceneError& error) {
    err << error.message() << "\n";
  } catch (const OutputFailure& failure) {
    err << failure.message() << "\n";
    return 3;
  }
  return 2;
}

TEST_CASE("options: numbers, ranges and choices as the commands read them, CLI11's errors as the command's own") {
  for (const char* text : {"", " 1", "1e-3s", "nan", "inf", "1e400", "0x", "0x10"}) CHECK(!parse_number(text));
  CHECK(parse_number("-2.5e2") == -250.0);
  std::string why;
  CHECK((!parse_number("1e-310", &why) && why.rfind("'1e-310' is too small (below 2.2e-308", 0) == 0));
  CHECK(number_in(0.0, 1.0)("1e-310") == why);  // a subnormal is too small, not 'not a finite number'
  CHECK(positive()("1e400") == "'1e400' is too large (beyond 1.8e308)");
  CHECK(number_in(0.0, 1.0)("0.5").empty());
  CHECK(number_in(0.0, 0.5, true)("0.5") == "must be a number in [0, 0.5), got '0.5'");
  CHECK(number_in(0.0, 0.5, true).get_description() == "NUMBER in [0, 0.5)");
  CHECK(positive()("nan") == "must be a number > 0, got 'nan'");
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
      {{"stray"}, "error: stray: unexpected argument (mpm try --help lists the options)\n"},
      {{"--refuse"}, "error: --refuse: no\n"},
      {{"--fail"}, "error: out.csv: cannot write: full\n"}};
  for (const auto& [arguments, message] : wrong) {
    CommandParser fresh("try", "a trial");
    fresh.add_option("--ppc", ppc, "particles per cell")->check(whole_in(1, 4));
    bool refuse = false, fail = false;
    fresh.add_flag("--refuse", refuse, "refuse");
    fresh.add_flag("--fail", fail, "fail");
    err.str("");
    const int code = run_parsed(fresh, arguments, out, err, [&] {
      if (fail) throw OutputFailure("out.csv", "full");
      if (refuse) throw Refused("--refuse: no");
      return 0;
    });
    CHECK(code == (fail ? 3 : 2));
    CHECK(err.str() == message);
  }
  CommandParser helped("try", "a trial");
  helped.add_option("--ppc", ppc, "particles per cell")->check(whole_in(1, 4));
  CHECK(parse_arguments(helped, {"--help"}, "try", out, err) == 0);
  CHECK(out.str().find("--ppc INTEGER in [1, 4] (default ") != std::string::npos);
}

}  // namespace mpm::cli
