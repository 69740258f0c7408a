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
  ignore_file_size_signal();
}

void ignore_file_size_signal() {
  // Past a file size limit (ulimit -f) a write fails with EFBIG instead of killing the process: the
  // run then stops as for a full disk, with its files whole.
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace lmgc::solver
