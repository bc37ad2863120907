// SIGINT and SIGTERM as a request to stop: while a SignalStop lives, either signal sets a flag
// the render loop reads between sample passes (so a checkpoint can be written) instead of
// ending the process; the previous handlers come back when it goes.
#pragma once
#include <atomic>
#include <csignal>

namespace wf {

class SignalStop {
public:
    SignalStop();
    ~SignalStop();
    SignalStop(const SignalStop&) = delete;
    SignalStop& operator=(const SignalStop&) = delete;

    const std::atomic<bool>& requested() const;
    int signal() const; // the signal that asked, 0 if none

private:
    struct sigaction previousInt_{};
    struct sigaction previousTerm_{};
};

} // namespace wf
