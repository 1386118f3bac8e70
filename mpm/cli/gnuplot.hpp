/// \file
/// Running gnuplot safely, for `mpm plot` and `mpm compare --plot`:
/// - every string written into a script is a gnuplot single-quoted string (no escapes but '' for a quote, no
///   backquote or macro substitution inside), and strings holding a control character are refused before, so
///   that a name read from a CSV header cannot end the string and run a command;
/// - an output name never starts with '|' (gnuplot would run it as a shell command);
/// - each file the CLI creates (script, log, picture) is created afresh: an existing file or symbolic link of
///   that name is removed, never followed, and a folder of that name refused;
/// - gnuplot is started without a shell (fork and execvp), and each picture is checked complete afterwards
///   (the PNG signature at its start, the IEND chunk at its end): gnuplot exits 0 on a failed write.
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

namespace mpm::cli {

/// `text` as a gnuplot single-quoted string: 'it''s'.
inline std::string gnuplot_quoted(const std::string& text) {
  std::string result = "'";
  for (char character : text) result += character == '\'' ? std::string("''") : std::string(1, character);
  return result + "'";
}

/// True if `text` holds a control character (a newline, a tab, a NUL, DEL...).
inline bool has_control_character(const std::string& text) {
  for (char character : text)
    if (static_cast<unsigned char>(character) < 0x20 || character == 0x7f) return true;
  return false;
}

/// A path as gnuplot's `set output` may take it: a relative one starts with ./ so that it never starts with '|'.
inline std::string gnuplot_output_path(const std::string& path) { return path.rfind('/', 0) == 0 ? path : "./" + path; }

/// Creates `path` afresh for writing (an existing file or symbolic link of that name removed first, never
/// followed; a folder refused); the descriptor, or -1 with `reason` set.
inline int create_fresh(const std::string& path, std::string& reason) {
  struct stat status {};
  if (::lstat(path.c_str(), &status) == 0) {
    if (S_ISDIR(status.st_mode)) {
      reason = "a folder of that name is in the way";
      return -1;
    }
    if (::unlink(path.c_str()) != 0) {
      reason = std::strerror(errno);
      return -1;
    }
  }
  const int descriptor = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (descriptor < 0) reason = std::strerror(errno);
  return descriptor;
}

/// Writes all of `text` to `descriptor`; false with `reason` set on a short or failed write.
inline bool write_all(int descriptor, const std::string& text, std::string& reason) {
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t count = ::write(descriptor, text.data() + done, text.size() - done);
    if (count < 0 && errno == EINTR) continue;
    if (count <= 0) {
      reason = count < 0 ? std::strerror(errno) : "nothing written";
      return false;
    }
    done += static_cast<std::size_t>(count);
  }
  return true;
}

/// Creates `path` afresh (create_fresh) holding `text`; false with `reason` set unless all of it was written and closed.
inline bool write_fresh(const std::string& path, const std::string& text, std::string& reason) {
  const int descriptor = create_fresh(path, reason);
  if (descriptor < 0) return false;
  const bool written = write_all(descriptor, text, reason);
  if (::close(descriptor) != 0 && written) {
    reason = std::strerror(errno);
    return false;
  }
  return written;
}

/// True if `start` (a file's first bytes) and `end` (its last) are those of a complete PNG: the signature,
/// and the IEND chunk (length 0, type, CRC) closing it.
inline bool png_complete(const std::string& start, const std::string& end) {
  static const std::string signature("\x89PNG\r\n\x1a\n", 8), last("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return start.size() >= 8 && start.compare(0, 8, signature) == 0 && end.size() >= 12 &&
         end.compare(end.size() - 12, 12, last) == 0;
}

/// True if the file `path` (not a symbolic link) is a complete PNG (png_complete on its first and last bytes).
inline bool png_file_complete(const std::string& path) {
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (descriptor < 0) return false;
  struct stat status {};
  std::string start(8, '\0'), end(12, '\0');
  const bool read = ::fstat(descriptor, &status) == 0 && S_ISREG(status.st_mode) && status.st_size >= 20 &&
                    ::pread(descriptor, &start[0], 8, 0) == 8 && ::pread(descriptor, &end[0], 12, status.st_size - 12) == 12;
  ::close(descriptor);
  return read && png_complete(start, end);
}

/// Runs `gnuplot [script]` without a shell, in `folder` ("" for here), its standard input from `input` (-1:
/// /dev/null) and its standard output and error into `log`. Returns gnuplot's exit status (127: it could not
/// be started; 128 + N: killed by signal N).
inline int run_gnuplot(const std::string& folder, const std::string& script, int input, int log) {
  const pid_t child = ::fork();
  if (child < 0) return 127;
  if (child == 0) {  // only system calls here, then exec
    if (!folder.empty() && ::chdir(folder.c_str()) != 0) ::_exit(127);
    const int null = input >= 0 ? input : ::open("/dev/null", O_RDONLY);
    if (null < 0 || ::dup2(null, 0) < 0 || ::dup2(log, 1) < 0 || ::dup2(log, 2) < 0) ::_exit(127);
    if (script.empty()) ::execlp("gnuplot", "gnuplot", static_cast<char*>(nullptr));
    else ::execlp("gnuplot", "gnuplot", script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST_CASE("gnuplot: strings quoted, control characters found, PNGs complete only to their end chunk") {
  CHECK(gnuplot_quoted("A.x' . system('touch F') . '") == "'A.x'' . system(''touch F'') . '''");
  CHECK(gnuplot_quoted("plain") == "'plain'");
  CHECK(has_control_character("a\nb"));
  CHECK(has_control_character(std::string("a\0b", 3)));
  CHECK(has_control_character("tab\there"));
  CHECK(!has_control_character("sigma_xx (Pa) \xc3\xa9"));  // UTF-8 is no control character
  CHECK(gnuplot_output_path("|touch F.png") == "./|touch F.png");
  CHECK(gnuplot_output_path("/tmp/a.png") == "/tmp/a.png");
  const std::string signature("\x89PNG\r\n\x1a\n", 8), iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  const std::string whole = signature + std::string("\0\0\0\rIHDR...", 11) + iend;
  CHECK(png_complete(whole.substr(0, 8), whole.substr(whole.size() - 12)));
  const std::string cut = whole.substr(0, whole.size() - 1);  // the last byte of the CRC missing
  CHECK(!png_complete(cut.substr(0, 8), cut.substr(cut.size() - 12)));
  CHECK(!png_complete("GIF89a..", whole.substr(whole.size() - 12)));
  CHECK(!png_complete("", ""));
  namespace fs = std::filesystem;
  const std::string path = (fs::temp_directory_path() / "mpm_gnuplot_test.png").string(), target = path + ".target";
  std::string reason;
  REQUIRE(write_fresh(target, "precious", reason));
  fs::remove(path);
  fs::create_symlink(target, path);
  REQUIRE(write_fresh(path, whole, reason));  // the link removed, a file made in its place
  CHECK(!fs::is_symlink(path));
  CHECK(png_file_complete(path));
  CHECK(fs::file_size(target) == 8);  // the link's target untouched
  REQUIRE(write_fresh(path, cut, reason));
  CHECK(!png_file_complete(path));
  fs::remove(path);
  fs::create_directory(path);
  CHECK(!write_fresh(path, whole, reason));
  CHECK(reason == "a folder of that name is in the way");
  CHECK(!png_file_complete(path));
  fs::remove(path);
  fs::remove(target);
  const int sink = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  CHECK(run_gnuplot("/nonexistent/folder", "plot.gp", -1, sink) == 127);  // no such folder: gnuplot never started
  ::close(sink);
}

}  // namespace mpm::cli
