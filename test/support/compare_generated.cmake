# Runs COMMAND (a list) and fails unless its standard output equals the file EXPECTED: for
# checked-in files generated from code (docs/statistics.md), so they cannot go stale.
execute_process(COMMAND ${COMMAND} OUTPUT_VARIABLE generated RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${COMMAND} failed (${rc}): ${err}")
endif()
file(READ ${EXPECTED} checked_in)
if(NOT generated STREQUAL checked_in)
  file(WRITE ${EXPECTED}.generated "${generated}")
  message(FATAL_ERROR "${EXPECTED} is stale: it differs from what the code generates "
                      "(written to ${EXPECTED}.generated). Run: ${REGENERATE}")
endif()
