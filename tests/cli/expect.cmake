cmake_minimum_required(VERSION 3.20)
# Runs `${TENDRIL} ${ARGS}` (ARGS a ;-list) and requires exit status ${STATUS}
# and, when MATCH is given, that stdout+stderr match the regular expression.
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${TENDRIL} ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                WORKING_DIRECTORY ${WORK})
if(NOT rc STREQUAL STATUS)
  message(FATAL_ERROR "tendril ${ARGS}: exit status ${rc}, expected ${STATUS}\n${out}${err}")
endif()
if(DEFINED MATCH AND NOT "${out}${err}" MATCHES "${MATCH}")
  message(FATAL_ERROR "tendril ${ARGS}: the output does not match '${MATCH}':\n${out}${err}")
endif()
