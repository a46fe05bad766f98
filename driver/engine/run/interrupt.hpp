#pragma once
// Interrupting a run with SIGINT (Ctrl-C), SIGTERM or SIGHUP (the terminal or SSH session that
// started it went away: the run stops as for SIGTERM rather than dying with rows unsaved). The
// handler only stores the signal number in
// an atomic flag; the time loop (run_fixed_steps, which every run goes through) reads it after
// every step, stops there, closes the outputs with the status "interrupted at t = … s (SIGINT)"
// and returns normally, so the summary is printed and `fowtsim run` exits with 128 + signal (130
// for SIGINT, 143 for SIGTERM, 129 for SIGHUP). A second signal of the same kind kills the process at once
// (SA_RESETHAND).
// Header-only: the flag is one inline variable shared by every translation unit.
#include <atomic>
#include <csignal>
#include <string>

#include <fmt/format.h>

namespace fowtsim::driver {

namespace detail {
inline std::atomic<int> pending_interrupt{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free flag");
extern "C" inline void record_interrupt(int signal_number) {
  pending_interrupt.store(signal_number, std::memory_order_relaxed);
}
}  // namespace detail

// The signal that asked the run to stop, or 0.
inline int interrupt_signal() { return detail::pending_interrupt.load(std::memory_order_relaxed); }
// Asks the running loop to stop as if `signal_number` had arrived (tests, embedding code).
inline void request_interrupt(int signal_number) { detail::record_interrupt(signal_number); }
inline void clear_interrupt() { detail::pending_interrupt.store(0, std::memory_order_relaxed); }

inline std::string signal_name(int signal_number) {
  if (signal_number == SIGINT) return "SIGINT";
  if (signal_number == SIGTERM) return "SIGTERM";
  if (signal_number == SIGHUP) return "SIGHUP";
  return fmt::format("signal {}", signal_number);
}

// The output status of a run stopped by `signal_number` after reaching `t_s`.
inline std::string interrupted_status(double t_s, int signal_number) {
  return fmt::format("interrupted at t = {:.6g} s ({})", t_s, signal_name(signal_number));
}

// Exit code of a run stopped by a signal, as a shell reports a process killed by it.
inline int interrupted_exit_code(int signal_number) { return 128 + signal_number; }

// Installs the SIGINT, SIGTERM and SIGHUP handlers for its lifetime (clearing the flag first) and puts the
// previous handlers back when destroyed.
class InterruptHandlers {
 public:
  InterruptHandlers() {
    clear_interrupt();
    struct sigaction action {};
    action.sa_handler = &detail::record_interrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // a second Ctrl-C stops a run that does not reach a step end
    sigaction(SIGINT, &action, &previous_int_);
    sigaction(SIGTERM, &action, &previous_term_);
    sigaction(SIGHUP, &action, &previous_hup_);
    // With the terminal or the reading end of a pipe gone, printing progress must not kill the
    // run before it closes its files: a failed write to stdout is ignored instead.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGPIPE, &ignore, &previous_pipe_);
  }
  ~InterruptHandlers() {
    sigaction(SIGINT, &previous_int_, nullptr);
    sigaction(SIGTERM, &previous_term_, nullptr);
    sigaction(SIGHUP, &previous_hup_, nullptr);
    sigaction(SIGPIPE, &previous_pipe_, nullptr);
  }
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
  struct sigaction previous_hup_ {};
  struct sigaction previous_pipe_ {};
};

}  // namespace fowtsim::driver
