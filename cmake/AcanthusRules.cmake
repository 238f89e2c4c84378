# acanthus_add_pattern(NAME RULES file.acr [IMPORT_DIRS dir...] [LIBRARIES lib...])
#
# Compiles a rule file to C++ with `acanthus compile` and builds it into the executable NAME,
# linked with Acanthus::stdlib, Acanthus::runtime and LIBRARIES. The compile
# step depends on the rule file, every rule file it imports (found in IMPORT_DIRS, then the
# stdlib directory) and the compiler, so editing any of them regenerates the program. The
# imports are the compiler's own list (`acanthus compile --depfile`): CMake never parses
# %import lines itself.
#
# Used inside the Acanthus tree and, installed next to AcanthusConfig.cmake, by
# find_package(Acanthus CONFIG). Needs ACANTHUS_STDLIB_DIR (the directory of the stdlib's rule
# files: in the tree, the one the stdlib registry names) set before it is included.
include_guard(GLOBAL)

set_property(GLOBAL PROPERTY ACANTHUS_STDLIB_DIR "${ACANTHUS_STDLIB_DIR}")

# Functions keep the policies in effect where they are defined: DEPFILE paths are then handled
# the same way by Ninja and Makefiles (CMP0116), whatever the calling project requires.
cmake_policy(PUSH)
cmake_policy(VERSION 3.20...3.28)

function(acanthus_add_pattern name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "RULES" "IMPORT_DIRS;LIBRARIES")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "acanthus_add_pattern(${name}): unexpected arguments: "
      "${ARG_UNPARSED_ARGUMENTS} (use RULES file.acr [IMPORT_DIRS dir...] [LIBRARIES lib...])")
  endif()
  if(NOT ARG_RULES)
    message(FATAL_ERROR "acanthus_add_pattern(${name}): RULES file.acr is required")
  endif()
  get_filename_component(rules "${ARG_RULES}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT EXISTS "${rules}")
    message(FATAL_ERROR "acanthus_add_pattern(${name}): rule file '${rules}' does not exist")
  endif()

  get_property(stdlib_dir GLOBAL PROPERTY ACANTHUS_STDLIB_DIR)
  set(import_dirs "")
  foreach(dir IN LISTS ARG_IMPORT_DIRS)
    get_filename_component(dir "${dir}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND import_dirs "${dir}")
  endforeach()
  if(stdlib_dir AND NOT stdlib_dir IN_LIST import_dirs)
    list(APPEND import_dirs "${stdlib_dir}")
  endif()
  set(import_flags "")
  foreach(dir IN LISTS import_dirs)
    list(APPEND import_flags -I "${dir}")
  endforeach()

  set(gen_dir "${CMAKE_CURRENT_BINARY_DIR}/acanthus_generated")
  set(generated "${gen_dir}/${name}.cpp")
  set(depfile "${gen_dir}/${name}.d")
  file(RELATIVE_PATH shown "${CMAKE_BINARY_DIR}" "${generated}")

  if(TARGET Acanthus::acanthus)
    add_custom_command(OUTPUT "${generated}"
      COMMAND "${CMAKE_COMMAND}" -E make_directory "${gen_dir}"
      COMMAND Acanthus::acanthus compile "${rules}" -o "${generated}" --depfile "${depfile}"
              ${import_flags}
      # The first build needs no import list (the output is missing); every later one reads
      # the list the compiler wrote, so a new %import line is tracked without re-running CMake.
      DEPENDS "${rules}" Acanthus::acanthus
      DEPFILE "${depfile}"
      COMMENT "Compiling rule file ${ARG_RULES} to ${shown}"
      VERBATIM)
  else()
    # No compiler yet (inside the tree before compiler/ defines it): configure anyway, and say
    # why when someone builds this pattern.
    add_custom_command(OUTPUT "${generated}"
      COMMAND "${CMAKE_COMMAND}" -E echo
              "acanthus_add_pattern(${name}): the acanthus compiler target does not exist"
      COMMAND "${CMAKE_COMMAND}" -E false
      DEPENDS "${rules}"
      VERBATIM)
  endif()

  add_executable(${name} "${generated}")
  target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES} Acanthus::stdlib Acanthus::runtime)
  set_property(TARGET ${name} PROPERTY ACANTHUS_RULES "${rules}")
  set_property(TARGET ${name} PROPERTY ACANTHUS_GENERATED_SOURCE "${generated}")
endfunction()

cmake_policy(POP)
