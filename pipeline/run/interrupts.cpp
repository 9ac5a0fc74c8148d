#include "pipeline/run/interrupts.hpp"

#include <atomic>
#include <csignal>
#include <signal.h>

namespace eyestream::pipeline {

namespace {

std::atomic<int> g_received{0};
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction g_previous[3], g_previous_pipe;

void on_signal(int signal) {
  g_received.store(signal);
  // The next one takes the default action: a user pressing Ctrl-C twice
  // means now.
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(signal, &dfl, nullptr);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_received.store(0);
  struct sigaction act {};
  act.sa_handler = on_signal;
  sigemptyset(&act.sa_mask);
  act.sa_flags = SA_RESTART;  // reads and writes in progress carry on
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &act, &g_previous[i]);
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGPIPE, &ignore, &g_previous_pipe);
}

InterruptGuard::~InterruptGuard() {
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
  sigaction(SIGPIPE, &g_previous_pipe, nullptr);
}

int InterruptGuard::received() { return g_received.load(); }

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

}  // namespace eyestream::pipeline
