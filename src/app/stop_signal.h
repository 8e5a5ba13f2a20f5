// Clean stops on SIGINT / SIGTERM: the handler only records the signal (the one piece of
// process-wide state, as a signal handler can reach nothing else); the run loop polls it
// between steps, finishes the step, writes the final frame, flushes every file, sets
// summary.json's status to "interrupted", and the program exits 128 + signal (130, 143).
#pragma once

namespace slamsph {

// Installs the handlers (once, from main).
void install_stop_handlers();
// The signal that asked the run to stop, 0 if none.
int stop_signal();

}  // namespace slamsph
