# cmake/write_commit.cmake against three trees: a fresh repository at a known
# commit (the 12-digit commit), the same with a tracked file changed
# ("-dirty"; an untracked file alone does not count), and a directory inside
# some other repository, this build's own tree ("unknown": its commit would
# name other code). Run as cmake -DSCRIPT=... -DWORK_DIR=... -P this file.
find_package(Git QUIET)
if(NOT GIT_FOUND)
    message("SKIPPED: no git on this machine")
    return()
endif()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/repo ${WORK_DIR}/repo/inner)

function(stamp source out)
    execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${source}
                            -DOUTPUT=${WORK_DIR}/stamp.hpp -P ${SCRIPT}
                    RESULT_VARIABLE failed)
    if(failed)
        message(FATAL_ERROR "write_commit.cmake failed on ${source}")
    endif()
    file(STRINGS ${WORK_DIR}/stamp.hpp line REGEX "define ORTHORAY_COMMIT")
    string(REGEX REPLACE ".*ORTHORAY_COMMIT \"([^\"]*)\".*" "\\1" value "${line}")
    set(${out} "${value}" PARENT_SCOPE)
endfunction()

function(git)
    execute_process(COMMAND ${GIT_EXECUTABLE} -c user.name=test -c user.email=test@example.org
                            -c commit.gpgsign=false
                            -c init.defaultBranch=main ${ARGN}
                    WORKING_DIRECTORY ${WORK_DIR}/repo RESULT_VARIABLE failed
                    OUTPUT_VARIABLE out ERROR_VARIABLE out)
    if(failed)
        message(FATAL_ERROR "git ${ARGN}: ${out}")
    endif()
endfunction()

file(WRITE ${WORK_DIR}/repo/tracked.txt "one\n")
git(init -q)
git(add tracked.txt)
git(commit -q -m first)
execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short=12 HEAD
                WORKING_DIRECTORY ${WORK_DIR}/repo OUTPUT_VARIABLE head
                OUTPUT_STRIP_TRAILING_WHITESPACE)

stamp(${WORK_DIR}/repo commit)
if(NOT commit STREQUAL head)
    message(FATAL_ERROR "clean tree: got '${commit}', expected '${head}'")
endif()
file(WRITE ${WORK_DIR}/repo/untracked.txt "not added\n")
stamp(${WORK_DIR}/repo commit)
if(NOT commit STREQUAL head)
    message(FATAL_ERROR "untracked file only: got '${commit}', expected '${head}'")
endif()
file(WRITE ${WORK_DIR}/repo/tracked.txt "two\n")
stamp(${WORK_DIR}/repo commit)
if(NOT commit STREQUAL "${head}-dirty")
    message(FATAL_ERROR "changed tracked file: got '${commit}', expected '${head}-dirty'")
endif()
stamp(${WORK_DIR}/repo/inner commit)
if(NOT commit STREQUAL "unknown")
    message(FATAL_ERROR "a directory inside another repository: got '${commit}'")
endif()
message("write_commit.cmake: ${head}, ${head}-dirty and unknown, as expected")
