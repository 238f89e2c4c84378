# `acanthus build` and `acanthus run` from an install prefix only: a rule file that imports the
# installed stdlib (dartfill) builds and runs, and `run` builds into its cache and runs.
#   cmake -DPREFIX=<prefix> -DSOURCE=<source dir> -DWORK=<dir> -P installed_driver.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(acanthus "${PREFIX}/bin/acanthus")
function(check what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
endfunction()
# Copy the rule file away from the source tree so nothing but the prefix can resolve imports.
file(COPY "${SOURCE}/rules/pebbles.acr" "${SOURCE}/rules/dots.acr" DESTINATION "${WORK}")
check("acanthus build (installed)" "${acanthus}" build "${WORK}/pebbles.acr" -o "${WORK}/pebbles")
check("pebbles" "${WORK}/pebbles" --region circle:40 --quiet -o "${WORK}/pebbles.svg")
check("acanthus run (installed)" ${CMAKE_COMMAND} -E env "ACANTHUS_CACHE_DIR=${WORK}/cache"
  "${acanthus}" run "${WORK}/dots.acr" --region rect:60,40 --quiet -o "${WORK}/dots.svg")
foreach(f pebbles.svg dots.svg)
  file(READ "${WORK}/${f}" svg LIMIT 200)
  if(NOT svg MATCHES "<svg")
    message(FATAL_ERROR "${f} is not an SVG")
  endif()
endforeach()
message(STATUS "installed acanthus build and run work")
