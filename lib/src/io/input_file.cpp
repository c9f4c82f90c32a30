// The one way orthoray opens a file to read: scenes are read whole, capped
// at input_cap_bytes; certificates are streamed, and their reader caps each
// line instead (a certificate's length grows with the reflections it lists,
// but memory must not). A directory, a missing file, a device that never
// ends and a signal while a FIFO waits for its writer each get their own
// answer instead of a hang, a wrong verdict or exhausted memory.
#include "orthoray/parse.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <istream>
#include <poll.h>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>

namespace orthoray {
namespace {

// The ReadStopCheck the readers on this thread ask (parse.hpp).
thread_local ReadStopCheck* innermost_check = nullptr;

[[noreturn]] void fail_to_read(const std::string& path, int error, const char* what) {
    // No SA_RESTART on orthoray's signal handlers: EINTR means one of them ran.
    if (error == EINTR) throw ReadInterrupted(path);
    throw InputError(path, 1, 1,
                     std::string("found ") + what + " (" + std::strerror(error) +
                         "), expected a readable file");
}

// Opens `path` for reading and refuses a directory.
int open_for_reading(const std::string& path) {
    // "-" is standard input, as for most Unix tools; a duplicate, so that
    // closing it after the read leaves the process's own stdin alone.
    if (path == "-") {
        const int fd = ::fcntl(STDIN_FILENO, F_DUPFD_CLOEXEC, 0);
        if (fd < 0) fail_to_read(path, errno, "a readable standard input");
        return fd;
    }
    // Non-blocking, so that opening a FIFO does not wait for its writer
    // here, where nothing could stop the wait: read_some waits instead.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) fail_to_read(path, errno, "no readable file");
    struct stat info {};
    if (fstat(fd, &info) == 0 && S_ISDIR(info.st_mode)) {
        ::close(fd);
        throw InputError(path, 1, 1, "found a directory, expected a readable file");
    }
    return fd;
}

// How often a read waiting for data asks the thread's ReadStopCheck.
constexpr int stop_check_ms = 10;

// read(2) into `buffer`; 0 at the end of the file. A FIFO waiting for its
// writer, or a slow pipe, is waited on with poll(2) in slices while a
// ReadStopCheck lives on this thread, so that a stop asked from another
// thread (batch's workers: the signal handler runs on the main thread) or
// a deadline ends the wait; with none, the wait is unbounded and a
// signal's handler interrupts it (EINTR). A FIFO opened without blocking
// reports nothing to poll(2) until a writer comes, so it is not mistaken
// for an empty file.
std::size_t read_some(int fd, const std::string& path, char* buffer, std::size_t size) {
    for (;;) {
        pollfd wait{fd, POLLIN, 0};
        const int ready = ::poll(&wait, 1, innermost_check ? stop_check_ms : -1);
        if (ready < 0) fail_to_read(path, errno, "a file that cannot be read");
        if (ready == 0) {
            ReadStopCheck::poll();
            continue;
        }
        const ssize_t n = ::read(fd, buffer, size);
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) continue;
        if (n < 0) fail_to_read(path, errno, "a file that cannot be read");
        return static_cast<std::size_t>(n);
    }
}

// A stream buffer over a file descriptor. Errors are thrown from underflow;
// the stream is set to rethrow them (badbit), so a read error is an error,
// not an early end of file that would look like a truncated certificate.
class FileBuffer final : public std::streambuf {
public:
    FileBuffer(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
    ~FileBuffer() override { ::close(fd_); }
    FileBuffer(const FileBuffer&) = delete;
    FileBuffer& operator=(const FileBuffer&) = delete;

protected:
    int_type underflow() override {
        const std::size_t n = read_some(fd_, path_, buffer_, sizeof buffer_);
        if (n == 0) return traits_type::eof();
        setg(buffer_, buffer_, buffer_ + n);
        return traits_type::to_int_type(buffer_[0]);
    }

private:
    int fd_;
    std::string path_;
    char buffer_[1 << 16];
};

class FileStream final : public std::istream {
public:
    FileStream(int fd, const std::string& path) : std::istream(nullptr), buffer_(fd, path) {
        rdbuf(&buffer_);
        exceptions(std::ios::badbit);
    }

private:
    FileBuffer buffer_;
};

} // namespace

ReadInterrupted::ReadInterrupted(const std::string& path)
    : std::runtime_error("interrupted while reading '" + path + "'") {}

ReadStopCheck::ReadStopCheck(std::string path, std::function<bool()> stop_requested)
    : path_(std::move(path)), stop_requested_(std::move(stop_requested)), outer_(innermost_check) {
    innermost_check = this;
}

ReadStopCheck::~ReadStopCheck() {
    innermost_check = outer_;
}

void ReadStopCheck::poll() {
    if (innermost_check && innermost_check->stop_requested_())
        throw ReadInterrupted(innermost_check->path_);
}

std::string read_file(const std::string& path) {
    const int fd = open_for_reading(path);
    struct Close {
        int fd;
        ~Close() { ::close(fd); }
    } close_fd{fd};
    std::string content;
    struct stat info {};
    if (fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0)
        content.reserve(static_cast<std::size_t>(
            std::min<off_t>(info.st_size, static_cast<off_t>(input_cap_bytes) + 1)));
    // The line and column where the cap is crossed, for the message.
    int line = 1;
    std::size_t line_start = 0;
    char buffer[1 << 16];
    while (const std::size_t n = read_some(fd, path, buffer, sizeof buffer)) {
        const std::size_t room = input_cap_bytes + 1 - content.size();
        content.append(buffer, std::min(n, room));
        if (content.size() <= input_cap_bytes) continue;
        for (std::size_t i = 0; i < input_cap_bytes; ++i)
            if (content[i] == '\n') ++line, line_start = i + 1;
        const std::size_t column = input_cap_bytes - line_start + 1;
        throw InputError(path, line, static_cast<int>(column),
                         "found more than " + std::to_string(input_cap_bytes >> 20) +
                             " MiB, expected a file of at most that size (docs/limits.md)");
    }
    return content;
}

std::unique_ptr<std::istream> open_file_stream(const std::string& path) {
    return std::make_unique<FileStream>(open_for_reading(path), path);
}

} // namespace orthoray
