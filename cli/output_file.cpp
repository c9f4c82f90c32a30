#include "output_file.hpp"

#include "usage_error.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <poll.h>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace orthoray::cli {
namespace {

std::string reason(int error) {
    return std::strerror(error);
}

// The temporary files being written, for remove_unfinished_output(): plain
// arrays, since a signal handler may read them at any moment. A command
// writes at most two outputs at once (render's PNG: an SVG and the PNG), but
// batch's threads and Python's write certificates concurrently: a slot is
// claimed by a lock-free compare-and-swap (safe beside a signal handler, as
// a mutex is not), and the handler unlinks only a slot whose path is whole.
constexpr int max_unfinished = 4;
enum Slot : int { free_slot, claimed, ready };
char unfinished_path[max_unfinished][4096];
std::atomic<int> unfinished_used[max_unfinished];
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler reads the slots");

int remember_unfinished(const std::string& path) {
    if (path.size() >= sizeof unfinished_path[0]) return -1;
    for (int i = 0; i < max_unfinished; ++i) {
        int expected = free_slot;
        if (unfinished_used[i].compare_exchange_strong(expected, claimed)) {
            std::memcpy(unfinished_path[i], path.c_str(), path.size() + 1);
            unfinished_used[i].store(ready);
            return i;
        }
    }
    return -1; // no slot: a signal then leaves this temporary file behind
}

void forget_unfinished(int slot) {
    if (slot >= 0) unfinished_used[slot].store(free_slot);
}

bool same_file(const struct stat& a, const struct stat& b) {
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// The paths a chain of symbolic links passes through: `path`, then each
// link's target in turn, up to the first that is no link or cannot be read
// (at most 40 links, as the kernel follows).
std::vector<std::filesystem::path> link_chain(std::filesystem::path path) {
    std::vector<std::filesystem::path> chain{path};
    for (int hops = 0; hops < 40; ++hops) {
        struct stat info {};
        if (::lstat(path.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) break;
        std::error_code error;
        const std::filesystem::path next = std::filesystem::read_symlink(path, error);
        if (error) break;
        path = next.is_absolute() ? next : path.parent_path() / next;
        chain.push_back(path);
    }
    return chain;
}

// The path a file is written at once its symbolic links are followed (the
// path itself when it is no link), so that the link stays and the file it
// names is replaced. A link to something other than a regular file (a
// device, a pipe: /dev/stdout) is kept, since such a target is written in
// place through it. A chain that ends nowhere is followed link by link, so
// that the file is created where the last link points; when a link cannot
// be read, creating the file fails there (/dev/stdout with standard output
// closed ends at /proc/self/fd/1, which no one can create), where renaming
// over the first link would have replaced it.
std::filesystem::path followed(const std::filesystem::path& path) {
    struct stat info {};
    if (::lstat(path.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return path;
    if (::stat(path.c_str(), &info) == 0) {
        if (!S_ISREG(info.st_mode)) return path;
        std::error_code error;
        const std::filesystem::path real = std::filesystem::canonical(path, error);
        return error ? path : real;
    }
    return link_chain(path).back();
}

// Whether `path` names standard output itself: /dev/stdout, /dev/fd/1 or
// /proc/self/fd/1, or a link that leads through one of them. Only such a
// name is written through descriptor 1; the file standard output happens to
// be redirected to, named as itself, is replaced as any file is (else what
// the command prints would land inside it).
bool names_standard_output(const std::filesystem::path& path) {
    const std::string own = "/proc/" + std::to_string(::getpid()) + "/fd/1";
    for (const std::filesystem::path& hop : link_chain(path)) {
        const std::filesystem::path name = hop.lexically_normal();
        if (name == "/dev/stdout" || name == "/dev/fd/1" || name == "/proc/self/fd/1" ||
            name == own)
            return true;
    }
    return false;
}

} // namespace

// Buffers writes to a file descriptor; a failed write(2) throws WriteError,
// which the stream rethrows (badbit), so the caller stops at the first one.
class OutputFile::Buffer final : public std::streambuf {
public:
    Buffer(int fd, std::string description) : fd_(fd), description_(std::move(description)) {
        setp(buffer_, buffer_ + sizeof buffer_);
    }
    ~Buffer() override {
        if (fd_ >= 0) ::close(fd_);
    }
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    // Writes what is buffered, syncs a regular file and closes the descriptor.
    void close(bool regular) {
        drain();
        // fsync makes the rename below publish bytes that are on the disk.
        if (regular && ::fsync(fd_) != 0) fail(errno);
        const int fd = fd_;
        fd_ = -1;
        if (::close(fd) != 0) fail(errno);
    }

protected:
    int_type overflow(int_type c) override {
        drain();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override {
        drain();
        return 0;
    }

private:
    int fd_;
    std::string description_;
    char buffer_[1 << 16];

    [[noreturn]] void fail(int error) const {
        throw WriteError("cannot write " + description_ + ": " + reason(error));
    }

    void drain() {
        const char* p = pbase();
        while (p < pptr()) {
            const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) fail(errno);
            p += n;
        }
        setp(buffer_, buffer_ + sizeof buffer_);
    }
};

void require_file_name(const std::string& path, const std::string& what) {
    if (path.empty())
        throw UsageError("found an empty file name for " + what + ", expected a file name");
    if (path == "-")
        throw UsageError("found '-' for " + what +
                         ", expected a file name (/dev/stdout for standard output)");
}

void refuse_same_output(const std::string& a, const std::string& what_a, const std::string& b,
                        const std::string& what_b) {
    if (a.empty() || b.empty()) return;
    // Neither file need exist yet: compare the paths as the file system
    // would resolve them, and existing files by device and inode.
    // (weakly_canonical leaves a relative path relative when no part of it
    // exists yet: "y.svg" and "./y.svg" would differ; hence absolute first.)
    std::error_code error_a, error_b;
    const std::filesystem::path path_a = std::filesystem::weakly_canonical(
                                    std::filesystem::absolute(followed(a)), error_a),
                                path_b = std::filesystem::weakly_canonical(
                                    std::filesystem::absolute(followed(b)), error_b);
    bool same = error_a || error_b ? a == b : path_a == path_b;
    struct stat sa {
    }, sb{};
    if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)
        same = same || same_file(sa, sb);
    if (same)
        throw UsageError("found " + what_b + " '" + b + "' naming the same file as " + what_a +
                         " '" + a + "', expected another file (one would replace the other)");
}

void refuse_input_as_output(const std::string& path, const std::vector<std::string>& inputs,
                            const std::string& what) {
    struct stat target {};
    if (::stat(path.c_str(), &target) != 0) return; // a new file overwrites nothing
    for (const std::string& input : inputs) {
        struct stat in {};
        if (::stat(input.c_str(), &in) == 0 && same_file(in, target))
            throw UsageError("found " + what + " '" + path + "' naming the input '" + input +
                             "', expected another file (it would be overwritten)");
    }
}

OutputFile::OutputFile(const std::string& given, const std::vector<std::string>& inputs,
                       const std::string& what)
    : what_(what + " '" + given + "'") {
    require_file_name(given, what);
    refuse_input_as_output(given, inputs, what);
    path_ = followed(given).string();
    const std::string& path = path_;
    struct stat target {};
    const bool exists = ::stat(path.c_str(), &target) == 0;
    if (exists) {
        if (S_ISDIR(target.st_mode))
            throw UsageError("found a directory for " + what_ + ", expected a file name");
    }
    // A link still, yet no file: a loop, or a chain too long to follow.
    // Creating the file would replace the link.
    struct stat link {};
    if (!exists && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) cannot_create(ELOOP);
    // Standard output named as such (/dev/stdout) is written through the
    // descriptor the shell opened: a rename would drop what `>>` appends to,
    // and a fresh open would start at its beginning.
    const bool is_standard_output = exists && names_standard_output(given);
    int fd = -1;
    if (is_standard_output) {
        fd = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 0);
        if (fd < 0) cannot_create(errno);
    } else if (exists && !S_ISREG(target.st_mode)) {
        fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) cannot_create(errno);
    } else {
        // The temporary file sits beside the target, so the rename stays on
        // one file system and is atomic; its name says what it is, should a
        // killed run leave it behind.
        const std::filesystem::path target_path(path);
        // Appended piece by piece: GCC 12 at -O3 warns falsely (-Wrestrict)
        // on "." + name + suffix when this file is compiled on its own.
        std::string name = ".";
        name += target_path.filename().string();
        name += ".partial-XXXXXX";
        std::string pattern = (target_path.parent_path() / name).string();
        fd = ::mkstemp(pattern.data());
        if (fd < 0) cannot_create(errno);
        temporary_ = pattern;
        slot_ = remember_unfinished(temporary_);
        // mkstemp makes the file private; give it the mode a plain create
        // would (or the mode of the file it replaces).
        mode_t mode = 0666;
        if (exists) {
            mode = target.st_mode & 07777;
        } else {
            const mode_t mask = ::umask(0);
            ::umask(mask);
            mode &= ~mask;
        }
        ::fchmod(fd, mode);
    }
    buffer_ = std::make_unique<Buffer>(fd, what_);
    stream_ = std::make_unique<std::ostream>(buffer_.get());
    stream_->exceptions(std::ios::badbit);
}

OutputFile::~OutputFile() {
    forget_unfinished(slot_);
    if (!committed_ && !temporary_.empty()) ::unlink(temporary_.c_str());
}

// A path that cannot be opened or created (no such directory, no
// permission) is a mistake on the command line, found before any work:
// exit 2, as for a bad option. Failures while writing are WriteError.
void OutputFile::cannot_create(int error) const {
    throw UsageError("cannot write " + what_ + ": " + reason(error));
}

std::ostream& OutputFile::stream() {
    return *stream_;
}

void OutputFile::commit() {
    buffer_->close(!temporary_.empty());
    if (!temporary_.empty() && ::rename(temporary_.c_str(), path_.c_str()) != 0)
        throw WriteError("cannot write " + what_ + ": " + reason(errno));
    forget_unfinished(slot_);
    committed_ = true;
}

void remove_unfinished_output() noexcept {
    for (int i = 0; i < max_unfinished; ++i)
        if (unfinished_used[i].load() == ready) ::unlink(unfinished_path[i]);
}

// The error of a write to standard output that failed earlier, inside the
// stream's buffering, after which errno was overwritten: a pipe or socket
// whose reader is gone reports POLLERR on poll(2), which is the broken pipe
// (EPIPE) that write(2) gave then. 0 when it cannot be told.
int earlier_stdout_error() {
    struct stat info {};
    if (::fstat(STDOUT_FILENO, &info) != 0) return errno;
    if (!S_ISFIFO(info.st_mode) && !S_ISSOCK(info.st_mode)) return 0;
    pollfd out{STDOUT_FILENO, POLLOUT, 0};
    if (::poll(&out, 1, 0) == 1 && (out.revents & POLLERR)) return EPIPE;
    return 0;
}

void finish_standard_output() {
    errno = 0;
    const bool flushed = std::fflush(stdout) == 0;
    int error = errno;
    if (flushed && !std::ferror(stdout) && std::cout.good()) return;
    if (error == 0) error = earlier_stdout_error();
    throw WriteError(std::string("cannot write to standard output: ") +
                     (error ? reason(error) : "a write failed"));
}

} // namespace orthoray::cli
