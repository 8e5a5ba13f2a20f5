#include "app/stop_signal.h"

#include <csignal>

namespace slamsph {

namespace {
volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_stop(int sig) {
  g_stop = sig;
}
}  // namespace

void install_stop_handlers() {
  std::signal(SIGINT, on_stop);
  std::signal(SIGTERM, on_stop);
}

int stop_signal() {
  return g_stop;
}

}  // namespace slamsph
