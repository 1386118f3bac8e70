/// \file
/// The check of the trace equation -> kernel -> test (ctest runs it as `docs_trace`), and the writer of
/// the page of tests by equation that `make docs` renders.
///
///     build/bin/docs_trace                        run the doctests: the real trace of this source tree
///                                                 (with build/bin/mpm_tests run under each equation's
///                                                 filter -tc='*Eq. (N)*'), and the checker itself on
///                                                 small synthetic inputs
///     build/bin/docs_trace --tests-page FILE.md [MUTANTS.csv]
///                                                 write the generated page of tests by equation, with
///                                                 the mutants of make mutants (results/mutants/mutants.csv)
///
/// The real check fails with one message per missing piece, each naming its equation, e.g.
/// "Eq. (41): no TEST_CASE in mpm/ or tests/ names it".
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>

#include "tests/docs_trace.hpp"

namespace {

using docs_trace::check;
using docs_trace::equations_named;
using docs_trace::Sources;

bool mentions(const std::vector<std::string>& errors, const std::string& text) {
  return std::any_of(errors.begin(), errors.end(), [&](const std::string& e) { return e.find(text) != std::string::npos; });
}

/// A synthetic section of the contract's shape.
std::string section(const std::string& label, const std::string& kernel_line, const std::string& test_line = "") {
  const std::string suffix = docs_trace::anchor_suffix(label);
  return "### Eq. (" + label + "): words {#eq" + suffix + "}\n\n\\f[\n  a = b\n\\f]\n\n" + kernel_line + "\n" +
         (test_line.empty() ? "- test: \\ref tests_eq" + suffix + " \"doctests\"\n" : test_line + "\n") + "\n";
}

/// Synthetic sources in which all 63 equations are stated with "no kernel", except those the test adds.
Sources all_without_kernels() {
  Sources sources;
  std::string page = "# Sample {#paper_sample}\n\n";
  for (const std::string& label : docs_trace::equation_labels())
    if (label != "16" && label != "A.5")
      page += "### Eq. (" + label + "): words {#eq" + docs_trace::anchor_suffix(label) +
              "}\n\\f[ a = b \\f]\n- no kernel: the synthetic sample states it only\n\n";
  sources.pages["paper/01_sample.md"] = page;
  sources.code["mpm/transfer/strain_update.hpp"] =
      "namespace mpm {\ntemplate <int Dim>\nvoid strain_rate(const Stencils<Dim>& s) {}\n}\n";
  sources.code["mpm/exact/bar.hpp"] =
      "namespace mpm::exact {\nclass ElasticBar {\n double stress(double x, double t) const { return 0; }\n};\n}\n";
  return sources;
}

const std::string test_case = std::string("TEST_") + "CASE(\"";  // not a test of this project

}  // namespace

TEST_CASE("docs_trace: a test name names an equation only as \"Eq. (N)\", as the filter -tc='*Eq. (N)*' does") {
  CHECK(equations_named("Eq. (16): strain rate") == std::vector<std::string>{"16"});
  CHECK(equations_named("Eq. (9), Eq. (10), Eq. (14): forces, again Eq. (9)") == std::vector<std::string>{"9", "10", "14"});
  CHECK(equations_named("Eq. (A.16), Eq. (A.1): bar") == std::vector<std::string>{"A.16", "A.1"});
  CHECK(equations_named("eq. (a.5) and EQ. (3), as doctest ignores case") == std::vector<std::string>{"A.5", "3"});
  CHECK(equations_named("Eqs. (19)-(22): G2P").empty());
  CHECK(equations_named("Eqs. (14), (15) and (A.5)").empty());
  CHECK(equations_named("Equal masses (3 of them), Eq (4), Eq. 5, Eq.(6)").empty());
  CHECK(equations_named("Eq. (x): nothing").empty());
  CHECK(docs_trace::names_equations_in_plural("Eq. (8), Eqs. (21)-(22): P2G"));
  CHECK(docs_trace::names_equations_in_plural("eqs. (1), (2)"));
  CHECK_FALSE(docs_trace::names_equations_in_plural("Eq. (21), Eq. (22): P2G; the Eqs. are listed"));
}

TEST_CASE("docs_trace: TEST_CASE names and their lines are read from the source text") {
  const std::string text = "// a\n" + test_case + "Eq. (3): Hooke\") {\n}\n\n" + test_case + "two \\\"quoted\\\"\") {}\n";
  const auto found = docs_trace::test_cases_in(text, "mpm/x.hpp");
  REQUIRE(found.size() == 2);
  CHECK(found[0].name == "Eq. (3): Hooke");
  CHECK(found[0].line == 2);
  CHECK(found[1].name == "two \"quoted\"");
  CHECK(found[1].line == 5);
}

TEST_CASE("docs_trace: a complete synthetic sample passes") {
  Sources sources = all_without_kernels();
  sources.pages["paper/02_sample.md"] =
      "# Two {#paper_two}\n\n" +
      section("16", "- kernel: \\ref mpm::strain_rate \"strain_rate()\" in mpm/transfer/strain_update.hpp") +
      section("A.5", "- kernel: \\ref mpm::exact::ElasticBar::stress \"stress()\" in mpm/exact/bar.hpp");
  sources.code["tests/t.cpp"] = test_case + "Eq. (15), Eq. (16), Eq. (17): a list names 16\") {}\n" + test_case +
                                "Eq. (A.5), Eq. (A.19): jumps\") {}\n";
  const auto errors = check(sources);
  for (const auto& e : errors) INFO(e);
  CHECK(errors.empty());
  const std::string page = docs_trace::tests_page(sources);
  CHECK(page.find("\\page tests_eq16 Eq. (16): words") != std::string::npos);
  CHECK(page.find("\\page tests_eqA5 Eq. (A.5): words") != std::string::npos);
  CHECK(page.find("<a href=\"t_8cpp_source.html#l00002\">tests/t.cpp:2</a>: `Eq. (A.5), Eq. (A.19): jumps`") !=
        std::string::npos);
  CHECK(page.find("No doctest names Eq. (41).") != std::string::npos);
}

TEST_CASE("docs_trace: each broken piece of a sample fails, naming its equation") {
  const std::string good_kernel = "- kernel: \\ref mpm::strain_rate \"strain_rate()\" in mpm/transfer/strain_update.hpp";
  const std::string a5_kernel = "- kernel: \\ref mpm::exact::ElasticBar::stress \"stress()\" in mpm/exact/bar.hpp";
  const std::string tests = test_case + "Eq. (16): x\") {}\n" + test_case + "Eq. (A.5): y\") {}\n";
  auto with = [&](const std::string& page16, const std::string& code_tests) {
    Sources sources = all_without_kernels();
    sources.pages["paper/02_sample.md"] = "# Two {#paper_two}\n\n" + page16 + section("A.5", a5_kernel);
    sources.code["tests/t.cpp"] = code_tests;
    return check(sources);
  };
  SUBCASE("the section is missing") {
    const auto errors = with("", tests);
    CHECK(errors.size() == 1);
    CHECK(mentions(errors, "Eq. (16): no section"));
  }
  SUBCASE("no display formula after the heading") {
    const auto errors = with("### Eq. (16): words {#eq16}\n\nprose first\n" + good_kernel + "\n- test: \\ref tests_eq16\n", tests);
    CHECK(errors.size() == 1);
    CHECK(mentions(errors, "Eq. (16): no display formula"));
  }
  SUBCASE("a wrong anchor") {
    const std::string page = section("16", good_kernel);
    const auto errors = with(page.substr(0, page.find("{#eq16}")) + "{#eq61}" + page.substr(page.find("{#eq16}") + 7), tests);
    CHECK(mentions(errors, "Eq. (16): its heading's anchor is {#eq61}"));
  }
  SUBCASE("neither kernel nor no kernel") {
    const auto errors = with(section("16", "some prose"), tests);
    CHECK(errors.size() == 1);
    CHECK(mentions(errors, "Eq. (16): neither a `- kernel:` line"));
  }
  SUBCASE("a kernel that does not exist in the named file") {
    const auto errors = with(section("16", "- kernel: \\ref mpm::strain_rates \"x\" in mpm/transfer/strain_update.hpp"), tests);
    CHECK(errors.size() == 1);
    CHECK(mentions(errors, "Eq. (16): kernel mpm::strain_rates is not declared in mpm/transfer/strain_update.hpp"));
  }
  SUBCASE("a kernel only called, not declared, in the named file") {
    const auto errors = with(section("16", "- kernel: \\ref mpm::exact::ElasticBar::velocity \"x\" in mpm/exact/bar.hpp"), tests);
    CHECK(mentions(errors, "Eq. (16): kernel mpm::exact::ElasticBar::velocity is not declared"));
  }
  SUBCASE("a kernel in a file that does not exist") {
    const auto errors = with(section("16", "- kernel: \\ref mpm::strain_rate \"x\" in mpm/transfer/strain.hpp"), tests);
    CHECK(mentions(errors, "Eq. (16): kernel mpm::strain_rate: no file mpm/transfer/strain.hpp"));
  }
  SUBCASE("a kernel line without its file") {
    const auto errors = with(section("16", "- kernel: \\ref mpm::strain_rate \"x\""), tests);
    CHECK(mentions(errors, "Eq. (16): a kernel line not of the shape"));
  }
  SUBCASE("a kernel but no test line") {
    const auto errors = with("### Eq. (16): words {#eq16}\n\\f[ a \\f]\n" + good_kernel + "\n", tests);
    CHECK(errors.size() == 1);
    CHECK(mentions(errors, "Eq. (16): no `- test: \\ref tests_eq16"));
  }
  SUBCASE("a test line pointing at another equation's tests") {
    const auto errors = with(section("16", good_kernel, "- test: \\ref tests_eq17 \"x\""), tests);
    CHECK(mentions(errors, "Eq. (16): its test line refers to tests_eq17"));
  }
  SUBCASE("a kernel but no TEST_CASE naming the equation") {
    const auto errors = with(section("16", good_kernel), test_case + "Eq. (161): x\") {}\n" + test_case + "Eq. (A.5): y\") {}\n");
    CHECK(errors.size() == 1);
    CHECK(mentions(errors, "Eq. (16): no TEST_CASE in mpm/ or tests/ names it"));
  }
  SUBCASE("a range that the filter does not match names no equation, and is reported") {
    const auto errors = with(section("16", good_kernel), test_case + "Eqs. (15)-(17): x\") {}\n" + test_case + "Eq. (A.5): y\") {}\n");
    CHECK(errors.size() == 2);
    CHECK(mentions(errors, "Eq. (16): no TEST_CASE"));
    CHECK(mentions(errors, "tests/t.cpp:1: the doctest \"Eqs. (15)-(17): x\" names equations as \"Eqs. (...)\""));
  }
  SUBCASE("the appendix equation loses its test") {
    const auto errors = with(section("16", good_kernel), test_case + "Eq. (16): x\") {}\n" + test_case + "Eq. (A.50): y\") {}\n");
    CHECK(errors.size() == 1);
    CHECK(mentions(errors, "Eq. (A.5): no TEST_CASE"));
  }
  SUBCASE("an equation stated twice, and a heading of the wrong shape") {
    const auto errors = with(section("16", good_kernel) + section("16", good_kernel) + "## Eq. (7): weak form, a level too high and no anchor\n" + "### Eq. (32) is not the Newmark average {#choice_eq32}\n", tests);
    CHECK(errors.size() == 2);  // the other heading about Eq. (32) is prose, not a statement
    CHECK(mentions(errors, "Eq. (16): stated 2 times"));
    CHECK(mentions(errors, "paper/02_sample.md:21: an equation heading not of the shape"));
  }
  SUBCASE("an equation the paper does not have") {
    const auto errors = with(section("16", good_kernel) + section("45", "- no kernel: none"), tests);
    CHECK(mentions(errors, "Eq. (45): not an equation of the paper"));
  }
}

TEST_CASE("docs_trace: the filter check fails, naming the equation, when -tc='*Eq. (N)*' selects no test of an equation with a kernel") {
  Sources sources = all_without_kernels();
  sources.pages["paper/02_sample.md"] =
      "# Two {#paper_two}\n\n" +
      section("16", "- kernel: \\ref mpm::strain_rate \"strain_rate()\" in mpm/transfer/strain_update.hpp") +
      section("A.5", "- kernel: \\ref mpm::exact::ElasticBar::stress \"stress()\" in mpm/exact/bar.hpp");
  sources.code["tests/t.cpp"] = test_case + "Eq. (16): x\") {}\n" + test_case + "Eq. (A.5): y\") {}\n" + test_case +
                                "Eq. (A.5): z\") {}\n";
  std::vector<std::string> asked;
  auto counting = [&](int for16, int forA5) {
    return [&asked, for16, forA5](const std::string& label) {
      asked.push_back(label);
      return label == "16" ? for16 : forA5;
    };
  };
  CHECK(docs_trace::check_filter(sources, counting(1, 2)).empty());
  CHECK(asked == std::vector<std::string>{"16", "A.5"});  // only the equations with a kernel
  const auto none = docs_trace::check_filter(sources, counting(0, 2));
  REQUIRE(none.size() == 1);
  CHECK(none[0] == "Eq. (16): it has a kernel, but mpm_tests -tc='*Eq. (16)*' runs no test case");
  const auto fewer = docs_trace::check_filter(sources, counting(1, 1));
  REQUIRE(fewer.size() == 1);
  CHECK(mentions(fewer, "Eq. (A.5): mpm_tests -tc='*Eq. (A.5)*' runs 1 test cases, the sources name it in 2"));
  const auto broken = docs_trace::check_filter(sources, counting(-1, 2));
  CHECK(mentions(broken, "Eq. (16): the test program did not run"));
}

TEST_CASE("docs_trace: filtered_test_count runs the test program with the filter a user types") {
  CHECK(docs_trace::filtered_test_count(MPM_TESTS_PROGRAM, "16") >= 1);
  CHECK(docs_trace::filtered_test_count(MPM_TESTS_PROGRAM, "45") == 0);
  CHECK(docs_trace::filtered_test_count(MPM_SOURCE_DIR "/no/such/program", "16") == -1);
}

TEST_CASE("docs_trace: the mutants of make mutants on each equation's page of tests") {
  const std::string csv =
      "id,equations,file,what,fate,stage,killed_by,equivalent,seconds\n"
      "gamma_swap,26 29,mpm/transfer/particle_to_grid.hpp,\"gamma for (1 - gamma), |x|\",killed,own doctests,\"Eq. (26): \"\"x\"\"\",,5.0\n"
      "indices,16,mpm/transfer/strain_update.hpp,swapped,survived,mpm_tests,,the symmetric part,80.0\n";
  const auto mutants = docs_trace::mutants_from_csv(csv);
  REQUIRE(mutants.size() == 2);
  CHECK(mutants[0].equations == std::vector<std::string>{"26", "29"});
  CHECK(mutants[0].what == "gamma for (1 - gamma), |x|");
  CHECK(mutants[0].killed_by == "Eq. (26): \"x\"");
  CHECK(mutants[1].equivalent == "the symmetric part");
  Sources sources = all_without_kernels();
  sources.pages["paper/02_sample.md"] =
      "# Two {#paper_two}\n\n" + section("16", "- kernel: \\ref mpm::strain_rate \"strain_rate()\" in mpm/transfer/strain_update.hpp") +
      section("A.5", "- kernel: \\ref mpm::exact::ElasticBar::stress \"stress()\" in mpm/exact/bar.hpp");
  const std::string page = docs_trace::tests_page(sources, mutants);
  CHECK(page.find("2 mutants of the kernels, 1 killed by the tests, 1 surviving as equivalent") != std::string::npos);
  CHECK(page.find("| `indices` | mpm/transfer/strain_update.hpp | `swapped` | `survived (mpm_tests), equivalent: the symmetric part` |  |") !=
        std::string::npos);
  CHECK(page.find("`gamma for (1 - gamma), \u2223x\u2223`") != std::string::npos);  // a bar would end the cell
  CHECK(page.find("No mutant of `make mutants` names Eq. (A.5).") != std::string::npos);
  CHECK(page.find("make mutants` has not been run") == std::string::npos);
  CHECK(docs_trace::tests_page(sources).find("make mutants` has not been run") != std::string::npos);
}

TEST_CASE("docs_trace: a test name with a semicolon is one ctest cannot select, named with its file and line") {
  docs_trace::Sources sources;
  sources.code["mpm/a.hpp"] = std::string("\n") + "TEST_" + "CASE(\"Eq. (16): fine, with a comma\") {}\n" + "TEST_" + "CASE(\"x; y\") {}\n";
  const auto errors = docs_trace::check_ctest_names(sources);
  REQUIRE(errors.size() == 1);
  CHECK(errors[0].rfind("mpm/a.hpp:3: TEST_CASE \"x; y\"", 0) == 0);
}

TEST_CASE("docs_trace: Doxygen's names of source listings and line anchors") {
  CHECK(docs_trace::source_listing_html("mpm/exact/bar.hpp") == "bar_8hpp_source.html");
  CHECK(docs_trace::source_listing_html("mpm/transfer/grid_to_particle.hpp") == "grid__to__particle_8hpp_source.html");
  CHECK(docs_trace::line_anchor(51) == "l00051");
}

TEST_CASE("docs_trace: every equation (1)-(44), (A.1)-(A.19) of paper/ has its statement, kernel and test, and -tc='*Eq. (N)*' runs its tests") {
  const Sources sources = docs_trace::read_sources(MPM_SOURCE_DIR);
  REQUIRE_MESSAGE(!sources.pages.empty(), "no paper/*.md under " MPM_SOURCE_DIR);
  auto errors = check(sources);
  for (const std::string& error :
       docs_trace::check_filter(sources, [](const std::string& label) { return docs_trace::filtered_test_count(MPM_TESTS_PROGRAM, label); }))
    errors.push_back(error);
  for (const std::string& error : docs_trace::check_ctest_names(sources)) errors.push_back(error);
  for (const std::string& error : errors) FAIL_CHECK(error);
  int traced = 0;
  for (const std::string& label : docs_trace::equation_labels())
    traced += mentions(errors, "Eq. (" + label + "): ") ? 0 : 1;
  MESSAGE(traced << " of 63 equations traced to their statement, kernel (or no kernel) and test; " << errors.size()
                 << " problems");
}

int main(int argc, char** argv) {
  if ((argc == 3 || argc == 4) && std::string(argv[1]) == "--tests-page") {
    const auto mutants = argc == 4 ? docs_trace::mutants_from_csv(docs_trace::read_text(argv[3])) : std::vector<docs_trace::MutantRecord>{};
    std::ofstream out(argv[2]);
    out << docs_trace::tests_page(docs_trace::read_sources(MPM_SOURCE_DIR), mutants);
    if (!out) {
      std::cerr << "docs_trace: could not write " << argv[2] << "\n";
      return 1;
    }
    return 0;
  }
  doctest::Context context(argc, argv);
  return context.run();
}
