# Builds examples/cmake-consumer against an installed Acanthus (MODE=install, PREFIX=<prefix>)
# or a build tree (MODE=build-tree, ACANTHUS_BUILD=<build dir>), runs the program, then checks
# that the build tracks the rule file and its import through the compiler's depfile: touching
# either regenerates the C++, adding or removing an import is followed, and a rebuild with
# nothing touched does nothing.
#   cmake -DMODE=... -DCONSUMER=<source> -DWORK=<dir> -DGENERATOR=<gen> -DCXX=<compiler>
#         [-DLAUNCHER=<ccache>] [-DLINK_FLAGS=<flags>] [-DRSVG=<rsvg-convert>] -P consumer.cmake
cmake_minimum_required(VERSION 3.20)

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${code}):\n${out}\n${err}")
  endif()
  set(run_output "${out}${err}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK}")
file(COPY "${CONSUMER}/" DESTINATION "${WORK}/src")
set(src "${WORK}/src")
set(build "${WORK}/build")

set(args -S "${src}" -B "${build}" -G "${GENERATOR}" "-DCMAKE_CXX_COMPILER=${CXX}"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo)
if(LAUNCHER)
  list(APPEND args "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
endif()
if(LINK_FLAGS)
  list(APPEND args "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}")
endif()
if(MODE STREQUAL "install")
  list(APPEND args "-DCMAKE_PREFIX_PATH=${PREFIX}")
  set(expected_dir "${PREFIX}")
elseif(MODE STREQUAL "build-tree")
  list(APPEND args "-DAcanthus_DIR=${ACANTHUS_BUILD}")
  set(expected_dir "${ACANTHUS_BUILD}")
else()
  message(FATAL_ERROR "consumer.cmake: MODE must be install or build-tree")
endif()
run("configure" "${CMAKE_COMMAND}" ${args})

# The package must come from where we pointed, nowhere else.
file(STRINGS "${build}/CMakeCache.txt" found_dir REGEX "^Acanthus_DIR:")
string(REGEX REPLACE "^Acanthus_DIR:[A-Z]+=" "" found_dir "${found_dir}")
file(REAL_PATH "${found_dir}" found_dir)
file(REAL_PATH "${expected_dir}" expected_dir)
string(FIND "${found_dir}" "${expected_dir}" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "Acanthus was found in '${found_dir}', not under '${expected_dir}'")
endif()

run("build" "${CMAKE_COMMAND}" --build "${build}")
set(generated "${build}/acanthus_generated/ring.cpp")
if(NOT EXISTS "${generated}")
  message(FATAL_ERROR "the generated source ${generated} is missing")
endif()

run("run ring" "${build}/ring" --region circle:80 --rng-seed 5 -o "${WORK}/ring.svg"
  --json "${WORK}/ring.json")
file(READ "${WORK}/ring.svg" svg)
if(NOT svg MATCHES "<svg")
  message(FATAL_ERROR "ring.svg is not an SVG file")
endif()
file(READ "${WORK}/ring.json" tree)
string(JSON n LENGTH "${tree}" elements)
if(n LESS 20)
  message(FATAL_ERROR "ring grew only ${n} elements")
endif()
if(RSVG)
  run("rsvg-convert reads ring.svg" "${RSVG}" -o "${WORK}/ring.png" "${WORK}/ring.svg")
endif()
message(STATUS "ring: ${n} elements")

# The compiler's depfile (`acanthus compile --depfile`) is what names the import to CMake.
set(depfile "${build}/acanthus_generated/ring.d")
if(NOT EXISTS "${depfile}")
  message(FATAL_ERROR "acanthus_add_pattern wrote no depfile ${depfile}")
endif()
file(READ "${depfile}" deps)
foreach(listed "${src}/ring.acr" "${src}/rules/palette.acr")
  string(FIND "${deps}" "${listed}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the depfile does not list ${listed}:\n${deps}")
  endif()
endforeach()

# Rebuilding with nothing changed must not recompile the rule file.
run("no-op rebuild" "${CMAKE_COMMAND}" --build "${build}")
if(run_output MATCHES "Compiling rule file")
  message(FATAL_ERROR "a rebuild with nothing changed recompiled the rule file:\n${run_output}")
endif()

# Touching the rule file, then its import, must regenerate the C++ each time.
foreach(touched "${src}/ring.acr" "${src}/rules/palette.acr")
  file(TIMESTAMP "${generated}" before "%s")
  execute_process(COMMAND "${CMAKE_COMMAND}" -E sleep 1.1)
  file(TOUCH "${touched}")
  run("rebuild after touching ${touched}" "${CMAKE_COMMAND}" --build "${build}")
  file(TIMESTAMP "${generated}" after "%s")
  if(NOT run_output MATCHES "Compiling rule file" OR after STREQUAL before)
    message(FATAL_ERROR "touching ${touched} did not regenerate ${generated}:\n${run_output}")
  endif()
endforeach()

# A new %import line is picked up without re-running CMake (the build-time depfile).
file(WRITE "${src}/rules/extra.acr" "// imported only to test dependency tracking\n")
file(APPEND "${src}/rules/palette.acr" "%import \"extra\"\n")
run("rebuild after adding an import" "${CMAKE_COMMAND}" --build "${build}")
execute_process(COMMAND "${CMAKE_COMMAND}" -E sleep 1.1)
file(TOUCH "${src}/rules/extra.acr")
run("rebuild after touching the new import" "${CMAKE_COMMAND}" --build "${build}")
if(NOT run_output MATCHES "Compiling rule file")
  message(FATAL_ERROR "touching a newly added import did not regenerate:\n${run_output}")
endif()

# An import removed with its %import line: the build follows the new list, no stale rule.
file(READ "${src}/rules/palette.acr" palette)
string(REPLACE "%import \"extra\"\n" "" palette "${palette}")
file(WRITE "${src}/rules/palette.acr" "${palette}")
file(REMOVE "${src}/rules/extra.acr")
run("rebuild after removing an import" "${CMAKE_COMMAND}" --build "${build}")
if(NOT run_output MATCHES "Compiling rule file")
  message(FATAL_ERROR "removing an import did not regenerate:\n${run_output}")
endif()
# CMake's Makefile generator (3.25) keeps every path a custom command's depfile ever named, so
# there a removed import regenerates the C++ on each build; Ninja takes the new list.
if(GENERATOR STREQUAL "Ninja")
  run("no-op rebuild after removing an import" "${CMAKE_COMMAND}" --build "${build}")
  if(run_output MATCHES "Compiling rule file")
    message(FATAL_ERROR "a rebuild with nothing changed recompiled the rule file:\n${run_output}")
  endif()
endif()
message(STATUS "rebuilds track the rule file and its imports (${GENERATOR})")
