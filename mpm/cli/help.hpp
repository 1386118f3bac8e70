/// \file
/// The help of the `mpm` command and of each command, with every scene key from the one table of
/// mpm/io/scene_keys.hpp (so the help lists exactly what the parser reads, with its defaults).
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/cli/compare_command.hpp"
#include "mpm/cli/exact_command.hpp"
#include "mpm/cli/plot_command.hpp"
#include "mpm/cli/run_command.hpp"
#include "mpm/cli/shape_command.hpp"
#include "mpm/cli/stability_command.hpp"
#include "mpm/cli/study_command.hpp"
#include "mpm/cli/trace_command.hpp"
#include "mpm/io/scene_keys.hpp"

namespace mpm::cli {

/// The exit codes the help of `mpm` and of its commands ends with.
inline const char* exit_codes =
    "Exit codes:\n"
    "  0  done\n"
    "  2  a bad scene, option or run folder: one line `error: FILE:LINE: KEY: what is wrong`, nothing written\n"
    "  3  the method failed during the run (or gnuplot failed for `mpm plot`), the run would not end (a step past\n"
    "     --max-steps, a collapsing time step), or a file or standard output could not be written (`cannot write`):\n"
    "     one line on stderr; what was written so far is kept\n"
    "  128 + N  signal N stopped the run (129 SIGHUP, 130 SIGINT, 143 SIGTERM...; run.json says \"interrupted\")\n";

/// A key's default as the help shows it (`0.5`, `0.0 per axis`, `required`, `none`: optional), and README (`0.5`
/// in code) when `markdown`.
inline std::string default_text(const io::SceneKey& key, bool markdown = false) {
  if (!key.fallback) return "required";
  if (key.is_optional()) return "none";
  return (markdown ? "`" + std::string(key.fallback) + "`" : std::string(key.fallback)) +
         (key.per_axis ? " per axis" : "");
}

/// Every scene key with its default, unit and meaning, one line each.
inline std::string scene_keys_help() {
  std::vector<std::array<std::string, 4>> rows{{"key", "default", "unit", "meaning"}};
  for (const auto& key : io::scene_keys()) rows.push_back({key.key, default_text(key), key.unit, key.meaning});
  std::array<std::size_t, 3> width{};
  for (const auto& row : rows)
    for (int k = 0; k < 3; ++k) width[k] = std::max(width[k], row[k].size());
  std::string text =
      "Scene keys (TOML; body[].min is `min` of every [[body]]; \"per axis\": the default on every axis;\n"
      "`required`: no default; `none`: optional, absent unless given):\n";
  auto cell = [&](const std::string& text, int k) { return text + std::string(width[k] + 2 - text.size(), ' '); };
  for (const auto& row : rows) text += "  " + cell(row[0], 0) + cell(row[1], 1) + cell(row[2], 2) + row[3] + "\n";
  return text;
}

/// README's table of scene keys, one row per key (README.md, between the lines `<!-- scene keys -->` and
/// `<!-- /scene keys -->`; the doctest below holds README to it).
inline std::string scene_keys_markdown() {
  std::string table = "| key | default | unit | meaning |\n|---|---|---|---|\n";
  for (const auto& key : io::scene_keys()) {
    std::string meaning = key.meaning;
    for (auto bar = meaning.find('|'); bar != std::string::npos; bar = meaning.find('|', bar + 2))
      meaning.insert(bar, "\\");
    table += "| `" + key.key + "` | " + default_text(key, true) + " | " + key.unit + " | " + meaning + " |\n";
  }
  return table;
}

/// The help a command's own parser prints for `--help`.
inline std::string help_of(int (*command)(const std::vector<std::string>&, std::ostream&, std::ostream&)) {
  std::ostringstream out, err;
  command({"--help"}, out, err);
  return out.str();
}

/// `mpm --help`
inline std::string main_help() {
  return std::string("mpm: the Material Point Method with linear, uGIMP and LME shape functions (README.md)\n\n") +
         run_usage() + "\n" + exact_usage() + "\n" + help_of(compare_command) + "\n" + help_of(shape_command) + "\n" +
         help_of(plot_command) + "\n" + help_of(stability_command) + "\n" +
         help_of(study_command) + "\n" + help_of(trace_command) +
         "\nusage: mpm --version\n  Prints the version (git describe at build time).\n\n" + scene_keys_help() + "\n" +
         exit_codes;
}

/// The help of one command ("run", "exact", "compare", "shape", "plot", "stability", "study", "trace"); the main help
/// for any other.
inline std::string command_help(const std::string& command) {
  if (command == "run") return run_usage() + "\n" + scene_keys_help() + "\n" + exit_codes;
  if (command == "shape") return help_of(shape_command) + "\n" + exit_codes;
  if (command == "plot") return help_of(plot_command) + "\n" + exit_codes;
  if (command == "stability") return help_of(stability_command) + "\n" + exit_codes;
  if (command == "exact")
    return exact_usage() + "\n" + exit_codes + "  (mpm exact exits 3 only when its output cannot be written)\n";
  if (command == "compare") return help_of(compare_command);
  if (command == "study") return help_of(study_command);
  if (command == "trace") return help_of(trace_command) + "\n" + exit_codes;
  return main_help();
}

/// True if the arguments ask for help (`--help` or `-h` anywhere).
inline bool asks_for_help(const std::vector<std::string>& arguments) {
  return std::any_of(arguments.begin(), arguments.end(),
                     [](const std::string& a) { return a == "--help" || a == "-h"; });
}

TEST_CASE("mpm help: every scene key with its default and unit, and the exit codes") {
  const std::string help = command_help("run");
  for (const auto& key : io::scene_keys()) {
    const std::string name = key.key;
    CAPTURE(name);
    const auto line_start = help.find("\n  " + std::string(key.key) + " ");
    REQUIRE(line_start != std::string::npos);
    const std::string line = help.substr(line_start + 1, help.find('\n', line_start + 1) - line_start - 1);
    CHECK(line.find(default_text(key)) != std::string::npos);
    for (const std::string& choice : key.choices)
      CHECK(line.find(choice) != std::string::npos);  // every word a choice takes
    CHECK(line.find(std::string("  ") + key.unit + "  ") != std::string::npos);
  }
  for (const std::string command : {"run", "shape", "plot", "exact", "stability", "trace", ""})
    CHECK(command_help(command).find("  3  the method failed") != std::string::npos);
  for (const std::string name :
       {"dyka_bar", "soil_column", "vibrating_bar", "manufactured_small", "manufactured_large"})
    CHECK(command_help("exact").find("\n    " + name + " ") !=
          std::string::npos);  // every value of the scene key `exact`
  CHECK(command_help("compare").find("Exit codes: 0 within the tolerance, 1 above it, 2 a bad input") !=
        std::string::npos);
  CHECK(main_help().find("Usage: mpm compare [OPTIONS] RESULT.csv SCENE.toml") != std::string::npos);
  CHECK(command_help("shape").find("--tol") != std::string::npos);
  CHECK(command_help("shape").find("LME support tolerance") != std::string::npos);
  CHECK(asks_for_help({"--dim", "1", "-h"}));
  CHECK(!asks_for_help({"--dim", "1"}));
}

#ifdef MPM_SOURCE_DIR
TEST_CASE("README's table of scene keys is the table of mpm/io/scene_keys.hpp (MPM_UPDATE_README=1 rewrites it)") {
  const std::string path = std::string(MPM_SOURCE_DIR) + "/README.md";
  std::ifstream in(path);
  std::stringstream read;
  read << in.rdbuf();
  std::string readme = read.str();
  const std::string begin = "<!-- scene keys -->\n", end = "<!-- /scene keys -->";
  const auto from = readme.find(begin), to = readme.find(end);
  REQUIRE_MESSAGE((from != std::string::npos && to != std::string::npos && from < to),
                  "README.md lacks the markers " << begin << end);
  const std::string given = readme.substr(from + begin.size(), to - from - begin.size()),
                    wanted = scene_keys_markdown();
  if (given != wanted && std::getenv("MPM_UPDATE_README")) {
    std::ofstream(path) << readme.replace(from + begin.size(), to - from - begin.size(), wanted);
    return;
  }
  std::istringstream given_rows(given), wanted_rows(wanted);
  for (std::string a, b; std::getline(wanted_rows, b);) {
    if (!std::getline(given_rows, a)) a = "(no row)";
    CHECK_MESSAGE(a == b, "README.md's row differs from the key's declaration; want:\n" << b);
    if (a != b) break;  // one row named: the key that differs
  }
  CHECK(given.size() == wanted.size());
}
#endif

}  // namespace mpm::cli
