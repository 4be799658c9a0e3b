# The Self-Choreographic Network reads its sensor stream from stdin as it
# does from a file (thesis 6.5: the interface a sensor, a socket or a robot
# uses): the same readings give the same model, bit for bit.
cmake_minimum_required(VERSION 3.20)
set(scene ${SOURCE}/scripts/case-studies/self-choreographic-networks.lua)
set(readings ${SOURCE}/scripts/case-studies/data/self-choreographic-networks.txt)
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${TENDRIL} run ${scene} --quiet --out ${WORK}/file RESULT_VARIABLE rc_file OUTPUT_VARIABLE out_file)
execute_process(COMMAND ${TENDRIL} run ${scene} --quiet --param input=- --out ${WORK}/stdin
                INPUT_FILE ${readings} RESULT_VARIABLE rc_stdin OUTPUT_VARIABLE out_stdin ERROR_VARIABLE err_stdin)
if(NOT rc_file EQUAL 0 OR NOT rc_stdin EQUAL 0)
  message(FATAL_ERROR "the scene failed (file: ${rc_file}, stdin: ${rc_stdin}):\n${out_stdin}${err_stdin}")
endif()
if(NOT out_stdin MATCHES "readings \\| 91 \\| — \\| from stdin")
  message(FATAL_ERROR "the stdin run did not read the 91 readings from stdin:\n${out_stdin}")
endif()
file(READ ${WORK}/file/scn.xml a)
file(READ ${WORK}/stdin/scn.xml b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "the readings from stdin and from the file gave different models")
endif()
message(STATUS "91 readings from stdin: the same model as from the file")
