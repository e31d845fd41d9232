// Blocking SIGINT/SIGTERM and waiting for them on a thread of our own (see stop_signals.hpp).
#include "stop_signals.hpp"

#include <pthread.h>
#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <system_error>
#include <utility>

namespace roughgas::cli {

StopSignals::StopSignals(std::string command, std::string on_first, bool repeat_ends_now)
    : command_(std::move(command)), on_first_(std::move(on_first)), repeat_ends_now_(repeat_ends_now) {
    sigemptyset(&set_);
    sigaddset(&set_, SIGINT);
    sigaddset(&set_, SIGTERM);
    if (const int e = pthread_sigmask(SIG_BLOCK, &set_, &old_); e != 0)
        throw std::system_error(e, std::generic_category(), "pthread_sigmask");
    waiter_ = std::thread([this] { wait(); }); // inherits the blocked mask: sigwait needs it
}

StopSignals::~StopSignals() {
    // Wake the waiter with a signal directed at its thread; it sees closing_ and returns. A signal
    // sent to the process meanwhile stays pending and is delivered once the mask is restored.
    closing_.store(true, std::memory_order_release);
    pthread_kill(waiter_.native_handle(), SIGTERM);
    waiter_.join();
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
}

std::string StopSignals::name() const { return name_of(signal()); }

std::string StopSignals::name_of(int signal) {
    switch (signal) {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
    default:
        return "no signal";
    }
}

void StopSignals::wait() {
    for (;;) {
        int sig = 0;
        if (sigwait(&set_, &sig) != 0)
            continue;
        if (closing_.load(std::memory_order_acquire))
            return;
        int none = 0;
        if (signal_.compare_exchange_strong(none, sig, std::memory_order_acq_rel)) {
            std::cerr << "\nroughgas " << command_ << ": " << name() << ": " << on_first_
                      << (repeat_ends_now_ ? " (send it again to end at once)\n" : "\n");
            continue;
        }
        if (!repeat_ends_now_)
            continue;
        // The second signal: its default action, which ends the process as killed by it. Raised on
        // this thread, the only one where it is unblocked now.
        struct sigaction dfl {};
        dfl.sa_handler = SIG_DFL;
        sigaction(sig, &dfl, nullptr);
        sigset_t one;
        sigemptyset(&one);
        sigaddset(&one, sig);
        pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
        raise(sig);
        std::_Exit(128 + sig); // not reached
    }
}

} // namespace roughgas::cli
