/// \file
/// The signals that end a run or a study early. Every signal whose default action ends a process and that a process
/// can catch (SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU, SIGVTALRM, SIGPROF) asks the run to
/// stop after its current step, so that run.json can say "interrupted"; a second one changes nothing (only SIGKILL
/// ends a run at once). SIGHUP ignored when mpm starts stays ignored (`nohup mpm run ...` asks for that); the others
/// are caught even when a shell ignores them (it ignores SIGINT and SIGQUIT in a script's background jobs). SIGPIPE and SIGXFSZ are ignored:
/// a write they would interrupt fails instead, and the writer reports it (`cannot write`).
///
/// A study forwards the signal to the children it runs (forward_stop_signals_to), so that each of its runs ends as
/// `mpm run` does; each child also dies with the study (PR_SET_PDEATHSIG, mpm/study/process.hpp).
#pragma once
#include <doctest/doctest.h>
#include <pthread.h>
#include <signal.h>
#include <sys/types.h>

#include <atomic>
#include <csignal>
#include <string>

namespace mpm::io {

/// The signal that asked the run to stop; 0 while none did.
inline volatile std::sig_atomic_t stop_signal = 0;

/// The signals catch_stop_signals() catches.
inline constexpr int stop_signals[] = {SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU, SIGVTALRM, SIGPROF};

/// The children a stop signal is forwarded to: process ids, 0 for a free slot (one per child running at once).
inline std::atomic<pid_t> forwarded_children[1024];

/// Records the first stop signal and forwards every one to the registered children. A later stop signal changes
/// nothing: the run still ends after its current step, so that run.json can say so (SIGKILL ends a process at once,
/// and leaves its run.json saying "running").
inline void on_stop_signal(int signal) {
  if (stop_signal == 0) stop_signal = signal;
  for (auto& child : forwarded_children)
    if (const pid_t pid = child.load(); pid > 0) ::kill(pid, signal);
}

/// Catches the stop signals and ignores SIGPIPE and SIGXFSZ.
inline void catch_stop_signals() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  action.sa_flags = SA_RESTART;
  sigemptyset(&action.sa_mask);
  for (int signal : stop_signals) {
    struct sigaction now {};
    const bool nohup = signal == SIGHUP && ::sigaction(signal, nullptr, &now) == 0 && now.sa_handler == SIG_IGN;
    if (!nohup) ::sigaction(signal, &action, nullptr);
  }
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
}

/// The stop signals as a set, to block them around a fork (StopSignalsBlocked).
inline sigset_t stop_signal_set() {
  sigset_t set;
  sigemptyset(&set);
  for (int signal : stop_signals) sigaddset(&set, signal);
  return set;
}

/// While it lives, the calling thread receives no stop signal (they wait, pending); a child forked meanwhile starts
/// with them blocked too, and calls in_child_after_fork().
class StopSignalsBlocked {
 public:
  StopSignalsBlocked() {
    const sigset_t set = stop_signal_set();
    ::pthread_sigmask(SIG_BLOCK, &set, &previous_);
  }
  StopSignalsBlocked(const StopSignalsBlocked&) = delete;
  StopSignalsBlocked& operator=(const StopSignalsBlocked&) = delete;
  ~StopSignalsBlocked() { ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }

  /// In a child just forked: the stop signals back to their default action, then unblocked, so that one sent before
  /// the child's program has started ends the child, instead of the parent's handler recording it in memory that
  /// exec discards. Async-signal-safe.
  void in_child_after_fork() const {
    for (int signal : stop_signals) std::signal(signal, SIG_DFL);
    ::sigprocmask(SIG_SETMASK, &previous_, nullptr);  // the child has one thread
  }

 private:
  sigset_t previous_{};
};

/// Registers child `pid` for the forwarding; returns its slot (-1 when all are taken: the child is not told).
inline int forward_stop_signals_to(pid_t pid) {
  for (int slot = 0; slot < static_cast<int>(std::size(forwarded_children)); ++slot) {
    pid_t free = 0;
    if (forwarded_children[slot].compare_exchange_strong(free, pid)) return slot;
  }
  return -1;
}

/// Ends the forwarding to the child in `slot` (forward_stop_signals_to's), once it has been waited for.
inline void stop_forwarding(int slot) {
  if (slot >= 0) forwarded_children[slot].store(0);
}

/// "SIGTERM": the name of a stop signal (else "signal N").
inline std::string signal_name(int signal) {
  const char* names[] = {"SIGHUP", "SIGINT", "SIGQUIT", "SIGTERM", "SIGALRM", "SIGUSR1", "SIGUSR2", "SIGXCPU", "SIGVTALRM", "SIGPROF"};
  for (std::size_t k = 0; k < std::size(stop_signals); ++k)
    if (stop_signals[k] == signal) return names[k];
  return "signal " + std::to_string(signal);
}

/// Raised between two steps (or two removals of a clear) after a stop signal.
struct Interrupted {
  int signal;
};

/// \throws Interrupted if a stop signal came.
inline void stop_if_signalled() {
  if (stop_signal != 0) throw Interrupted{stop_signal};
}

TEST_CASE("stop signals: SIGHUP caught and named, a second signal changing nothing, SIGHUP under nohup left ignored, SIGINT caught") {
  struct sigaction saved[std::size(stop_signals)];
  for (std::size_t k = 0; k < std::size(stop_signals); ++k) ::sigaction(stop_signals[k], nullptr, &saved[k]);
  std::signal(SIGHUP, SIG_IGN);  // under nohup: SIGHUP stays ignored; SIGINT, ignored by a shell, is caught
  std::signal(SIGINT, SIG_IGN);
  catch_stop_signals();
  struct sigaction now {};
  ::sigaction(SIGHUP, nullptr, &now);
  CHECK((now.sa_handler == SIG_IGN ? 1 : 0) == 1);
  ::sigaction(SIGINT, nullptr, &now);
  CHECK((now.sa_handler == on_stop_signal ? 1 : 0) == 1);
  std::signal(SIGHUP, SIG_DFL);
  catch_stop_signals();
  ::raise(SIGHUP);
  CHECK(stop_signal == SIGHUP);
  CHECK_THROWS_AS(stop_if_signalled(), Interrupted);
  ::raise(SIGINT);  // a second stop signal: the first is the one that stops the run
  CHECK(stop_signal == SIGHUP);
  ::sigaction(SIGTERM, nullptr, &now);
  CHECK((now.sa_handler == on_stop_signal ? 1 : 0) == 1);
  CHECK(signal_name(SIGHUP) == "SIGHUP");
  CHECK(signal_name(SIGPROF) == "SIGPROF");
  CHECK(signal_name(SIGKILL) == "signal 9");
  const int slot = forward_stop_signals_to(12345);
  CHECK(forwarded_children[slot].load() == 12345);
  stop_forwarding(slot);
  CHECK(forwarded_children[slot].load() == 0);
  for (std::size_t k = 0; k < std::size(stop_signals); ++k) ::sigaction(stop_signals[k], &saved[k], nullptr);
  std::signal(SIGPIPE, SIG_DFL);
  std::signal(SIGXFSZ, SIG_DFL);
  stop_signal = 0;
}

}  // namespace mpm::io
