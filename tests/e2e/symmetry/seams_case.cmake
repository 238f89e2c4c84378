# One wallpaper tile grown and checked across its seams:
#   cmake -DPROGRAM=<exe> -DCHECK=<check_seams> -DGROUP=<p4m> -DTILE=<W,H[,ANGLE]> -DWORK=<dir>
#         [-DSEED=<rng seed, 1 by default>] -P seams_case.cmake
cmake_minimum_required(VERSION 3.20)
if(NOT DEFINED SEED)
  set(SEED 1)
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${PROGRAM}" --wallpaper ${GROUP} --tile ${TILE} --rng-seed ${SEED} --quiet
    --json tree.json -o tile.png
  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE code ERROR_VARIABLE err TIMEOUT 300)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the program failed (exit ${code}):\n${err}")
endif()
execute_process(COMMAND "${CHECK}" tree.json ${TILE} --sites WORKING_DIRECTORY "${WORK}"
  RESULT_VARIABLE code OUTPUT_VARIABLE out TIMEOUT 300)
message(STATUS "${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "check_seams found faults")
endif()
