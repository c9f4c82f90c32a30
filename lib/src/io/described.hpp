// What a reader expects next, as its error message says it: a string, or a
// function that builds one. The scene readers ask for several values an
// element, and building every description while nothing is wrong (string
// concatenations, most too long to be stored in place) took longer than
// reading the values; a function is called only when its value is at fault.
#pragma once

#include <string>
#include <type_traits>

namespace orthoray::io {

template <class What>
std::string spelled(const What& what) {
    if constexpr (std::is_invocable_v<const What&>)
        return what();
    else
        return std::string(what);
}

} // namespace orthoray::io
