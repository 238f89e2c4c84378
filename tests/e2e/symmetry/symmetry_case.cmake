# One pattern grown under a symmetry group, checked from the outside:
#   cmake -DPROGRAM=<pattern> -DCHECK=<check_symmetry> -DREGION=<spec|svg> -DGROUP=d8
#         -DWORK=<dir> [-DARGS=a|b|...] [-DGROUP_ARGS=--frieze|p2|--period|40] -P symmetry_case.cmake
# GROUP is what check_symmetry takes (d8, frieze:p2:40, wallpaper:p4m:100,100); GROUP_ARGS the
# program's options for it (default --symmetry GROUP). REGION - grows in the wallpaper's tile.
# Grows with --json twice with the same --rng-seed (the trees must be byte-identical), then runs
# check_symmetry on the tree.
cmake_minimum_required(VERSION 3.20)
foreach(var PROGRAM CHECK REGION GROUP WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "symmetry_case.cmake: -D${var}=... is required")
  endif()
endforeach()
string(REPLACE "|" ";" args "${ARGS}")
if(DEFINED GROUP_ARGS AND NOT GROUP_ARGS STREQUAL "")
  string(REPLACE "|" ";" group_args "${GROUP_ARGS}")
else()
  set(group_args --symmetry ${GROUP})
endif()
set(region_args --region "${REGION}")
if(REGION STREQUAL "-")
  set(region_args "")
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
foreach(run a b)
  execute_process(COMMAND "${PROGRAM}" ${region_args} ${group_args} --rng-seed 3
      --resolution 256 --quiet ${args} -o "${WORK}/${run}.svg" --json "${WORK}/${run}.json"
    RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 300)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} failed (${rc}) under ${GROUP} on ${REGION}:\n${err}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/a.json" "${WORK}/b.json"
  RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the same --rng-seed gave different trees: ${WORK}/a.json, ${WORK}/b.json")
endif()
execute_process(COMMAND "${CHECK}" "${WORK}/a.json" ${GROUP} "${REGION}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_symmetry found faults under ${GROUP} on ${REGION}; render: ${WORK}/a.svg")
endif()
