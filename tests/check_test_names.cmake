# ctest hands a test's name to Catch on its command line, where a name that
# starts with '-' is read as an option ("Unrecognised token") and the test
# fails without running. This check lists every Catch2 test name and fails
# on such a name, so the mistake shows up as one clear failure.
execute_process(COMMAND ${TESTS} --list-test-names-only
                OUTPUT_VARIABLE names RESULT_VARIABLE status)
# Catch2 v2 exits with the number of tests listed; anything else is a failure to run.
if(NOT status MATCHES "^[0-9]+$")
    message(FATAL_ERROR "could not list the test names: ${status}")
endif()
string(REPLACE "\n" ";" names "${names}")
set(bad "")
foreach(name IN LISTS names)
    if(name MATCHES "^-")
        list(APPEND bad "${name}")
    endif()
endforeach()
if(bad)
    message(FATAL_ERROR "test names that ctest would pass to Catch as options: ${bad}")
endif()
list(LENGTH names count)
message(STATUS "${count} test names, none starting with '-'")
