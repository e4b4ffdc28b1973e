# Run pg_solve on ${PRM}; require exit code 1 and a message matching
# ${EXPECT} on standard error. Used by the exit_code tests.
execute_process(COMMAND ${PG_SOLVE} ${PRM}
                RESULT_VARIABLE code
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT code EQUAL 1)
  message(FATAL_ERROR "pg_solve ${PRM} returned <${code}>, expected 1.\n${out}\n${err}")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "The message does not match <${EXPECT}>:\n${err}")
endif()
message(STATUS "exit code 1 with the expected message")
