#include "support/spawn_cli.hpp"

#include "support/test_files.hpp"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace orthoray::test {

pid_t spawn_cli(const std::vector<std::string>& args, const std::string& out,
                const std::string& err) {
    std::vector<char*> argv;
    std::string program = ORTHORAY_CLI;
    std::vector<std::string> words = args;
    argv.push_back(program.data());
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    const pid_t child = fork();
    if (child == 0) {
        const int out_fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(out_fd, STDOUT_FILENO);
        dup2(err_fd, STDERR_FILENO);
        execv(program.c_str(), argv.data());
        _exit(127);
    }
    return child;
}

int wait_for(pid_t child) {
    int status = 0;
    if (waitpid(child, &status, 0) != child) return -1000;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

std::optional<int> wait_at_most(pid_t child, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        int status = 0;
        if (waitpid(child, &status, WNOHANG) == child)
            return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    kill(child, SIGKILL);
    wait_for(child);
    return std::nullopt;
}

namespace {

// Polls `ready` every 2 ms for at most a minute, while `child` runs.
template <class Ready>
bool poll_child(pid_t child, Ready ready) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (std::chrono::steady_clock::now() < give_up) {
        if (ready()) return true;
        siginfo_t info{};
        // An ended child is left to be reaped by the test (WNOWAIT).
        if (::waitid(P_PID, static_cast<id_t>(child), &info, WEXITED | WNOHANG | WNOWAIT) != 0 ||
            info.si_pid == child)
            return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
}

} // namespace

bool wait_until_catching(pid_t child, int signal) {
    const std::string status = "/proc/" + std::to_string(child) + "/status";
    const std::filesystem::path exe = "/proc/" + std::to_string(child) + "/exe";
    const std::filesystem::path program = std::filesystem::canonical(ORTHORAY_CLI);
    return poll_child(child, [&] {
        // Until it has run execv the child is a copy of the test process,
        // whose own handlers (Catch2's) would show in SigCgt.
        std::error_code error;
        if (std::filesystem::read_symlink(exe, error) != program) return false;
        std::ifstream in(status);
        std::string line;
        while (std::getline(in, line))
            if (line.rfind("SigCgt:", 0) == 0)
                return (std::stoull(line.substr(7), nullptr, 16) >> (signal - 1) & 1) != 0;
        return false;
    });
}

bool wait_until_open(pid_t child, const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path target = fs::canonical(path);
    const fs::path fds = "/proc/" + std::to_string(child) + "/fd";
    return poll_child(child, [&] {
        std::error_code error;
        for (const fs::directory_entry& fd : fs::directory_iterator(fds, error)) {
            std::error_code link_error;
            if (fs::read_symlink(fd.path(), link_error) == target) return true;
        }
        return false;
    });
}

bool wait_until_queued(pid_t child, int reader, int bytes) {
    return poll_child(child, [&] {
        int queued = 0;
        return ::ioctl(reader, FIONREAD, &queued) == 0 && queued >= bytes;
    });
}

ShellResult run_shell(const std::string& script) {
    const TempDir dir;
    const std::string err = dir.path("err");
    const std::string command = "ORTHORAY=" + quote(ORTHORAY_CLI) + " bash -c " + quote(script) +
                                " 2>" + quote(err) + " </dev/null >/dev/null";
    const int raw = std::system(command.c_str());
    ShellResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.err = slurp(err);
    return r;
}

} // namespace orthoray::test
