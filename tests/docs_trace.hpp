/// \file
/// The trace from each equation of the paper to its kernel and its test, read from the sources.
///
/// paper/*.md states every equation (1)-(44) and (A.1)-(A.19) in a section of the shape fixed by the
/// docs contract:
///
///     ### Eq. (16): rate of deformation at a particle {#eq16}
///     \f[ ... \f]
///     - kernel: \ref mpm::strain_rate "strain_rate()" in mpm/transfer/strain_update.hpp
///     - test: \ref tests_eq16 "doctests of Eq. (16)"
///
/// or `- no kernel: <why>` instead of the kernel line. The doctests of mpm/ and tests/ name the equations
/// they check in their TEST_CASE names, each on its own ("Eq. (16): ...", "Eq. (A.5), Eq. (A.19): ..."),
/// so that `mpm_tests -tc='*Eq. (N)*'` runs them; a range "Eqs. (19)-(22)" is reported as a problem.
/// This header parses both and lists what is missing (tests/docs_trace.cpp runs it under ctest), and
/// writes the page of tests by equation that `make docs` renders (anchors tests_eq16, tests_eqA5).
/// It knows no part of the solver: it reads text only.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace docs_trace {

/// The 63 equation labels in paper order: "1" ... "44", "A.1" ... "A.19".
inline std::vector<std::string> equation_labels() {
  std::vector<std::string> labels;
  for (int n = 1; n <= 44; ++n) labels.push_back(std::to_string(n));
  for (int n = 1; n <= 19; ++n) labels.push_back("A." + std::to_string(n));
  return labels;
}

/// "16" -> "16", "A.5" -> "A5": the suffix of the anchors eq16, tests_eqA5.
inline std::string anchor_suffix(const std::string& label) {
  std::string suffix;
  for (char c : label)
    if (c != '.') suffix += c;
  return suffix;
}

/// Every equation a text names as "Eq. (16)" or "Eq. (A.5)", in order, each once: exactly the labels N
/// for which doctest's filter `-tc='*Eq. (N)*'` (a wildcard match that ignores case) selects a test of
/// that name. A range or list after "Eqs." ("Eqs. (19)-(22)", "Eqs. (14), (15)") names nothing: the
/// filter a user types for Eq. (20) would not run such a test.
inline std::vector<std::string> equations_named(const std::string& text) {
  static const std::regex named(R"(eq\. \(((?:A\.)?[0-9]{1,3})\))", std::regex::icase);
  std::vector<std::string> labels;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), named); it != std::sregex_iterator(); ++it) {
    std::string label = (*it)[1].str();
    if (!label.empty() && label[0] == 'a') label[0] = 'A';
    if (std::find(labels.begin(), labels.end(), label) == labels.end()) labels.push_back(label);
  }
  return labels;
}

/// True when a text gives equations as "Eqs. (...)" (a range or a list), which no filter
/// `-tc='*Eq. (N)*'` matches.
inline bool names_equations_in_plural(const std::string& text) {
  static const std::regex plural(R"(eqs\. \()", std::regex::icase);
  return std::regex_search(text, plural);
}

/// One doctest: its name, and where it is (path relative to the source root, 1-based line).
struct TestCase {
  std::string name;
  std::string file;
  int line = 0;
};

/// The TEST_CASE("...") names in one file's text.
inline std::vector<TestCase> test_cases_in(const std::string& text, const std::string& file) {
  std::vector<TestCase> found;
  const std::string opening = std::string("TEST_") + "CASE(\"";  // split: this file is not a test file
  std::size_t at = 0;
  while ((at = text.find(opening, at)) != std::string::npos) {
    const std::size_t start = at + opening.size();
    std::string name;
    std::size_t i = start;
    for (; i < text.size() && text[i] != '"' && text[i] != '\n'; ++i) {
      if (text[i] == '\\' && i + 1 < text.size()) ++i;
      name += text[i];
    }
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    found.push_back({name, file, line});
    at = i;
  }
  return found;
}

/// One `- kernel:` reference: the qualified name and the file it is said to be in.
struct KernelReference {
  std::string qualified_name;  ///< e.g. mpm::strain_rate
  std::string file;            ///< e.g. mpm/transfer/strain_update.hpp
};

/// One equation's section of a paper page.
struct Section {
  std::string label;      ///< "16", "A.5"
  std::string title;      ///< the words after "Eq. (16): "
  std::string page_file;  ///< paper/02_mpm_forward_euler.md
  std::string page_id;    ///< the page's id, from `{#id}` on its first line
  int line = 0;
  std::string anchor;     ///< what the heading's `{#...}` says
  bool has_display_formula = false;
  std::string formula;    ///< the text between `\f[` and `\f]`
  std::vector<KernelReference> kernels;
  std::vector<std::string> malformed_kernel_lines;
  bool no_kernel = false;
  std::string test_anchor;  ///< the target of the `\ref` on the `- test:` line, empty if none
};

inline std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

/// The equation sections of one Markdown page, and every line that looks like an equation heading but
/// is not of the contract's shape (reported as problems).
inline std::vector<Section> sections_in(const std::string& text, const std::string& page_file,
                                        std::vector<std::string>& problems) {
  static const std::regex page_title(R"(^# .*\{#([A-Za-z0-9_]+)\}\s*$)");
  static const std::regex heading(R"(^### Eqs?\. \(([^)]*)\): (.+?) \{#([A-Za-z0-9_]+)\}\s*$)");
  static const std::regex loose_heading(R"(^#{1,6} Eqs?\. \([^)]*\):)");
  static const std::regex reference(R"(\\ref\s+(mpm::[A-Za-z0-9_:]+))");
  static const std::regex in_file(R"(\bin\s+`?((?:mpm|tests|verification)/[A-Za-z0-9_/]+\.(?:hpp|cpp))`?)");
  static const std::regex test_reference(R"(^- test:\s*\\ref\s+([A-Za-z0-9_]+))");
  std::vector<Section> sections;
  std::istringstream lines(text);
  std::string line, page_id;
  int number = 0;
  Section* current = nullptr;
  bool expecting_formula = false, in_formula = false;
  while (std::getline(lines, line)) {
    ++number;
    std::smatch match;
    if (number == 1 && std::regex_match(line, match, page_title)) page_id = match[1].str();
    if (std::regex_match(line, match, heading)) {
      Section section;
      section.label = match[1].str();
      section.title = match[2].str();
      section.anchor = match[3].str();
      section.page_file = page_file;
      section.page_id = page_id;
      section.line = number;
      sections.push_back(section);
      current = &sections.back();
      expecting_formula = true;
      in_formula = false;
      continue;
    }
    if (std::regex_search(line, loose_heading)) {
      problems.push_back(page_file + ":" + std::to_string(number) +
                         ": an equation heading not of the shape `### Eq. (N): words {#eqN}`: " + line);
      current = nullptr;
      continue;
    }
    if (!line.empty() && line[0] == '#') {  // any other heading ends the section
      current = nullptr;
      continue;
    }
    if (current == nullptr) continue;
    const std::string stripped = trim(line);
    if (in_formula) {
      const auto close = stripped.find("\\f]");
      current->formula += " " + stripped.substr(0, close);
      if (close != std::string::npos) {
        in_formula = false;
        current->has_display_formula = !trim(current->formula).empty();
      }
      continue;
    }
    if (expecting_formula && !stripped.empty()) {
      expecting_formula = false;
      if (stripped.rfind("\\f[", 0) == 0) {
        const std::string rest = stripped.substr(3);
        const auto close = rest.find("\\f]");
        current->formula = rest.substr(0, close);
        if (close == std::string::npos)
          in_formula = true;
        else
          current->has_display_formula = !trim(current->formula).empty();
        continue;
      }
    }
    if (stripped.rfind("- kernel:", 0) == 0) {
      std::smatch file_match;
      std::vector<std::string> names;
      for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), reference); it != std::sregex_iterator(); ++it)
        names.push_back((*it)[1].str());
      if (names.empty() || !std::regex_search(stripped, file_match, in_file)) {
        current->malformed_kernel_lines.push_back(stripped);
        continue;
      }
      for (const std::string& name : names) current->kernels.push_back({name, file_match[1].str()});
    } else if (stripped.rfind("- no kernel:", 0) == 0) {
      current->no_kernel = !trim(stripped.substr(12)).empty();
      if (!current->no_kernel) current->malformed_kernel_lines.push_back(stripped + " (gives no reason)");
    } else {
      std::smatch test_match;
      if (std::regex_search(stripped, test_match, test_reference)) current->test_anchor = test_match[1].str();
    }
  }
  return sections;
}

/// The last component and the enclosing ones of "mpm::exact::ElasticBar::velocity".
inline std::vector<std::string> name_components(const std::string& qualified_name) {
  std::vector<std::string> parts;
  std::size_t start = 0, at;
  while ((at = qualified_name.find("::", start)) != std::string::npos) {
    parts.push_back(qualified_name.substr(start, at - start));
    start = at + 2;
  }
  parts.push_back(qualified_name.substr(start));
  return parts;
}

/// True when `text` (a header) declares `qualified_name`: its last component as a function
/// (a type or `auto` before the name, a parameter list after it), a class, struct, enum or alias, and
/// every enclosing class or namespace as a word of the file.
inline bool declares(const std::string& text, const std::string& qualified_name) {
  const std::vector<std::string> parts = name_components(qualified_name);
  if (parts.size() < 2 || parts.front() != "mpm") return false;
  for (std::size_t i = 1; i + 1 < parts.size(); ++i)
    if (!std::regex_search(text, std::regex("\\b" + parts[i] + "\\b"))) return false;
  const std::string& name = parts.back();
  if (std::regex_search(text, std::regex("\\b(class|struct|enum class|enum|using)\\s+" + name + "\\b"))) return true;
  const std::regex function("([A-Za-z0-9_>&*:]+)\\s+[&*]?" + name + "\\s*\\(");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), function); it != std::sregex_iterator(); ++it) {
    const std::string before = (*it)[1].str();
    if (before != "return" && before != "new" && before != "else" && before != "throw" && before != "case") return true;
  }
  return false;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// What the checker reads: page texts by their path (paper/...), source texts by their path (mpm/..., tests/...).
struct Sources {
  std::map<std::string, std::string> pages;
  std::map<std::string, std::string> code;
};

/// Reads paper/*.md, and every .hpp and .cpp under mpm/ and tests/, below `root`. The checker's own
/// files (tests/docs_*) hold synthetic sections and test names for its doctests, so they are skipped.
inline Sources read_sources(const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  Sources sources;
  if (fs::is_directory(root / "paper"))
    for (const auto& entry : fs::directory_iterator(root / "paper"))
      if (entry.is_regular_file() && entry.path().extension() == ".md")
        sources.pages["paper/" + entry.path().filename().string()] = read_text(entry.path());
  for (const char* folder : {"mpm", "tests"}) {
    if (!fs::is_directory(root / folder)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
      const auto extension = entry.path().extension();
      if (!entry.is_regular_file() || (extension != ".hpp" && extension != ".cpp")) continue;
      const std::string relative = fs::relative(entry.path(), root).generic_string();
      if (relative.rfind("tests/docs_", 0) == 0) continue;
      sources.code[relative] = read_text(entry.path());
    }
  }
  return sources;
}

/// Everything parsed: the sections by label (several if a label is stated twice) and the test cases.
struct Trace {
  std::map<std::string, std::vector<Section>> sections;
  std::vector<TestCase> test_cases;
  std::map<std::string, std::vector<TestCase>> tests_by_equation;
  std::vector<std::string> problems;  ///< parse problems (malformed headings)
};

inline Trace trace(const Sources& sources) {
  Trace result;
  for (const auto& [file, text] : sources.pages)
    for (const Section& section : sections_in(text, file, result.problems))
      result.sections[section.label].push_back(section);
  for (const auto& [file, text] : sources.code)
    for (const TestCase& test : test_cases_in(text, file)) {
      result.test_cases.push_back(test);
      if (names_equations_in_plural(test.name))
        result.problems.push_back(test.file + ":" + std::to_string(test.line) + ": the doctest \"" + test.name +
                                  "\" names equations as \"Eqs. (...)\", which no filter -tc='*Eq. (N)*' runs: "
                                  "write \"Eq. (N)\" for each");
      std::set<std::string> labels;
      for (const std::string& label : equations_named(test.name)) labels.insert(label);
      for (const std::string& label : labels) result.tests_by_equation[label].push_back(test);
    }
  return result;
}

/// Every way the sources break the contract, each message starting with the equation it concerns.
inline std::vector<std::string> check(const Sources& sources) {
  const Trace parsed = trace(sources);
  std::vector<std::string> errors = parsed.problems;
  const std::vector<std::string> labels = equation_labels();
  const std::set<std::string> known(labels.begin(), labels.end());
  for (const auto& [label, sections] : parsed.sections)
    if (known.count(label) == 0)
      for (const Section& section : sections)
        errors.push_back("Eq. (" + label + "): not an equation of the paper, stated at " + section.page_file + ":" +
                         std::to_string(section.line));
  for (const std::string& label : labels) {
    const std::string eq = "Eq. (" + label + "): ";
    const auto found = parsed.sections.find(label);
    if (found == parsed.sections.end()) {
      errors.push_back(eq + "no section `### Eq. (" + label + "): ... {#eq" + anchor_suffix(label) + "}` in paper/*.md");
      continue;
    }
    if (found->second.size() > 1) {
      std::string where;
      for (const Section& section : found->second) where += " " + section.page_file + ":" + std::to_string(section.line);
      errors.push_back(eq + "stated " + std::to_string(found->second.size()) + " times:" + where);
    }
    const Section& section = found->second.front();
    const std::string at = " (" + section.page_file + ":" + std::to_string(section.line) + ")";
    if (section.anchor != "eq" + anchor_suffix(label))
      errors.push_back(eq + "its heading's anchor is {#" + section.anchor + "}, not {#eq" + anchor_suffix(label) + "}" + at);
    if (!section.has_display_formula)
      errors.push_back(eq + "no display formula \\f[ ... \\f] right after its heading" + at);
    for (const std::string& malformed : section.malformed_kernel_lines)
      errors.push_back(eq + "a kernel line not of the shape `- kernel: \\ref mpm::name \"text\" in path/file.hpp` "
                       "(or `- no kernel: why`): " + malformed + at);
    if (section.kernels.empty() && !section.no_kernel) {
      errors.push_back(eq + "neither a `- kernel:` line nor a `- no kernel: why` line" + at);
    }
    for (const KernelReference& kernel : section.kernels) {
      const auto code = sources.code.find(kernel.file);
      if (code == sources.code.end()) {
        errors.push_back(eq + "kernel " + kernel.qualified_name + ": no file " + kernel.file + at);
      } else if (!declares(code->second, kernel.qualified_name)) {
        errors.push_back(eq + "kernel " + kernel.qualified_name + " is not declared in " + kernel.file + at);
      }
    }
    const std::string test_anchor = "tests_eq" + anchor_suffix(label);
    const bool has_tests = parsed.tests_by_equation.count(label) > 0;
    if (!section.kernels.empty() && section.test_anchor.empty())
      errors.push_back(eq + "no `- test: \\ref " + test_anchor + " \"...\"` line" + at);
    if (!section.test_anchor.empty() && section.test_anchor != test_anchor)
      errors.push_back(eq + "its test line refers to " + section.test_anchor + ", not " + test_anchor + at);
    if ((!section.kernels.empty() || !section.test_anchor.empty()) && !has_tests)
      errors.push_back(eq + "no TEST_CASE in mpm/ or tests/ names it (\"Eq. (" + label + "): ...\")");
  }
  return errors;
}

/// The TEST_CASEs that ctest would never run: doctest_discover_tests registers each name as a CMake list
/// element, so a ';' cuts the name, and ctest's `--test-case=` filter then selects no test case (and passes).
/// One message per such name, with its file and line.
inline std::vector<std::string> check_ctest_names(const Sources& sources) {
  std::vector<std::string> errors;
  for (const auto& [file, text] : sources.code)
    for (const TestCase& test : test_cases_in(text, file))
      if (test.name.find(';') != std::string::npos)
        errors.push_back(file + ":" + std::to_string(test.line) + ": TEST_CASE \"" + test.name +
                         "\": a ';' in its name cuts it for ctest, which then runs no test case; write ',' instead");
  return errors;
}

/// The filter a user types for the tests of one equation: `*Eq. (16)*`, given to `-tc=`.
inline std::string equation_filter(const std::string& label) { return "*Eq. (" + label + ")*"; }

/// How many test cases `program --list-test-cases -tc='*Eq. (N)*'` lists (doctest's own count of the
/// test cases passing the filter), or -1 when the program cannot be run or says no count.
inline int filtered_test_count(const std::string& program, const std::string& label) {
  const std::string command = "'" + program + "' --list-test-cases '-tc=" + equation_filter(label) + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return -1;
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = pclose(pipe);
  static const std::regex count_line(R"(unskipped test cases passing the current filters: ([0-9]+))");
  std::smatch match;
  if (status != 0 || !std::regex_search(output, match, count_line)) return -1;
  return std::stoi(match[1].str());
}

/// The equations with a kernel that the filter `-tc='*Eq. (N)*'` does not reach: `count(label)` says how
/// many test cases the filter selects (filtered_test_count on the test program in the real check), and
/// it must be at least one, and as many as the TEST_CASEs of the sources that name the equation (fewer
/// means a test file is not compiled into the program). One message per equation, naming it.
inline std::vector<std::string> check_filter(const Sources& sources, const std::function<int(const std::string&)>& count) {
  const Trace parsed = trace(sources);
  std::vector<std::string> errors;
  for (const std::string& label : equation_labels()) {
    const auto found = parsed.sections.find(label);
    if (found == parsed.sections.end() || found->second.front().kernels.empty()) continue;
    const std::string filter = "-tc='" + equation_filter(label) + "'";
    const int selected = count(label);
    const auto named = parsed.tests_by_equation.find(label);
    const int in_sources = named == parsed.tests_by_equation.end() ? 0 : static_cast<int>(named->second.size());
    if (selected < 0)
      errors.push_back("Eq. (" + label + "): the test program did not run with " + filter + " (is it built?)");
    else if (selected == 0)
      errors.push_back("Eq. (" + label + "): it has a kernel, but mpm_tests " + filter + " runs no test case");
    else if (selected < in_sources)
      errors.push_back("Eq. (" + label + "): mpm_tests " + filter + " runs " + std::to_string(selected) + " test cases, "
                       "the sources name it in " + std::to_string(in_sources));
  }
  return errors;
}

/// The Doxygen HTML file of a source file's listing: mpm/exact/bar.hpp -> bar_8hpp_source.html
/// (Doxygen's escaping of the file name; the paths of this project have distinct file names).
inline std::string source_listing_html(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  std::string escaped;
  for (char c : name) {
    if (c == '_') escaped += "__";
    else if (c == '.') escaped += "_8";
    else if (c == '-') escaped += "-";
    else if (std::isupper(static_cast<unsigned char>(c))) escaped += std::string("_") + static_cast<char>(std::tolower(c));
    else escaped += c;
  }
  return escaped + "_source.html";
}

/// Doxygen's line anchor in a source listing: line 51 -> l00051.
inline std::string line_anchor(int line) {
  std::string digits = std::to_string(line);
  while (digits.size() < 5) digits = "0" + digits;
  return "l" + digits;
}

inline std::string html_escape(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    if (c == '<') escaped += "&lt;";
    else if (c == '>') escaped += "&gt;";
    else if (c == '&') escaped += "&amp;";
    else if (c == '"') escaped += "&quot;";
    else escaped += c;
  }
  return escaped;
}

/// One mutant of `make mutants`, as results/mutants/mutants.csv records it.
struct MutantRecord {
  std::string id, file, what, fate, stage, killed_by, equivalent;
  std::vector<std::string> equations;
};

/// The rows of a CSV text (RFC 4180: fields in double quotes may hold commas, newlines and "" for ").
inline std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false, any = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
      continue;
    }
    if (c == '"') {
      quoted = any = true;
    } else if (c == ',') {
      row.push_back(field);
      field.clear();
      any = true;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      if (any || !field.empty()) {
        row.push_back(field);
        rows.push_back(row);
      }
      row.clear();
      field.clear();
      any = false;
    } else {
      field += c;
      any = true;
    }
  }
  if (any || !field.empty()) {
    row.push_back(field);
    rows.push_back(row);
  }
  return rows;
}

/// The mutants of results/mutants/mutants.csv (columns by their header's names); empty for an empty text.
inline std::vector<MutantRecord> mutants_from_csv(const std::string& text) {
  const auto rows = csv_rows(text);
  std::vector<MutantRecord> mutants;
  if (rows.empty()) return mutants;
  std::map<std::string, std::size_t> column;
  for (std::size_t i = 0; i < rows[0].size(); ++i) column[rows[0][i]] = i;
  auto field = [&](const std::vector<std::string>& row, const std::string& name) {
    const auto at = column.find(name);
    return at != column.end() && at->second < row.size() ? row[at->second] : std::string();
  };
  for (std::size_t r = 1; r < rows.size(); ++r) {
    MutantRecord m{field(rows[r], "id"), field(rows[r], "file"), field(rows[r], "what"), field(rows[r], "fate"),
                   field(rows[r], "stage"), field(rows[r], "killed_by"), field(rows[r], "equivalent"), {}};
    std::istringstream labels(field(rows[r], "equations"));
    for (std::string label; labels >> label;) m.equations.push_back(label);
    mutants.push_back(m);
  }
  return mutants;
}

/// A table cell's text as a code span: no line breaks, no backquotes, and U+2223 for the bar of |x|
/// (a bar would end the cell).
inline std::string code_cell(const std::string& text) {
  std::string out = "`";
  for (char c : text) {
    if (c == '\n' || c == '\r') out += ' ';
    else if (c == '`') out += '\'';
    else if (c == '|') out += "\u2223";
    else out += c;
  }
  return out + "`";
}

/// The page of tests by equation (Doxygen Markdown): one subpage per equation, id tests_eq16 or
/// tests_eqA5 and title "Eq. (16): <its title on the paper page>" (so the search box finds
/// "Eq. (16)"), linking back to the statement and listing every TEST_CASE that names the equation,
/// with a link to its line in the source listing.
inline std::string mutants_of(const std::vector<MutantRecord>& mutants, const std::string& label) {
  std::ostringstream table;
  table << "| mutant | file | what it changes | fate | killed by |\n|---|---|---|---|---|\n";
  int count = 0;
  for (const MutantRecord& m : mutants) {
    if (std::find(m.equations.begin(), m.equations.end(), label) == m.equations.end()) continue;
    ++count;
    std::string fate = m.fate + (m.stage.empty() ? "" : " (" + m.stage + ")");
    if (!m.equivalent.empty()) fate += ", equivalent: " + m.equivalent;
    table << "| " << code_cell(m.id) << " | " << m.file << " | " << code_cell(m.what) << " | " << code_cell(fate) << " | "
          << (m.killed_by.empty() ? "" : code_cell(m.killed_by)) << " |\n";
  }
  return count == 0 ? "" : table.str();
}

/// `mutants`: the records of results/mutants/mutants.csv (make mutants), shown on each equation's page;
/// empty when make mutants has not been run.
inline std::string tests_page(const Sources& sources, const std::vector<MutantRecord>& mutants = {}) {
  const Trace parsed = trace(sources);
  std::ostringstream page;
  page << "# Tests by equation {#tests_by_equation}\n\n"
       << "Generated by `make docs` from the `TEST_CASE` names of mpm/ and tests/: a doctest checks an equation "
          "when its name says so, each equation on its own (\"Eq. (16): ...\", \"Eq. (19), Eq. (20): ...\"). "
          "Run the tests of one equation with `build/bin/mpm_tests -tc=\"*Eq. (16)*\"`; the check `docs_trace` (run by "
          "ctest) fails when an equation of the paper has a kernel but that filter runs no test.\n\n";
  if (mutants.empty()) {
    page << "`make mutants` has not been run here (results/mutants/mutants.csv): run it, then `make docs`, for the "
            "mutants of each equation's kernels and their fate.\n\n";
  } else {
    int killed = 0, equivalent = 0;
    for (const MutantRecord& m : mutants) {
      killed += m.fate == "killed" ? 1 : 0;
      equivalent += m.fate == "survived" && !m.equivalent.empty() ? 1 : 0;
    }
    page << "Mutants (`make mutants`, tests/mutants/mutants.tsv, fates from results/mutants/mutants.csv): " << mutants.size()
         << " mutants of the kernels, " << killed << " killed by the tests, " << equivalent
         << " surviving as equivalent (each with its reason), " << mutants.size() - killed - equivalent << " other. "
         << "Each equation's page lists its mutants.\n\n";
  }
  page << "| equation | stated on | doctests | mutants killed |\n|---|---|---|---|\n";
  for (const std::string& label : equation_labels()) {
    const auto tests = parsed.tests_by_equation.find(label);
    const std::size_t count = tests == parsed.tests_by_equation.end() ? 0 : tests->second.size();
    const auto section = parsed.sections.find(label);
    page << "| \\ref tests_eq" << anchor_suffix(label) << " \"Eq. (" << label << ")\" | ";
    if (section != parsed.sections.end()) page << "\\ref eq" << anchor_suffix(label) << " \"" << section->second.front().title << "\"";
    int of_label = 0, killed = 0;
    for (const MutantRecord& m : mutants)
      if (std::find(m.equations.begin(), m.equations.end(), label) != m.equations.end()) {
        ++of_label;
        killed += m.fate == "killed" ? 1 : 0;
      }
    page << " | " << count << " | ";
    if (of_label > 0) page << killed << " of " << of_label;
    page << " |\n";
  }
  page << "\n";
  for (const std::string& label : equation_labels()) page << "- \\subpage tests_eq" << anchor_suffix(label) << "\n";
  page << "\n";
  for (const std::string& label : equation_labels()) {
    const auto section = parsed.sections.find(label);
    const std::string title = section != parsed.sections.end() ? section->second.front().title : "not stated on any page";
    page << "\\page tests_eq" << anchor_suffix(label) << " Eq. (" << label << "): " << title << "\n\n";
    if (section != parsed.sections.end()) {
      const Section& stated = section->second.front();
      page << "Stated in \\ref eq" << anchor_suffix(label) << " \"Eq. (" << label << ")\"";
      if (!stated.page_id.empty()) page << " of \\ref " << stated.page_id;
      page << ".";
      if (stated.has_display_formula) page << "\n\\f[" << stated.formula << "\\f]\n";
      page << "\n\n";
      for (const KernelReference& kernel : stated.kernels)
        page << "- kernel: \\ref " << kernel.qualified_name << " in " << kernel.file << "\n";
      if (stated.no_kernel) page << "- no kernel (see the statement)\n";
      page << "\n";
    }
    const auto tests = parsed.tests_by_equation.find(label);
    if (tests == parsed.tests_by_equation.end()) {
      page << "No doctest names Eq. (" << label << ").\n\n";
    } else {
      page << "Doctests that name Eq. (" << label << ") (`build/bin/mpm_tests -tc=\"*Eq. (" << label << ")*\"` runs them):\n\n";
      for (const TestCase& test : tests->second)
        page << "- <a href=\"" << source_listing_html(test.file) << "#" << line_anchor(test.line) << "\">" << test.file << ":"
             << test.line << "</a>: `" << test.name << "`\n";
      page << "\n";
    }
    const std::string table = mutants_of(mutants, label);
    if (!table.empty())
      page << "Mutants of its kernels (`make mutants`; a mutant is killed when a test fails; \"own doctests\": those of "
              "the mutated header, \"mpm_tests\": the whole test program):\n\n" << table << "\n";
    else if (!mutants.empty() && section != parsed.sections.end() && !section->second.front().kernels.empty())
      page << "No mutant of `make mutants` names Eq. (" << label << ").\n\n";
  }
  return page.str();
}

}  // namespace docs_trace
