// Reading scene files, as .scene text or as JSON. Every error names the file, line and column, what
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

// Parses the text of a JSON scene (docs/scene-json.md), with the same kind
// of error messages; malformed JSON is reported at its line and column too.
Scene read_scene_json(std::string_view text, const std::string& file = "<input>");

// Reads a whole file (throws InputError when it cannot be opened).
std::string read_file(const std::string& path);

enum class SceneFormat {
    automatic, // by the file name: JSON when it ends in .json, .scene text otherwise
    text,      // the .scene format (docs/scene-format.md)
    json,      // the JSON scene format (docs/scene-json.md)
};

// `requested`, or for automatic the format the name of `path` implies.
SceneFormat resolve_scene_format(const std::string& path, SceneFormat requested);

// Reads the file at `path` in the given format. Every command that takes a
// scene reads it through here, so each accepts both formats.
Scene load_scene(const std::string& path, SceneFormat format = SceneFormat::automatic);

} // namespace orthoray
