// Long calls run without the GIL, so other Python threads go on; this
// monitor takes it back every 10 ms only to ask Python whether a signal
// arrived (Ctrl-C: PyErr_CheckSignals), and ends the run as a limit then,
// or at the timeout. The caller turns an interrupt into KeyboardInterrupt
// once the engine has stopped cleanly, so the partial answer is not lost.
#pragma once

#include "orthoray/solve.hpp"

#include <pybind11/pybind11.h>

#include <chrono>
#include <optional>

namespace orthoray::python {

class PythonMonitor : public RunMonitor {
public:
    explicit PythonMonitor(std::optional<double> timeout_seconds);
    std::optional<Limit> poll(std::uint64_t reflections) override;
    // Whether the run stopped because Python had a signal pending (its error
    // is then set again, for the caller to raise).
    bool interrupted() const { return interrupted_; }
    // With the GIL held, after the run: raises the pending KeyboardInterrupt
    // if the run was stopped by one.
    void raise_if_interrupted() const {
        if (interrupted_) throw pybind11::error_already_set();
    }

private:
    using Clock = std::chrono::steady_clock;
    std::optional<Clock::time_point> deadline_;
    Clock::time_point next_check_ = Clock::now();
    bool interrupted_ = false;
};

} // namespace orthoray::python
