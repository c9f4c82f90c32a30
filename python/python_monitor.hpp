// Long calls run without the GIL, so other Python threads go on; this
// monitor takes it back every 10 ms only to ask Python whether a signal
// arrived (PyErr_CheckSignals runs the handlers), and ends the run as a
// limit when a handler raised, or at the timeout. The handler's exception
// (KeyboardInterrupt for Ctrl-C, or whatever a handler of the caller's own
// raises: SystemExit, a timeout of theirs) is kept until the engine has
// stopped cleanly, and the caller raises it then, so the partial answer is
// not lost.
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
    // Whether a signal handler's exception stopped the run.
    bool interrupted() const { return interrupt_.has_value(); }
    // That exception (only when interrupted()).
    const pybind11::error_already_set& interrupt() const { return *interrupt_; }
    // With the GIL held, after the run: raises that exception, if any.
    void raise_if_interrupted() const {
        if (interrupt_) throw *interrupt_;
    }

private:
    using Clock = std::chrono::steady_clock;
    std::optional<Clock::time_point> deadline_;
    Clock::time_point next_check_ = Clock::now();
    // Fetched (and so cleared) when the handler raised: no Python error
    // stays set while the run goes on without the GIL.
    std::optional<pybind11::error_already_set> interrupt_;
};

} // namespace orthoray::python
