# doc/parameters.prm must be what 'pg_solve --print-parameters' prints: the
# documented reference of every entry stays the program's. Run by the test
# pg_solve/parameters_prm_up_to_date with -DPG_SOLVE=<pg_solve>
# -DREFERENCE=<doc/parameters.prm>.
execute_process(COMMAND ${PG_SOLVE} --print-parameters
                RESULT_VARIABLE code
                OUTPUT_VARIABLE printed)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "pg_solve --print-parameters returned <${code}>.")
endif()
file(READ ${REFERENCE} reference)
if(NOT printed STREQUAL reference)
  message(FATAL_ERROR
    "${REFERENCE} differs from what 'pg_solve --print-parameters' prints. "
    "After changing a parameter or its documentation, regenerate it from "
    "the repository root: "
    "build/applications/pg_solve/pg_solve --print-parameters > "
    "doc/parameters.prm")
endif()
