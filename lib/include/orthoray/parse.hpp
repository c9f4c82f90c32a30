// Reading scene files, as .scene text or as JSON. Every error names the file, line and column, what
// was found there and what was expected; see docs/scene-format.md.
#pragma once

#include "orthoray/scene.hpp"

#include <cstddef>
#include <functional>
#include <istream>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace orthoray {

// Bad input: one message of the form `FILE:LINE:COL: found ..., expected ...`.
class InputError : public std::runtime_error {
public:
    InputError(const std::string& file, int line, int column, const std::string& message);
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    int column() const { return column_; }
    const std::string& message() const { return message_; }

private:
    std::string file_;
    int line_, column_;
    std::string message_;
};

// Parses the text of a .scene file; `file` is only used in error messages.
Scene read_scene(std::string_view text, const std::string& file = "<input>");

// Parses the text of a JSON scene (docs/scene-json.md), with the same kind
// of error messages; malformed JSON is reported at its line and column too.
Scene read_scene_json(std::string_view text, const std::string& file = "<input>");

// The most orthoray reads into memory at once: a whole scene file, or one
// line of a certificate (certificates are streamed a line at a time, so only
// their lines are capped). 256 MiB holds a scene of some ten million
// mirrors and a certificate line with coordinates of 10^8 digits, far past
// what the engines can use, while /dev/zero or an endless pipe given by
// mistake ends within a second (docs/limits.md).
constexpr std::size_t input_cap_bytes = std::size_t{256} << 20;

// A signal handler ran while a file was opened or read (a FIFO waiting for
// its writer, a slow pipe): the command stops as interrupted, not as bad
// input.
class ReadInterrupted : public std::runtime_error {
public:
    explicit ReadInterrupted(const std::string& path);
};

// Parsing a huge scene takes a while after the bytes are in (converting a
// 10^6-digit decimal to binary takes tens of milliseconds, and a capped file
// holds millions of statements). While a ReadStopCheck lives on a thread,
// the scene readers on that thread ask it before every number they convert
// and throw ReadInterrupted for `path` once it answers true, so a stop
// request is seen within one number's conversion. The command line sets
// one; without it reading is never interrupted.
class ReadStopCheck {
public:
    ReadStopCheck(std::string path, std::function<bool()> stop_requested);
    ~ReadStopCheck();
    ReadStopCheck(const ReadStopCheck&) = delete;
    ReadStopCheck& operator=(const ReadStopCheck&) = delete;
    // Throws ReadInterrupted when the innermost check on this thread says so.
    static void poll();

private:
    std::string path_;
    std::function<bool()> stop_requested_;
    ReadStopCheck* outer_;
};

// Reads a whole file, at most input_cap_bytes. Throws InputError for a
// missing or unreadable file, a directory or a larger input.
std::string read_file(const std::string& path);

// Opens a file to stream (a certificate), with read_file's checks; a read
// error later throws InputError from the stream instead of looking like the
// end of the file.
std::unique_ptr<std::istream> open_file_stream(const std::string& path);

enum class SceneFormat {
    automatic, // by the file name: JSON for .json, a grid maze for .grid, .scene text otherwise
    text,      // the .scene format (docs/scene-format.md)
    json,      // the JSON scene format (docs/scene-json.md)
    grid,      // a grid mirror maze, read as its scene (docs/grid-mazes.md); read only
};

// `requested`, or for automatic the format the name of `path` implies.
SceneFormat resolve_scene_format(const std::string& path, SceneFormat requested);

// Parses `text` in the given format (automatic: as the name `file` implies).
Scene parse_scene(std::string_view text, const std::string& file, SceneFormat format);

// Reads the file at `path` in the given format. Every command that takes a
// scene reads it through here, so each accepts both formats.
Scene load_scene(const std::string& path, SceneFormat format = SceneFormat::automatic);

} // namespace orthoray
