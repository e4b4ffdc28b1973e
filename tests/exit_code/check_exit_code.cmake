# Run pg_solve on ${PRM}; require exit code 1 and a message matching
# ${EXPECT} on standard error. Used by the exit_code tests; ${LAUNCHER} (if
# set) is the MPI launcher, e.g. "mpiexec;-np;2". With ${SUMMARY} (a
# summary.json the run must leave behind) its text must match
# ${SUMMARY_EXPECT}, white space collapsed as for the message. With
# ${FORBID}, neither standard output nor standard error may match it.
if(DEFINED SUMMARY)
  file(REMOVE ${SUMMARY})
endif()
# (${OPTION}, if set, goes before the file, e.g. --validate)
execute_process(COMMAND ${LAUNCHER} ${PG_SOLVE} ${OPTION} ${PRM}
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
# A user error is a message, not a debugging session: no source location
# and no stack trace (PG_ERROR_DETAILS=1 asks for them).
if(err MATCHES "Stacktrace:|An error occurred in line")
  message(FATAL_ERROR "The message shows deal.II's source location or stack trace:\n${err}")
endif()
# ${FORBID} (if set): a regex that neither output may match, e.g. the line
# of a step cut where a run must stop at once.
if(DEFINED FORBID AND "${out}${err}" MATCHES "${FORBID}")
  message(FATAL_ERROR "The output matches <${FORBID}>:\n${out}\n${err}")
endif()
if(DEFINED SUMMARY)
  if(NOT EXISTS ${SUMMARY})
    message(FATAL_ERROR "The run left no <${SUMMARY}>.")
  endif()
  file(READ ${SUMMARY} summary)
  string(REGEX REPLACE "[ \t\r\n]+" " " summary_flat "${summary}")
  if(NOT summary_flat MATCHES "${SUMMARY_EXPECT}")
    message(FATAL_ERROR "<${SUMMARY}> does not match <${SUMMARY_EXPECT}>:\n${summary}")
  endif()
endif()
message(STATUS "exit code 1 with the expected message")
