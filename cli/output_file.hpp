// Every file the command line writes, and every certificate the Python
// module writes, goes through OutputFile: the bytes go to a temporary file
// beside the target, every write and the close are checked, and only a complete file is renamed
// over the target, so a reader never sees a torn file, whatever kills the process (docs/limits.md).
#pragma once

#include "usage_error.hpp"

#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace orthoray::cli {

// A write that failed (a full disk, a file size limit, a broken pipe):
// reported as `orthoray: cannot write ...: REASON`, exit status 5.
struct WriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Refuses (UsageError) an empty name and "-": inputs read "-" as standard
// input, but an output named "-" would be a file of that name, a surprise,
// and standard output carries the answer; /dev/stdout names it when that is
// what is meant. `what` names the output in the message.
void require_file_name(const std::string& path, const std::string& what);

// Refuses (UsageError) an existing `path` that names the same file as one
// of `inputs` (hard links and other spellings included): writing it would
// destroy an input. `what` names the output in the message.
void refuse_input_as_output(const std::string& path, const std::vector<std::string>& inputs,
                            const std::string& what);

// Refuses (UsageError) two outputs of one command that name the same file
// (the same path in another spelling, or a hard link): the second would
// replace the first. `what_a` and `what_b` name them in the message.
void refuse_same_output(const std::string& a, const std::string& what_a, const std::string& b,
                        const std::string& what_b);

class OutputFile {
public:
    // Refuses (UsageError) what require_file_name refuses and a path that
    // names the same file as one of `inputs`. A target that exists and is not a regular
    // file (/dev/null, /dev/full, a FIFO) is written in place: it cannot be
    // replaced by a rename, and a reader of a device sees what arrives. A
    // symbolic link is followed: the file it names is replaced and the link
    // stays (renaming over the link would replace the link itself).
    OutputFile(const std::string& path, const std::vector<std::string>& inputs,
               const std::string& what);
    // Removes the temporary file unless commit() ran.
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    // Throws WriteError from the write that failed.
    std::ostream& stream();
    // Flushes, syncs and closes the file, then renames it over the target.
    void commit();

private:
    class Buffer;
    [[noreturn]] void cannot_create(int error) const;
    std::string path_, temporary_, what_;
    std::unique_ptr<Buffer> buffer_;
    std::unique_ptr<std::ostream> stream_;
    int slot_ = -1; // in the table remove_unfinished_output() reads
    bool committed_ = false;
};

// Removes the temporary files of the outputs not yet committed. Safe to call
// from a signal handler (it only calls unlink).
void remove_unfinished_output() noexcept;

// Flushes standard output and throws WriteError if any write to it failed
// (a closed pipe, /dev/full): run once, after a command.
void finish_standard_output();

} // namespace orthoray::cli
