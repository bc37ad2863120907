#include "app/render_loop/signal_stop.h"

namespace wf {
namespace {

// Lock-free atomics are the signal-safe way to say something from a handler.
std::atomic<bool> stopRequested{false};
std::atomic<int> stopSignal{0};

void onSignal(int signal) {
    stopSignal.store(signal);
    stopRequested.store(true);
}

} // namespace

SignalStop::SignalStop() {
    stopRequested.store(false);
    stopSignal.store(0);
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previousInt_);
    sigaction(SIGTERM, &action, &previousTerm_);
}

SignalStop::~SignalStop() {
    sigaction(SIGINT, &previousInt_, nullptr);
    sigaction(SIGTERM, &previousTerm_, nullptr);
}

const std::atomic<bool>& SignalStop::requested() const { return stopRequested; }

int SignalStop::signal() const { return stopSignal.load(); }

} // namespace wf
