#include "batch_results.hpp"

#include "commands.hpp"
#include "output_file.hpp"

#include <boost/crc.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <limits>
#include <unistd.h>

namespace orthoray::cli {
namespace {

// A line longer than this is no result orthoray wrote (one holds a few
// hundred bytes, a few thousand with many targets): a torn or foreign file.
constexpr std::size_t longest_line = std::size_t{1} << 20;

[[noreturn]] void cannot_write(const std::string& path, int error) {
    throw WriteError("cannot write '" + path + "': " + std::strerror(error));
}

// The key of a complete result line, or nothing when `line` is not one.
std::optional<std::string> key_of(const nlohmann::json& j) {
    if (!j.is_object()) return std::nullopt;
    const auto version = j.find("hash");
    if (const auto path = j.find("path");
        path != j.end() && path->is_string() && version != j.end() && version->is_string())
        return result_key(path->get<std::string>(), version->get<std::string>());
    const auto generator = j.find("generate"), seed = j.find("seed");
    if (generator != j.end() && generator->is_string() && seed != j.end() &&
        seed->is_number_unsigned())
        return result_key("generate " + generator->get<std::string>(),
                          std::to_string(seed->get<std::uint64_t>()));
    return std::nullopt;
}

// Whether a result line records a failure: bad input (status 2) or a limit (3).
bool failed(const nlohmann::json& j) {
    const auto status = j.find("status");
    return status != j.end() && status->is_number_unsigned() &&
           (status->get<std::uint64_t>() == 2 || status->get<std::uint64_t>() == 3);
}

// What a result line names its instance by: the path, or the seed of a
// generated instance ("" when it names neither).
std::string name_of(const std::string& line) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) return {};
    if (const auto path = j.find("path"); path != j.end() && path->is_string())
        return path->get<std::string>();
    if (const auto seed = j.find("seed"); seed != j.end() && seed->is_number_unsigned())
        return std::to_string(seed->get<std::uint64_t>());
    return {};
}

} // namespace

std::string result_key(const std::string& source, const std::string& version) {
    return source + '\n' + version;
}

std::string content_hash(const std::string& bytes) {
    boost::crc_optimal<64, 0x42F0E1EBA9EA3693ULL, 0, 0, false, false> crc;
    crc.process_bytes(bytes.data(), bytes.size());
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(crc.checksum()));
    return hex;
}

ResultsLog::ResultsLog() = default;

ResultsLog::ResultsLog(const std::string& path, bool resume)
    : standard_output_(false), path_(path) {
    require_file_name(path, "the results");
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | (resume ? 0 : O_TRUNC), 0644);
    if (fd_ < 0)
        throw UsageError("cannot open the results file '" + path + "': " + std::strerror(errno));
    if (resume) {
        // Keep every complete line up to the first one that is not; the
        // rest is the torn tail of a run that was killed.
        std::string line;
        off_t good = 0, offset = 0;
        bool torn = false;
        char buffer[1 << 16];
        for (;;) {
            const ssize_t got = ::read(fd_, buffer, sizeof buffer);
            if (got < 0) {
                if (errno == EINTR) continue;
                throw UsageError("cannot read the results file '" + path +
                                 "': " + std::strerror(errno));
            }
            if (got == 0) break;
            for (ssize_t i = 0; i < got && !torn; ++i) {
                ++offset;
                if (buffer[i] != '\n') {
                    line += buffer[i];
                    torn = line.size() > longest_line;
                    continue;
                }
                const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
                const std::optional<std::string> key = key_of(j);
                if (!key)
                    torn = true;
                else {
                    done_[*key] = failed(j);
                    good = offset;
                }
                line.clear();
            }
            if (torn) break;
        }
        const off_t end = ::lseek(fd_, 0, SEEK_END);
        dropped_ = static_cast<std::uint64_t>(end - good);
        if (dropped_ > 0 && ::ftruncate(fd_, good) != 0) cannot_write(path, errno);
        ::lseek(fd_, good, SEEK_SET);
    }
    next_sync_ = std::chrono::steady_clock::now() + std::chrono::seconds(1);
}

Kept ResultsLog::kept(const std::string& key) const {
    const auto it = done_.find(key);
    if (it == done_.end()) return Kept::no;
    return it->second ? Kept::failed : Kept::decided;
}

std::vector<std::pair<std::string, bool>> ResultsLog::versions_of(const std::string& source) const {
    // Keys are source, newline, version: a source's keys are adjacent.
    std::vector<std::pair<std::string, bool>> versions;
    const std::string prefix = source + '\n';
    for (auto it = done_.lower_bound(prefix);
         it != done_.end() && it->first.compare(0, prefix.size(), prefix) == 0; ++it)
        versions.emplace_back(it->first.substr(prefix.size()), it->second);
    return versions;
}

ResultsLog::~ResultsLog() {
    if (fd_ >= 0) ::close(fd_);
}

void ResultsLog::append(const std::string& line) {
    const std::string bytes = line + '\n';
    const std::lock_guard lock(mutex_);
    if (standard_output_) {
        std::fwrite(bytes.data(), 1, bytes.size(), stdout);
        if (std::fflush(stdout) != 0 || std::ferror(stdout))
            throw WriteError(std::string("cannot write the results: ") + std::strerror(errno));
        return;
    }
    if (fd_ < 0) throw WriteError("the results file '" + path_ + "' is closed");
    const off_t start = ::lseek(fd_, 0, SEEK_CUR);
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd_, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            // A full disk or a file size limit can take part of the line:
            // take that part back, so that the file holds whole lines only
            // (docs/batch.md). Should even that fail, --resume drops it.
            const int error = errno;
            if (written > 0 && start >= 0 && ::ftruncate(fd_, start) == 0)
                ::lseek(fd_, start, SEEK_SET);
            cannot_write(path_, error);
        }
        written += static_cast<std::size_t>(n);
    }
    if (const auto now = std::chrono::steady_clock::now(); now >= next_sync_) {
        if (::fdatasync(fd_) != 0) cannot_write(path_, errno);
        next_sync_ = now + std::chrono::seconds(1);
    }
}

void ResultsLog::close() {
    const std::lock_guard lock(mutex_);
    if (standard_output_ || fd_ < 0) return;
    const int fd = fd_;
    fd_ = -1;
    if (::fdatasync(fd) != 0) {
        const int error = errno;
        ::close(fd);
        cannot_write(path_, error);
    }
    if (::close(fd) != 0) cannot_write(path_, errno);
}

} // namespace orthoray::cli

namespace orthoray::cli {

void ResultsLog::sort_lines(const std::function<std::size_t(const std::string& name)>& position) {
    if (standard_output_) return;
    std::vector<std::pair<std::size_t, std::string>> lines;
    {
        std::ifstream in(path_, std::ios::binary);
        std::string line;
        while (std::getline(in, line)) {
            lines.emplace_back(position(name_of(line)), std::move(line));
        }
        if (in.bad()) throw WriteError("cannot read back '" + path_ + "' to sort it");
    }
    std::stable_sort(lines.begin(), lines.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    OutputFile sorted(path_, {}, "the results");
    for (const auto& [where, line] : lines) sorted.stream() << line << '\n';
    sorted.commit();
}

} // namespace orthoray::cli
