# Run pg_solve on ${PRM}; require exit code 1 and a message matching
# ${EXPECT} on standard error. Used by the exit_code tests; ${LAUNCHER} (if
# set) is the MPI launcher, e.g. "mpiexec;-np;2".
execute_process(COMMAND ${LAUNCHER} ${PG_SOLVE} ${PRM}
                RESULT_VARIABLE code
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT code EQUAL 1)
  message(FATAL_ERROR "pg_solve ${PRM} returned <${code}>, expected 1.\n${out}\n${err}")
endif()
# deal.II wraps its messages at a width that depends on the path lengths in
# them; compare with all runs of white space collapsed to one blank.
string(REGEX REPLACE "[ \t\r\n]+" " " err_flat "${err}")
if(NOT err_flat MATCHES "${EXPECT}")
  message(FATAL_ERROR "The message does not match <${EXPECT}>:\n${err}")
endif()
message(STATUS "exit code 1 with the expected message")
