#include "solver/driver/run_loop.hpp"

#include <csignal>

namespace lmgc::solver {

std::atomic<int> g_stop_signal{0};

namespace {
extern "C" void on_stop_signal(int signal) {
  g_stop_signal.store(signal);
}
}  // namespace

void install_interrupt_handler() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, on_stop_signal);
}

}  // namespace lmgc::solver
