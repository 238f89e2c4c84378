# pkg-config for Make users: compiles a rule file with the installed compiler, then compiles
# and links the C++ with exactly `pkg-config --cflags --libs acanthus`, and runs the program.
#   cmake -DPREFIX=<prefix> -DCONSUMER=<examples/cmake-consumer> -DWORK=<dir> -DCXX=<compiler>
#         [-DLINK_FLAGS=<flags>] -P pkg_config.cmake
cmake_minimum_required(VERSION 3.20)
find_program(PKG_CONFIG NAMES pkg-config REQUIRED)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

file(GLOB_RECURSE pc "${PREFIX}/*/pkgconfig/acanthus.pc")
list(GET pc 0 pc)
get_filename_component(pc_dir "${pc}" DIRECTORY)

function(run what)
  execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PKG_CONFIG_PATH=${pc_dir}" ${ARGN}
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${code}):\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

run("pkg-config --cflags --libs acanthus" "${PKG_CONFIG}" --cflags --libs acanthus)
set(flags "${run_output}")
message(STATUS "pkg-config --cflags --libs acanthus: ${flags}")
separate_arguments(flags UNIX_COMMAND "${flags}")

run("pkg-config --variable=acanthus" "${PKG_CONFIG}" --variable=acanthus acanthus)
set(compiler "${run_output}")
run("pkg-config --variable=stdlibdir" "${PKG_CONFIG}" --variable=stdlibdir acanthus)
if(NOT IS_DIRECTORY "${run_output}")
  message(FATAL_ERROR "stdlibdir '${run_output}' is not a directory")
endif()

run("acanthus compile" "${compiler}" compile "${CONSUMER}/ring.acr" -o "${WORK}/ring.cpp"
  -I "${CONSUMER}/rules")
separate_arguments(link_flags UNIX_COMMAND "${LINK_FLAGS}")
run("c++ with pkg-config flags" "${CXX}" -std=c++20 "${WORK}/ring.cpp" -o "${WORK}/ring" ${flags}
  ${link_flags})
run("run ring" "${WORK}/ring" --region rect:160,100 -o "${WORK}/ring.svg")
file(READ "${WORK}/ring.svg" svg)
if(NOT svg MATCHES "<svg")
  message(FATAL_ERROR "ring.svg is not an SVG file")
endif()
