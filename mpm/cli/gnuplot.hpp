/// \file
/// gnuplot run safely for `mpm plot` and `mpm compare --plot`: every string in a script single-quoted (a name
/// with a control character refused before), each file made afresh (never through a symbolic link), gnuplot
/// started without a shell, and each picture checked complete to its end chunk (gnuplot exits 0 on a failed write).
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/io/output_file.hpp"
#include "mpm_generated/palette_gp.hpp"

namespace mpm::cli {

/// `text` as a gnuplot single-quoted string ('it''s': no escape, backquote or macro works inside).
inline std::string gnuplot_quoted(const std::string& text) {
  std::string result = "'";
  for (char character : text) result += character == '\'' ? std::string("''") : std::string(1, character);
  return result + "'";
}

/// True if `text` holds a control character (a newline, a tab, a NUL, DEL...).
inline bool has_control_character(const std::string& text) {
  return std::any_of(text.begin(), text.end(),
                     [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

/// The settings every picture starts with: the figures' one visual identity (verification/plots/palette.gp, built
/// in as gnuplot_palette: colours, dashes, the exact solution's style, the ramp), CSV data, a grid, the key outside,
/// t on the x axis.
inline const std::string gnuplot_preamble =
    std::string(gnuplot_palette) +
    "\nset datafile separator ','\nset grid lc rgb c_grid\nset key outside right top\nset lmargin 14\n"
    "set xlabel 't (s)'\n";

/// The style of curve `k` (from 0) of `count` drawn by `mpm plot` or `mpm compare --plot`: the palette's ramp, the
/// same colour for the same observer in every panel.
inline std::string gnuplot_curve_style(std::size_t k, std::size_t count) {
  return "lw 1.5 lc rgb ramp(" + std::to_string(k + 1) + ", " + std::to_string(count) + ")";
}

/// The lines starting a PNG `picture` of `panels` panels stacked, 260 pixels high each; a relative path is
/// written ./PATH, so that it never starts with '|' (gnuplot would run it as a command).
inline std::string gnuplot_page(const std::string& picture, std::size_t panels) {
  std::ostringstream page;
  page << "set terminal pngcairo noenhanced size 1000," << 260 * panels << " font ',11'\nset output "
       << gnuplot_quoted(picture.rfind('/', 0) == 0 ? picture : "./" + picture) << "\nset multiplot layout " << panels
       << ",1\n";
  return page.str();
}

/// Writes `text` into `path` atomically: a symbolic link at `path` is replaced, never followed; a folder in the
/// way is refused. \throws OutputFailure.
inline void write_fresh(const std::string& path, const std::string& text) { io::write_file(path, text); }

/// True if the file `path` (not a symbolic link) is a complete PNG: its signature first and the IEND chunk
/// (length 0, type, CRC) last.
inline bool png_file_complete(const std::string& path) {
  static const std::string signature("\x89PNG\r\n\x1a\n", 8), last("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  struct stat status {};
  std::string start(8, '\0'), end(12, '\0');
  const bool read = descriptor >= 0 && ::fstat(descriptor, &status) == 0 && S_ISREG(status.st_mode) &&
                    status.st_size >= 20 && ::pread(descriptor, &start[0], 8, 0) == 8 &&
                    ::pread(descriptor, &end[0], 12, status.st_size - 12) == 12;
  if (descriptor >= 0) ::close(descriptor);
  return read && start == signature && end == last;
}

/// Runs gnuplot without a shell in `folder` ("" for here) on `script`, given on its standard input from an
/// unnamed temporary file; `log` gets the first 64 KiB it printed. Returns its exit status (127: not started).
inline int run_gnuplot(const std::string& folder, const std::string& script, std::string& log) {
  std::FILE* input = std::tmpfile();
  std::FILE* output = std::tmpfile();
  int status = 127 << 8;
  if (input && output && std::fwrite(script.data(), 1, script.size(), input) == script.size() &&
      std::fflush(input) == 0 && ::lseek(fileno(input), 0, SEEK_SET) == 0) {
    const pid_t child = ::fork();
    if (child == 0) {  // only system calls here, then exec
      if ((!folder.empty() && ::chdir(folder.c_str()) != 0) || ::dup2(fileno(input), 0) < 0 ||
          ::dup2(fileno(output), 1) < 0 || ::dup2(fileno(output), 2) < 0)
        ::_exit(127);
      ::execlp("gnuplot", "gnuplot", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    while (child > 0 && ::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    log.assign(1 << 16, '\0');
    const ssize_t count = ::pread(fileno(output), &log[0], log.size(), 0);
    log.resize(count > 0 ? static_cast<std::size_t>(count) : 0);
  }
  for (std::FILE* file : {input, output})
    if (file) std::fclose(file);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// Draws `pictures` (paths from here) with gnuplot running `script` in `folder`, each picture made afresh first;
/// gnuplot's messages go into `log_path` (or, when it is "", their first line into the error).
/// \throws OutputFailure naming the first picture not drawn whole; the pictures are then removed.
inline void draw_with_gnuplot(const std::string& folder, const std::string& script,
                              const std::vector<std::string>& pictures, const std::string& log_path = "") {
  std::string log, reason, picture = pictures.front();
  try {
    for (const auto& fresh : pictures) write_fresh(fresh, "");
    const int status = run_gnuplot(folder, script, log);
    if (!log_path.empty()) write_fresh(log_path, log);
    const auto incomplete = std::find_if_not(pictures.begin(), pictures.end(), png_file_complete);
    if (status != 0) reason = "gnuplot failed (status " + std::to_string(status) + "; is gnuplot installed? make deps)";
    if (status == 0 && incomplete != pictures.end()) {
      reason = "gnuplot left it incomplete (no PNG end chunk)";
      picture = *incomplete;
    }
  } catch (const OutputFailure&) {
    for (const auto& made : pictures) ::unlink(made.c_str());
    throw;
  }
  if (reason.empty()) return;
  for (const auto& made : pictures) ::unlink(made.c_str());  // not whole: not to be taken for a picture
  log = log.substr(0, log.find_first_of("\r\n"));
  throw OutputFailure(picture, reason + (!log_path.empty() ? ": see " + log_path : log.empty() ? "" : ": " + log));
}

TEST_CASE(
    "gnuplot: strings quoted, control characters found, files made afresh, PNGs complete only to their end chunk") {
  CHECK(gnuplot_quoted("A.x' . system('touch F') . '") == "'A.x'' . system(''touch F'') . '''");
  CHECK(has_control_character("a\nb"));
  CHECK(has_control_character(std::string("a\0b", 3)));
  CHECK(!has_control_character("sigma_xx (Pa) \xc3\xa9"));  // UTF-8 is no control character
  CHECK(gnuplot_page("|touch F.png", 1).find("set output './|touch F.png'\n") != std::string::npos);
  CHECK(gnuplot_page("/tmp/a.png", 2).find("size 1000,520 font ',11'\nset output '/tmp/a.png'") != std::string::npos);
  namespace fs = std::filesystem;
  const std::string path =
      (fs::temp_directory_path() / ("mpm_gnuplot_test_" + std::to_string(::getpid()) + ".png")).string();
  const std::string target = path + ".target";
  const std::string signature("\x89PNG\r\n\x1a\n", 8), iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  const std::string whole = signature + std::string("\0\0\0\rIHDR...", 11) + iend;
  write_fresh(target, "precious");
  fs::remove(path);
  fs::create_symlink(target, path);
  write_fresh(path, whole);  // the link removed, a file made in its place
  CHECK(!fs::is_symlink(path));
  CHECK(png_file_complete(path));
  CHECK(fs::file_size(target) == 8);                     // the link's target untouched
  write_fresh(path, whole.substr(0, whole.size() - 1));  // the last byte of the CRC missing
  CHECK(!png_file_complete(path));
  write_fresh(path, "GIF89a.." + whole.substr(8));
  CHECK(!png_file_complete(path));
  fs::remove(path);
  fs::create_directory(path);
  CHECK_THROWS_AS(write_fresh(path, whole), OutputFailure);
  CHECK(!png_file_complete(path));
  fs::remove(path);
  fs::remove(target);
  std::string log;
  CHECK(run_gnuplot("/nonexistent/folder", "", log) == 127);  // no such folder: gnuplot never started
  CHECK_THROWS_WITH_AS(draw_with_gnuplot("/nonexistent/folder", "", {path}),
                       doctest::Contains("gnuplot failed (status 127"), OutputFailure);
  CHECK(!fs::exists(path));  // made, then removed: not whole
}

}  // namespace mpm::cli
