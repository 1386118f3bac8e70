/// \file
/// The study's children: each case is run by the same `mpm` program (/proc/self/exe) as a child process,
/// started with fork and execv (never a shell: no argument is ever parsed again), its standard output and
/// error caught in unnamed temporary files, its wall time measured around it and its CPU time (user + system)
/// taken from wait4's resource usage of that child alone.
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "mpm/io/stop_signals.hpp"

namespace mpm::study {

/// How a child ended and what it said.
struct ChildRun {
  int exit_code = 127;  ///< its exit status; 128 + N when signal N killed it; 127 when it could not be started
  double wall_s = 0.0, cpu_s = 0.0;
  std::string out, err;  ///< its standard output and error
};

/// The whole content of the open file `file`, read from its start.
inline std::string read_back(std::FILE* file) {
  std::string text;
  if (!file || std::fflush(file) != 0 || std::fseek(file, 0, SEEK_SET) != 0) return text;
  char block[1 << 14];
  for (std::size_t count; (count = std::fread(block, 1, sizeof block, file)) > 0;) text.append(block, count);
  return text;
}

/// The first line of `text` that starts with `error:` or `failure:`, else its first line: the reason a child gives.
inline std::string reason_line(const std::string& text) {
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (line.rfind("error:", 0) == 0 || line.rfind("failure:", 0) == 0) return line;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return text.substr(0, text.find('\n'));
}

/// Runs `program` with `arguments` (argv[0] first) as a child, without a shell, waits for it and returns how it
/// ended. Its standard input is /dev/null; its output and error are read back from temporary files. The child runs
/// in a process group of its own (a terminal's Ctrl-C reaches it once, forwarded: stop_signals.hpp) and dies with
/// its parent (PR_SET_PDEATHSIG, SIGTERM: it ends as after a stop signal). After a stop signal no child is started:
/// the run ends as if that signal had killed it.
inline ChildRun run_child(const std::string& program, const std::vector<std::string>& arguments) {
  ChildRun run;
  if (io::stop_signal != 0) {
    run.exit_code = 128 + io::stop_signal;
    run.err = "error: not started: the study was stopped by " + io::signal_name(io::stop_signal);
    return run;
  }
  std::vector<char*> argv;  // made before fork: the child only makes system calls
  for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  std::FILE* out = std::tmpfile();
  std::FILE* err = std::tmpfile();
  const int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  const auto start = std::chrono::steady_clock::now();
  const pid_t parent = ::getpid();
  std::optional<io::StopSignalsBlocked> blocked(std::in_place);  // until the child is registered for the forwarding
  const pid_t child = out && err && null >= 0 ? ::fork() : -1;
  if (child == 0) {
    ::setpgid(0, 0);
    if (::prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || ::getppid() != parent) ::_exit(127);  // the parent already died
    blocked->in_child_after_fork();  // a stop signal already sent ends the child here
    if (::dup2(null, 0) < 0 || ::dup2(fileno(out), 1) < 0 || ::dup2(fileno(err), 2) < 0) ::_exit(127);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  const int slot = child > 0 ? io::forward_stop_signals_to(child) : -1;
  blocked.reset();  // a stop signal that came meanwhile reaches the handler now, which forwards it to the child
  if (child > 0) {
    if (io::stop_signal != 0) ::kill(child, io::stop_signal);  // one that another thread took before the registration
    int status = 0;
    struct rusage usage {};
    while (::wait4(child, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    io::stop_forwarding(slot);
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.cpu_s = usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.out = read_back(out), run.err = read_back(err);
  } else {
    run.err = "error: cannot start " + program + ": " + (child < 0 ? "fork failed" : "no temporary file");
  }
  if (null >= 0) ::close(null);
  if (out) std::fclose(out);
  if (err) std::fclose(err);
  return run;
}

TEST_CASE("study children: exit status, output and error caught, time measured, no shell") {
  const ChildRun echo = run_child("/bin/echo", {"echo", "a;b", "$(c)"});
  CHECK(echo.exit_code == 0);
  CHECK(echo.out == "a;b $(c)\n");  // no shell: the arguments arrive as given
  CHECK(echo.wall_s >= 0.0);
  CHECK(echo.cpu_s >= 0.0);
  CHECK(run_child("/bin/false", {"false"}).exit_code == 1);
  const ChildRun missing = run_child("/nonexistent/mpm", {"mpm"});
  CHECK(missing.exit_code == 127);
  // the child in a process group of its own (field 5 of /proc/PID/stat)
  const ChildRun group = run_child("/bin/sh", {"sh", "-c", "cut -d' ' -f5 /proc/$$/stat"});
  CHECK(std::stol(group.out) != static_cast<long>(::getpgrp()));
  io::stop_signal = SIGTERM;  // after a stop signal: nothing started
  const ChildRun stopped = run_child("/bin/echo", {"echo", "x"});
  io::stop_signal = 0;
  CHECK(stopped.exit_code == 128 + SIGTERM);
  CHECK(stopped.out.empty());
  CHECK(reason_line("warning: a\nerror: b: c\nmore\n") == "error: b: c");
  CHECK(reason_line("warning: a\nother\n") == "warning: a");
  CHECK(reason_line("") == "");
}

}  // namespace mpm::study
