/// \file
/// `mpm study STUDY.toml [--out DIR] [--jobs N]`: the command's options (CLI11, mpm/cli/options.hpp); the study
/// itself is mpm/study/study.hpp.
#pragma once
#include <doctest/doctest.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "mpm/cli/options.hpp"
#include "mpm/study/study.hpp"

namespace mpm::cli {

/// `mpm study`'s parser, its options bound to `request`.
inline std::unique_ptr<CommandParser> study_parser(study::StudyRequest& request) {
  auto app = std::make_unique<CommandParser>(
      "study",
      "Runs a study of a scene: the product of the axes of STUDY.toml (any scene keys), each case a child `mpm run\n"
      "--threads 1` in DIR/cases/NNNN, --jobs at once; scores the observer's velocity against the scene's exact solution\n"
      "with `mpm compare` (Eq. 43) at the written time and at the time the integrator's velocity approximates, each\n"
      "score with the band of its own sampling and its ending (stopped: the case not done; failed: no better than a\n"
      "flat line at the exact mean); writes study.csv, fits.csv (the order p of error ~ C N^-p over the refine axis,\n"
      "with its standard error and band, failed scores left out), error.png and cost.png, and prints their names.\n"
      "README.md, \"Your own study\", shows a study file.");
  app->add_option("STUDY.toml", request.study_path, "the study file")->required();
  app->add_option("--out", request.out, "the study's folder (default runs/<the study file's name>)")->type_name("DIR");
  app->add_option("--jobs", request.jobs, "cases run at once (0: the machine's cores)")->check(whole_in(0, 1024));
  app->footer("Exit codes: 0 written (a case refused, stopped or failed is a row of study.csv), 2 a bad study file, scene\n"
              "or folder (`error: FILE:LINE: KEY: why`, nothing written), 3 a file could not be written, gnuplot failed or\n"
              "a case could not run (its folder a link or busy), 128 + N stopped by signal N (SIGINT, SIGTERM, SIGHUP...:\n"
              "forwarded to the runs, which end as interrupted; study.csv not written).");
  return app;
}

/// `mpm study --help`: the parser's own help.
inline std::string study_usage() {
  study::StudyRequest request;
  return study_parser(request)->help();
}

/// `mpm study ARGUMENTS...`: returns the exit code.
inline int study_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  study::StudyRequest request;
  if (const auto code = parse_arguments(*study_parser(request), arguments, "study", out, err)) return *code;
  return study::run_study(request, out, err);
}

TEST_CASE("mpm study: its options, and a missing study file refused with exit 2 before anything is written") {
  std::ostringstream out, err;
  CHECK(study_command({"--jobs", "-1", "s.toml"}, out, err) == 2);
  CHECK(err.str().find("--jobs") != std::string::npos);
  err.str("");
  CHECK(study_command({"/nonexistent/s.toml", "--out", "/nonexistent/out"}, out, err) == 2);
  CHECK(err.str().rfind("error: /nonexistent/s.toml: ", 0) == 0);
  CHECK(out.str().empty());
  CHECK(study_usage().find("--jobs") != std::string::npos);
}

}  // namespace mpm::cli
