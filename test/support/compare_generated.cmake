# Runs COMMAND (a list) and fails unless its standard output equals the file EXPECTED: for
# checked-in files generated from code (docs/statistics.md), so they cannot go stale. On a
# mismatch it writes what the code generates to GENERATED_COPY (in the build tree, never the
# source tree), for a diff.
execute_process(COMMAND ${COMMAND} OUTPUT_VARIABLE generated RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${COMMAND} failed (${rc}): ${err}")
endif()
file(READ ${EXPECTED} checked_in)
if(NOT generated STREQUAL checked_in)
  file(WRITE ${GENERATED_COPY} "${generated}")
  message(FATAL_ERROR "${EXPECTED} is stale: it differs from what the code generates "
                      "(written to ${GENERATED_COPY}). Run: ${REGENERATE}")
endif()
