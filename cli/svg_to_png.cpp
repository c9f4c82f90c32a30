#include "svg_to_png.hpp"

#include "commands.hpp"
#include "output_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace orthoray::cli {
namespace {

// The two pipes to the child and the child itself: on any way out, the
// ends we still hold are closed and the child is reaped, so no zombie or
// stray descriptor is left behind by an exception.
class Converter {
public:
    Converter() {
        if (pipe2(to_child_, O_CLOEXEC) != 0 || pipe2(from_child_, O_CLOEXEC) != 0) {
            const int error = errno;
            close_all();
            throw WriteError("cannot create a pipe to rsvg-convert: " +
                             std::string(std::strerror(error)));
        }
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        // dup2 clears close-on-exec on the copies, so the child keeps only
        // these two ends (and our standard error, for its own messages).
        posix_spawn_file_actions_adddup2(&actions, to_child_[0], STDIN_FILENO);
        posix_spawn_file_actions_adddup2(&actions, from_child_[1], STDOUT_FILENO);
        std::string program = "rsvg-convert", format = "--format", png = "png";
        char* argv[] = {program.data(), format.data(), png.data(), nullptr};
        const int failed = posix_spawnp(&pid_, "rsvg-convert", &actions, nullptr, argv, environ);
        posix_spawn_file_actions_destroy(&actions);
        if (failed != 0) {
            pid_ = -1;
            close_all();
            throw UsageError("PNG output needs the program rsvg-convert (Debian package "
                             "librsvg2-bin); install it, or write an .svg file instead");
        }
        close_end(to_child_[0]);
        close_end(from_child_[1]);
        // Our end must not block: a write of more than the pipe holds would
        // wait for the child, which may be waiting for us to read.
        fcntl(to_child_[1], F_SETFL, O_NONBLOCK);
    }
    ~Converter() {
        close_all();
        if (pid_ > 0) waitpid(pid_, nullptr, 0);
    }
    Converter(const Converter&) = delete;
    Converter& operator=(const Converter&) = delete;

    // Feeds `svg` and copies the output to `png` at the same time, with
    // poll(), so that neither side can block the other on a full pipe.
    void run(const std::string& svg, std::ostream& png) {
        std::size_t sent = 0;
        if (svg.empty()) close_end(to_child_[1]);
        char buffer[1 << 16];
        while (from_child_[0] >= 0) {
            pollfd fds[2] = {{from_child_[0], POLLIN, 0}, {to_child_[1], POLLOUT, 0}};
            const nfds_t count = to_child_[1] >= 0 ? 2 : 1;
            if (poll(fds, count, -1) < 0) {
                if (errno == EINTR) continue;
                throw WriteError("cannot wait for rsvg-convert: " +
                                 std::string(std::strerror(errno)));
            }
            if (count == 2 && fds[1].revents != 0) {
                const ssize_t n = write(to_child_[1], svg.data() + sent, svg.size() - sent);
                if (n < 0 && errno != EINTR && errno != EAGAIN) {
                    close_end(to_child_[1]); // it stopped reading: its status says why
                } else if (n > 0) {
                    sent += static_cast<std::size_t>(n);
                    if (sent == svg.size()) close_end(to_child_[1]);
                }
            }
            if (fds[0].revents != 0) {
                const ssize_t n = read(from_child_[0], buffer, sizeof buffer);
                if (n < 0 && errno == EINTR) continue;
                if (n <= 0)
                    close_end(from_child_[0]);
                else
                    png.write(buffer, n);
            }
        }
        close_end(to_child_[1]);
        int status = 0;
        const pid_t child = pid_;
        pid_ = -1;
        if (waitpid(child, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
            sent != svg.size())
            throw UsageError("rsvg-convert could not convert the picture to PNG");
    }

private:
    static void close_end(int& fd) {
        if (fd >= 0) close(fd);
        fd = -1;
    }
    void close_all() {
        for (int& fd : to_child_) close_end(fd);
        for (int& fd : from_child_) close_end(fd);
    }
    int to_child_[2] = {-1, -1}, from_child_[2] = {-1, -1};
    pid_t pid_ = -1;
};

} // namespace

void svg_to_png(const std::string& svg, std::ostream& png) {
    Converter converter;
    converter.run(svg, png);
}

} // namespace orthoray::cli
