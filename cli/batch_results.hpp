// The results of `orthoray batch`: JSON Lines, one line an instance,
// appended as each instance is decided, so that nothing decided is lost and
// nothing half-written is misread (docs/batch.md).
#pragma once

#include "batch_instance.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace orthoray::cli {

// An instance's identity in a results file: its path and the hash of its
// bytes (so an edited file is decided again), or for a generated instance
// its generator arguments and seed.
std::string result_key(const std::string& source, const std::string& version);

// CRC-64 (ECMA-182) of `bytes`, as 16 hex digits: names a file's content.
std::string content_hash(const std::string& bytes);

class ResultsLog {
public:
    // Standard output: lines are written and flushed one at a time.
    ResultsLog();
    // A results file. Without `resume` it is emptied. With `resume` its
    // complete lines are kept and their keys remembered; the first line that
    // is not a complete result (the torn end of a killed run) is cut off
    // with everything after it, and `dropped_bytes` says how much.
    ResultsLog(const std::string& path, bool resume);
    ~ResultsLog();
    ResultsLog(const ResultsLog&) = delete;
    ResultsLog& operator=(const ResultsLog&) = delete;

    // Whether the file holds a result for `key`, and whether that result
    // failed (status 2, bad input, or 3, a limit).
    Kept kept(const std::string& key) const;
    // The versions (content hashes) the file holds a result for at
    // `source`, each with whether its result failed.
    std::vector<std::pair<std::string, bool>> versions_of(const std::string& source) const;
    std::size_t kept() const { return done_.size(); }
    std::uint64_t dropped_bytes() const { return dropped_; }

    // Appends `line` and a newline in one write(2): a kill can cut a line
    // short but never interleave two. Safe to call from several threads.
    // Throws WriteError when the write fails.
    void append(const std::string& line);
    // Flushes the data to the disk (fdatasync) and closes; throws WriteError.
    void close();
    // After close(), rewrites the file with its lines stably sorted by
    // `position` of the name each gives (its path, or its seed), through a
    // temporary file renamed into place, so a complete batch leaves the same
    // bytes, apart from timings, however many threads or ranks decided it.
    void sort_lines(const std::function<std::size_t(const std::string& name)>& position);

private:
    std::mutex mutex_;
    bool standard_output_ = true;
    int fd_ = -1;
    std::string path_;
    std::map<std::string, bool> done_; // key -> its result failed
    std::uint64_t dropped_ = 0;
    // Lines reach the disk at most a second after they are written, so a
    // power loss costs at most the last second's instances (decided again
    // on --resume), while a batch of tiny instances is not slowed by a sync
    // per line.
    std::chrono::steady_clock::time_point next_sync_;
};

} // namespace orthoray::cli
