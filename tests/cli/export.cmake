cmake_minimum_required(VERSION 3.20)
# `tendril export` of a saved model (the CLI scene, a 1 kg mass hung from two
# pins, saved converged by --save): VTK, OBJ and PLY written, the VTK's
# reactions those of the saved state (each pin holds 9.81 / 2 N up) without
# a step, the OBJ grouped per block.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${TENDRIL} run ${SAVER} --quiet --out ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tendril run ${SAVER}: exit status ${rc}\n${out}${err}")
endif()
execute_process(COMMAND ${TENDRIL} export ${WORK}/model.xml --vtk ${WORK}/model.vtk --obj ${WORK}/model.obj
                        --ply ${WORK}/model.ply
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "3 particles, 2 blocks -> .*model.ply")
  message(FATAL_ERROR "tendril export: exit status ${rc}\n${out}${err}")
endif()
file(READ ${WORK}/model.vtk vtk)
string(REGEX MATCH "VECTORS reaction double\n[^\n]*\n" first "${vtk}")
if(NOT first MATCHES " -?0 4\\.90(49|50)[0-9]*\n$")
  message(FATAL_ERROR "the first pin's reaction is not (H, 0, 4.905):\n${first}")
endif()
file(READ ${WORK}/model.obj obj)
if(NOT obj MATCHES "^# tendril model; units: m\n" OR NOT obj MATCHES "\ng cable-0\nl 1 3\ng cable-1\nl 2 3\n")
  message(FATAL_ERROR "model.obj:\n${obj}")
endif()
file(READ ${WORK}/model.ply ply)
if(NOT ply MATCHES "^ply\nformat ascii 1.0\n.*element edge 2\n")
  message(FATAL_ERROR "model.ply:\n${ply}")
endif()
message(STATUS "export: VTK reactions, OBJ groups, PLY edges")
