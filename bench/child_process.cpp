#include "child_process.hpp"

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace orthoray::bench {

ChildOutput run_in_child(const std::function<std::string()>& work) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        close(fds[0]);
        try {
            const std::string out = work();
            const char* bytes = out.data();
            std::size_t left = out.size();
            while (left > 0) {
                const ssize_t w = write(fds[1], bytes, left);
                if (w <= 0) break;
                bytes += w;
                left -= static_cast<std::size_t>(w);
            }
        } catch (...) {
        }
        _exit(0);
    }
    close(fds[1]);
    ChildOutput result;
    char buffer[4096];
    for (ssize_t r; (r = read(fds[0], buffer, sizeof buffer)) > 0;)
        result.bytes.append(buffer, static_cast<std::size_t>(r));
    close(fds[0]);
    struct rusage ru {};
    wait4(pid, &result.status, 0, &ru);
    result.max_rss_kb = ru.ru_maxrss;
    return result;
}

} // namespace orthoray::bench
