# One facade through rules/facade.acr, checked from the outside:
#   cmake -DPROGRAM=<pattern_facade> -DCHECK=<check_facade> -DFACADE=<svg> -DWORK=<dir>
#         [-DARGS=a|b|...] [-DMORTAR=1] [-DCHECK_ARGS=no-sills] -P facade_case.cmake
# Renders with --json, runs check_facade on the tree, and renders again with the same
# --rng-seed: the two SVGs must be byte-identical.
cmake_minimum_required(VERSION 3.20)
foreach(var PROGRAM CHECK FACADE WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "facade_case.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT DEFINED MORTAR)
  set(MORTAR 1)
endif()
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
foreach(run a b)
  execute_process(COMMAND "${PROGRAM}" --region "${FACADE}" --rng-seed 7 --quiet ${args}
      --param cells_mortar=${MORTAR} -o "${WORK}/${run}.svg" --json "${WORK}/${run}.json"
    RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 300)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} failed (${rc}) on ${FACADE}:\n${err}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/a.svg" "${WORK}/b.svg"
  RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the same --rng-seed gave different SVG: ${WORK}/a.svg, ${WORK}/b.svg")
endif()
execute_process(COMMAND "${CHECK}" "${FACADE}" "${WORK}/a.json" "${MORTAR}" ${CHECK_ARGS}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_facade found faults in ${FACADE} (${ARGS}); render: ${WORK}/a.svg")
endif()
