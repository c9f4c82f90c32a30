#include "python_monitor.hpp"

namespace orthoray::python {

PythonMonitor::PythonMonitor(std::optional<double> timeout_seconds) {
    // Finite and at most about 30 years, so the deadline cannot overflow.
    if (timeout_seconds && !(*timeout_seconds >= 0 && *timeout_seconds <= 1e9))
        throw pybind11::value_error("timeout: expected a number of seconds from 0 to 1e9");
    if (timeout_seconds)
        deadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(*timeout_seconds));
}

std::optional<Limit> PythonMonitor::poll(std::uint64_t) {
    const Clock::time_point now = Clock::now();
    if (deadline_ && now >= *deadline_) return Limit::time;
    if (now < next_check_) return std::nullopt;
    next_check_ = now + std::chrono::milliseconds(10);
    pybind11::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {
        interrupt_.emplace(); // takes the handler's exception
        return Limit::interrupt;
    }
    return std::nullopt;
}

} // namespace orthoray::python
