# Writes OUTPUT, a header defining ORTHORAY_COMMIT: the git commit SOURCE_DIR
# is checked out at, with "-dirty" when tracked files differ from it, or
# "unknown" where there is no such commit (a source tarball, no git, or a tree
# that lies inside some other repository). Run at every build, not at
# configure time, so that a rebuild after a commit names the new one; the
# file is rewritten only when the text changes, so an unchanged commit
# recompiles nothing.
#
# git refuses a repository owned by another user ("dubious ownership"), as
# when root builds a user's checkout in a container. Every call here names
# SOURCE_DIR itself as a safe directory: the build already runs this tree's
# own CMake code, so trusting its git configuration adds no risk, and only
# that one path is named, so a tree inside some other user's repository
# still reads as unknown.
set(commit unknown)
find_package(Git QUIET)
if(GIT_FOUND)
    file(REAL_PATH "${SOURCE_DIR}" source)
    set(git ${GIT_EXECUTABLE} -c safe.directory=${source} -C ${source})
    execute_process(COMMAND ${git} rev-parse --show-toplevel
                    OUTPUT_VARIABLE top RESULT_VARIABLE failed
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(NOT failed AND NOT top STREQUAL "")
        file(REAL_PATH "${top}" top)
    endif()
    if(NOT failed AND top STREQUAL source)
        execute_process(COMMAND ${git} rev-parse --short=12 HEAD
                        OUTPUT_VARIABLE head RESULT_VARIABLE failed
                        OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
        if(NOT failed)
            set(commit ${head})
            execute_process(COMMAND ${git} status --porcelain --untracked-files=no
                            OUTPUT_VARIABLE changes RESULT_VARIABLE failed ERROR_QUIET)
            if(NOT failed AND NOT changes STREQUAL "")
                string(APPEND commit -dirty)
            endif()
        endif()
    endif()
endif()
set(text "// Written by cmake/write_commit.cmake at build time.\n#pragma once\n#define ORTHORAY_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS ${OUTPUT})
    file(READ ${OUTPUT} old)
endif()
if(NOT old STREQUAL text)
    file(WRITE ${OUTPUT} "${text}")
endif()
