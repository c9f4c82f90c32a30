# cmake/write_commit.cmake against four trees: a fresh repository at a known
# commit (the 12-digit commit), the same with a tracked file changed
# ("-dirty"; an untracked file alone does not count), a directory inside
# some other repository, this build's own tree ("unknown": its commit would
# name other code), and, when run as root, the repository owned by another
# user, which git itself refuses ("dubious ownership") unless told the
# directory is safe. Run as cmake -DSCRIPT=... -DWORK_DIR=... -P this file.
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

# Root building another user's checkout, as in a container with the sources
# mounted: the commit all the same. Skipped where it cannot be set up, or
# could not fail; `passed` ends the check with the line saying which.
function(passed other_owner)
    message("write_commit.cmake: ${head}, ${head}-dirty and unknown, as expected; "
            "the checkout owned by another user: ${other_owner}")
endfunction()
execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT uid STREQUAL "0")
    passed("SKIPPED (not running as root, so it cannot be given away)")
    return()
endif()
execute_process(COMMAND chown -R 65534:65534 ${WORK_DIR}/repo RESULT_VARIABLE failed
                ERROR_QUIET)
if(failed)
    passed("SKIPPED (this file system refused chown)")
    return()
endif()
execute_process(COMMAND ${GIT_EXECUTABLE} -C ${WORK_DIR}/repo rev-parse HEAD
                RESULT_VARIABLE refused OUTPUT_QUIET ERROR_QUIET)
stamp(${WORK_DIR}/repo commit)
execute_process(COMMAND chown -R 0:0 ${WORK_DIR}/repo)
if(NOT refused)
    passed("SKIPPED (git here already trusts every directory: the case could not fail)")
    return()
endif()
if(NOT commit STREQUAL "${head}-dirty")
    message(FATAL_ERROR "checkout owned by another user: got '${commit}', expected '${head}-dirty'")
endif()
passed("${head}-dirty, as expected")
