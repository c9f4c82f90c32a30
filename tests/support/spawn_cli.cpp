#include "support/spawn_cli.hpp"

#include "support/test_files.hpp"

#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <sys/wait.h>
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
