# Build-time half of acanthus_add_pattern: writes a Makefile-syntax depfile naming the rule file
# and everything it imports, so that a new %import line is tracked without re-running CMake.
#   cmake -DRULES=<file.acr> -DOUTPUT=<generated.cpp> -DDEPFILE=<file.d> "-DDIRS=<dir|dir...>"
#         -P AcanthusScanImports.cmake
cmake_minimum_required(VERSION 3.20)
include("${CMAKE_CURRENT_LIST_DIR}/AcanthusImports.cmake")

foreach(var RULES OUTPUT DEPFILE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "AcanthusScanImports.cmake: -D${var}=... is required")
  endif()
endforeach()

string(REPLACE "|" ";" DIRS "${DIRS}")
_acanthus_find_imports("${RULES}" imports DIRS ${DIRS})
function(_acanthus_make_escape path out_var)
  string(REPLACE "\\" "\\\\" path "${path}")
  string(REPLACE " " "\\ " path "${path}")
  string(REPLACE "#" "\\#" path "${path}")
  string(REPLACE "$" "$$" path "${path}")
  set(${out_var} "${path}" PARENT_SCOPE)
endfunction()
_acanthus_make_escape("${OUTPUT}" target)
set(text "${target}:")
foreach(dep IN ITEMS "${RULES}" LISTS imports)
  _acanthus_make_escape("${dep}" dep)
  string(APPEND text " \\\n  ${dep}")
endforeach()
file(WRITE "${DEPFILE}" "${text}\n")
