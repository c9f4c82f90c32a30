// Reading .scene files. Every error names the file, line and column, what
// was found there and what was expected; see docs/scene-format.md.
#pragma once

#include "orthoray/scene.hpp"

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

// Reads a whole file (throws InputError when it cannot be opened).
std::string read_file(const std::string& path);

// read_scene(read_file(path), path).
Scene load_scene(const std::string& path);

} // namespace orthoray
