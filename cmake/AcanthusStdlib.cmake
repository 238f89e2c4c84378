# The registry of built-in rule libraries: acanthus_stdlib_library() records each library once
# (sources, public include dir, rule file, dependencies, tests) in global properties; the stdlib
# archive, the compiler's toolchain, the package, pkg-config and tests/stdlib read it from there.
# How to add a library: docs/stdlib/README.md.
include_guard(GLOBAL)

# acanthus_stdlib_dependency(NAME name TARGET target [PACKAGE package [VERSION version]]
#                            [PKG_CONFIG module...] [HEADER_ONLY] [RUNTIME])
#
# An external package that libraries may name in DEPENDS: the imported TARGET they build with
# (found now with find_package(PACKAGE) unless it exists; a macro, so that the target is seen
# where it is declared and below), and what a consumer of libacanthus_stdlib.a links (PACKAGE
# for find_dependency, pkg-config modules). HEADER_ONLY packages reach no consumer. RUNTIME:
# libacanthus.a itself uses it, so the runtime links it, `acanthus build` links its modules,
# acanthus.pc requires them and AcanthusConfig.cmake finds it (acanthus_stdlib_get RUNTIME_*).
macro(acanthus_stdlib_dependency)
  cmake_parse_arguments(_acanthus_dep "HEADER_ONLY;RUNTIME" "NAME;TARGET;PACKAGE;VERSION"
    "PKG_CONFIG" ${ARGN})
  if(NOT _acanthus_dep_NAME OR NOT _acanthus_dep_TARGET OR _acanthus_dep_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "acanthus_stdlib_dependency: use NAME name TARGET target [PACKAGE p "
      "[VERSION v]] [PKG_CONFIG module...] [HEADER_ONLY] [RUNTIME]")
  endif()
  if(NOT TARGET ${_acanthus_dep_TARGET} AND _acanthus_dep_PACKAGE)
    find_package(${_acanthus_dep_PACKAGE} ${_acanthus_dep_VERSION} REQUIRED)
  endif()
  if(NOT TARGET ${_acanthus_dep_TARGET})
    message(FATAL_ERROR "acanthus_stdlib_dependency(${_acanthus_dep_NAME}): no target "
      "${_acanthus_dep_TARGET}")
  endif()
  set_property(GLOBAL APPEND PROPERTY ACANTHUS_STDLIB_DEPENDENCIES "${_acanthus_dep_NAME}")
  if(_acanthus_dep_RUNTIME)
    set_property(GLOBAL APPEND PROPERTY ACANTHUS_RUNTIME_DEPENDENCIES "${_acanthus_dep_NAME}")
  endif()
  foreach(_acanthus_field TARGET PACKAGE PKG_CONFIG HEADER_ONLY)
    set_property(GLOBAL PROPERTY ACANTHUS_STDLIB_DEP_${_acanthus_dep_NAME}_${_acanthus_field}
      "${_acanthus_dep_${_acanthus_field}}")
  endforeach()
endmacro()

# The runtime's own dependencies (RUNTIME; the only list of them: found by the top-level
# CMakeLists.txt, which includes this file before runtime/), and what only the stdlib uses.
acanthus_stdlib_dependency(NAME Cairo TARGET PkgConfig::CAIRO PKG_CONFIG cairo RUNTIME)
acanthus_stdlib_dependency(NAME libpng TARGET PkgConfig::LIBPNG PKG_CONFIG libpng RUNTIME)
# lib2geom's headers call GLib, GSL and double-conversion, which 2geom.pc does not require.
acanthus_stdlib_dependency(NAME 2Geom TARGET 2Geom::2geom PACKAGE 2Geom
  PKG_CONFIG 2geom glib-2.0 gsl double-conversion RUNTIME)
acanthus_stdlib_dependency(NAME pugixml TARGET pugixml::pugixml PACKAGE pugixml PKG_CONFIG pugixml
  RUNTIME)
acanthus_stdlib_dependency(NAME Clipper TARGET PkgConfig::POLYCLIPPING PKG_CONFIG polyclipping
  RUNTIME)
acanthus_stdlib_dependency(NAME Boost TARGET Boost::headers HEADER_ONLY RUNTIME)
acanthus_stdlib_dependency(NAME nlohmann_json TARGET nlohmann_json::nlohmann_json HEADER_ONLY
  RUNTIME)
acanthus_stdlib_dependency(NAME CGAL TARGET CGAL::CGAL PACKAGE CGAL VERSION 5.5
  PKG_CONFIG mpfr gmp)  # header-only, but its exact arithmetic links GMP and MPFR
acanthus_stdlib_dependency(NAME Eigen3 TARGET Eigen3::Eigen HEADER_ONLY)

# acanthus_stdlib_library(NAME name SOURCES file.cpp... [DEPENDS dep...] [TESTS file.cpp...]
#                         [TEST_DEPENDS dep...] [INTERNAL])
#
# Called from stdlib/<name>/CMakeLists.txt. A public library has its rule file stdlib/<name>.acr
# and its header stdlib/<name>/include/acanthus/stdlib/<name>.hpp; an INTERNAL one (common/) has
# neither and is shared by other libraries, which include it as "<name>/file.hpp". DEPENDS names
# other stdlib libraries and dependencies declared with acanthus_stdlib_dependency(). TESTS are
# GoogleTest files in tests/stdlib/<name>/, built with the library's own include directories
# and TEST_DEPENDS (what only the tests use).
function(acanthus_stdlib_library)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "INTERNAL" "NAME" "SOURCES;DEPENDS;TESTS;TEST_DEPENDS")
  set(usage "use NAME name SOURCES file.cpp... [DEPENDS dep...] [TESTS file.cpp...] "
    "[TEST_DEPENDS dep...] [INTERNAL]")
  if(ARG_UNPARSED_ARGUMENTS OR NOT ARG_NAME OR NOT ARG_SOURCES)
    message(FATAL_ERROR "acanthus_stdlib_library(${ARG_NAME}): ${usage}")
  endif()
  set(name "${ARG_NAME}")
  set(dir "${CMAKE_CURRENT_SOURCE_DIR}")
  get_filename_component(folder "${dir}" NAME)
  get_filename_component(rule_dir "${dir}" DIRECTORY)
  if(NOT folder STREQUAL name OR NOT name MATCHES "^[a-z][a-z0-9_]*$")
    message(FATAL_ERROR "acanthus_stdlib_library(${name}): the name must be lower case and the "
      "folder's (stdlib/${name}/), here ${dir}")
  endif()
  get_property(known GLOBAL PROPERTY ACANTHUS_STDLIB_LIBRARIES)
  if(name IN_LIST known)
    message(FATAL_ERROR "acanthus_stdlib_library(${name}): registered twice")
  endif()

  set(sources "")
  foreach(source IN LISTS ARG_SOURCES)
    get_filename_component(source "${source}" ABSOLUTE BASE_DIR "${dir}")
    list(APPEND sources "${source}")
  endforeach()
  set(tests "")
  foreach(test IN LISTS ARG_TESTS)
    get_filename_component(test "${test}" ABSOLUTE
      BASE_DIR "${PROJECT_SOURCE_DIR}/tests/stdlib/${name}")
    list(APPEND tests "${test}")
  endforeach()

  set(target acanthus_stdlib_${name})
  add_library(${target} OBJECT ${sources})
  target_link_libraries(${target} PUBLIC acanthus_runtime)
  target_include_directories(${target} PRIVATE "${dir}" "${PROJECT_SOURCE_DIR}/runtime/src")
  if(ARG_INTERNAL)
    set(include_dir "")
    set(rules "")
    target_include_directories(${target} INTERFACE "${rule_dir}")
  else()
    set(include_dir "${dir}/include")
    set(rules "${rule_dir}/${name}.acr")
    foreach(file "${include_dir}/acanthus/stdlib/${name}.hpp" "${rules}")
      if(NOT EXISTS "${file}")
        message(FATAL_ERROR "acanthus_stdlib_library(${name}): ${file} is missing")
      endif()
    endforeach()
    target_include_directories(${target} PUBLIC "${include_dir}")
  endif()
  foreach(dep IN LISTS ARG_DEPENDS)
    _acanthus_stdlib_dependency_target("${name}" "${dep}" dep_target)
    target_link_libraries(${target} PRIVATE ${dep_target})
  endforeach()
  acanthus_warnings(${target})

  set_property(GLOBAL APPEND PROPERTY ACANTHUS_STDLIB_LIBRARIES "${name}")
  foreach(field dir sources include_dir rules tests target)
    string(TOUPPER "${field}" key)
    set_property(GLOBAL PROPERTY ACANTHUS_STDLIB_${name}_${key} "${${field}}")
  endforeach()
  set_property(GLOBAL PROPERTY ACANTHUS_STDLIB_${name}_DEPENDS "${ARG_DEPENDS}")
  set_property(GLOBAL PROPERTY ACANTHUS_STDLIB_${name}_TEST_DEPENDS "${ARG_TEST_DEPENDS}")
  set_property(GLOBAL PROPERTY ACANTHUS_STDLIB_RULE_DIR "${rule_dir}")
endfunction()

# acanthus_stdlib_preview_strokes(NAME name KINDS kind... FILE_PARAM param [WIDTH_KINDS kind...]
#   [MODE_PARAM param MODE_KINDS kind...]): strokes `acanthus preview` lets the user draw for a
# program that imports the library: saved as an SVG of polylines whose class is the kind (a
# WIDTH_KINDS stroke's stroke-width is its brush diameter), the file named by FILE_PARAM; while a
# MODE_KINDS stroke is drawn, MODE_PARAM is set to its kind. Read back with
# acanthus_stdlib_get(PREVIEW_STROKES): one JSON object per library.
function(acanthus_stdlib_preview_strokes)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "" "NAME;FILE_PARAM;MODE_PARAM"
    "KINDS;WIDTH_KINDS;MODE_KINDS")
  set(what "acanthus_stdlib_preview_strokes(${ARG_NAME})")
  get_property(known GLOBAL PROPERTY ACANTHUS_STDLIB_LIBRARIES)
  if(ARG_UNPARSED_ARGUMENTS OR NOT ARG_NAME IN_LIST known OR NOT ARG_KINDS OR NOT ARG_FILE_PARAM
     OR (ARG_MODE_PARAM AND NOT ARG_MODE_KINDS) OR (ARG_MODE_KINDS AND NOT ARG_MODE_PARAM))
    message(FATAL_ERROR "${what}: use NAME registered-library KINDS kind... FILE_PARAM param "
      "[WIDTH_KINDS kind...] [MODE_PARAM param MODE_KINDS kind...]")
  endif()
  foreach(kind IN LISTS ARG_KINDS ARG_WIDTH_KINDS ARG_MODE_KINDS)
    if(NOT kind MATCHES "^[a-z][a-z0-9_]*$" OR NOT kind IN_LIST ARG_KINDS)
      message(FATAL_ERROR "${what}: '${kind}' is not one of KINDS (lower-case names)")
    endif()
  endforeach()
  # The parameters must be the library's own: declared in its rule file.
  get_property(rules GLOBAL PROPERTY ACANTHUS_STDLIB_${ARG_NAME}_RULES)
  file(READ "${rules}" rule_text)
  foreach(param IN LISTS ARG_FILE_PARAM ARG_MODE_PARAM)
    if(NOT rule_text MATCHES "\n%param [a-z:]+ ${param} ")
      message(FATAL_ERROR "${what}: ${rules} declares no %param ${param}")
    endif()
  endforeach()
  set(json "{\"library\": \"${ARG_NAME}\", \"file_param\": \"${ARG_FILE_PARAM}\"")
  string(APPEND json ", \"mode_param\": \"${ARG_MODE_PARAM}\"")
  foreach(field kinds width_kinds mode_kinds)
    string(TOUPPER "${field}" key)
    list(JOIN ARG_${key} "\", \"" items)
    if(items STREQUAL "")
      string(APPEND json ", \"${field}\": []")
    else()
      string(APPEND json ", \"${field}\": [\"${items}\"]")
    endif()
  endforeach()
  string(APPEND json "}")
  set_property(GLOBAL APPEND PROPERTY ACANTHUS_STDLIB_PREVIEW_STROKES "${json}")
endfunction()

# acanthus_stdlib_property(<out-var> <library> <field>): one recorded field of a library: DIR,
# SOURCES, INCLUDE_DIR, RULES, TESTS, TARGET, DEPENDS or TEST_DEPENDS.
function(acanthus_stdlib_property out_var name field)
  get_property(known GLOBAL PROPERTY ACANTHUS_STDLIB_LIBRARIES)
  if(NOT name IN_LIST known)
    message(FATAL_ERROR "acanthus_stdlib_property: no stdlib library '${name}'")
  endif()
  get_property(value GLOBAL PROPERTY ACANTHUS_STDLIB_${name}_${field})
  set(${out_var} "${value}" PARENT_SCOPE)
endfunction()

# acanthus_stdlib_get(<out-var> <what>), over all registered libraries:
#   LIBRARIES      names, in the order registered     RULE_DIR      where the rule files are
#   INCLUDE_DIRS   public include directories          RULE_FILES    the rule files
#   PACKAGES       CMake packages a consumer of libacanthus_stdlib.a finds (find_dependency)
#   LINK_TARGETS   the imported targets libacanthus_stdlib.a links
#   PKG_CONFIG     the pkg-config modules it links
#   PREVIEW_STROKES  the stroke tools libraries declare for the preview (JSON objects)
# and over the runtime's dependencies (declared RUNTIME):
#   RUNTIME_LINK_TARGETS   imported targets libacanthus.a links (not header-only)
#   RUNTIME_HEADER_ONLY    header-only targets it compiles with
#   RUNTIME_PKG_CONFIG     pkg-config modules a program linking libacanthus.a needs
#   RUNTIME_PACKAGES       CMake packages AcanthusConfig.cmake finds for it
#   RUNTIME_PKG_TARGETS    PREFIX=module[,module]... for each PkgConfig::PREFIX target it links
function(acanthus_stdlib_get out_var what)
  get_property(names GLOBAL PROPERTY ACANTHUS_STDLIB_LIBRARIES)
  set(result "")
  if(what MATCHES "^RUNTIME_")
    get_property(runtime_deps GLOBAL PROPERTY ACANTHUS_RUNTIME_DEPENDENCIES)
    foreach(dep IN LISTS runtime_deps)
      foreach(field TARGET PACKAGE PKG_CONFIG HEADER_ONLY)
        get_property(dep_${field} GLOBAL PROPERTY ACANTHUS_STDLIB_DEP_${dep}_${field})
      endforeach()
      if(what STREQUAL "RUNTIME_HEADER_ONLY")
        if(dep_HEADER_ONLY)
          list(APPEND result ${dep_TARGET})
        endif()
      elseif(dep_HEADER_ONLY)
        continue()
      elseif(what STREQUAL "RUNTIME_LINK_TARGETS")
        list(APPEND result ${dep_TARGET})
      elseif(what STREQUAL "RUNTIME_PKG_CONFIG")
        list(APPEND result ${dep_PKG_CONFIG})
      elseif(what STREQUAL "RUNTIME_PACKAGES")
        list(APPEND result ${dep_PACKAGE})
      elseif(what STREQUAL "RUNTIME_PKG_TARGETS")
        if(dep_TARGET MATCHES "^PkgConfig::(.+)$")
          list(JOIN dep_PKG_CONFIG "," modules)
          list(APPEND result "${CMAKE_MATCH_1}=${modules}")
        endif()
      else()
        message(FATAL_ERROR "acanthus_stdlib_get: unknown field '${what}'")
      endif()
    endforeach()
  elseif(what STREQUAL "LIBRARIES")
    set(result "${names}")
  elseif(what STREQUAL "PREVIEW_STROKES")
    get_property(result GLOBAL PROPERTY ACANTHUS_STDLIB_PREVIEW_STROKES)
  elseif(what STREQUAL "RULE_DIR")
    get_property(result GLOBAL PROPERTY ACANTHUS_STDLIB_RULE_DIR)
  elseif(what STREQUAL "INCLUDE_DIRS" OR what STREQUAL "RULE_FILES")
    if(what STREQUAL "INCLUDE_DIRS")
      set(field INCLUDE_DIR)
    else()
      set(field RULES)
    endif()
    foreach(name IN LISTS names)
      get_property(value GLOBAL PROPERTY ACANTHUS_STDLIB_${name}_${field})
      list(APPEND result ${value})
    endforeach()
  elseif(what MATCHES "^(PACKAGES|LINK_TARGETS|PKG_CONFIG)$")
    set(field "${what}")
    if(what STREQUAL "PACKAGES")
      set(field PACKAGE)
    elseif(what STREQUAL "LINK_TARGETS")
      set(field TARGET)
    endif()
    get_property(declared GLOBAL PROPERTY ACANTHUS_STDLIB_DEPENDENCIES)
    foreach(name IN LISTS names)
      get_property(deps GLOBAL PROPERTY ACANTHUS_STDLIB_${name}_DEPENDS)
      foreach(dep IN LISTS deps)
        if(NOT dep IN_LIST declared)
          continue()  # another stdlib library: its own dependencies are in this loop too
        endif()
        get_property(header_only GLOBAL PROPERTY ACANTHUS_STDLIB_DEP_${dep}_HEADER_ONLY)
        if(NOT header_only)
          get_property(value GLOBAL PROPERTY ACANTHUS_STDLIB_DEP_${dep}_${field})
          list(APPEND result ${value})
        endif()
      endforeach()
    endforeach()
  else()
    message(FATAL_ERROR "acanthus_stdlib_get: unknown field '${what}'")
  endif()
  list(REMOVE_DUPLICATES result)
  set(${out_var} "${result}" PARENT_SCOPE)
endfunction()

# acanthus_stdlib_use(<target> <dep>...): DEPENDS entries for a target outside the archive (a
# test): a stdlib library's include directories, a declared dependency's imported target.
function(acanthus_stdlib_use target)
  foreach(dep IN LISTS ARGN)
    _acanthus_stdlib_dependency_target("${target}" "${dep}" dep_target)
    if(dep_target STREQUAL "acanthus_stdlib_${dep}")  # objects are in the archive already
      target_include_directories(${target} PRIVATE
        $<TARGET_PROPERTY:${dep_target},INTERFACE_INCLUDE_DIRECTORIES>)
    else()
      target_link_libraries(${target} PRIVATE ${dep_target})
    endif()
  endforeach()
endfunction()

# acanthus_stdlib_archive(): libacanthus_stdlib.a (target acanthus_stdlib, Acanthus::stdlib)
# from every registered library; called once, after the libraries' add_subdirectory lines.
function(acanthus_stdlib_archive)
  acanthus_stdlib_get(names LIBRARIES)
  add_library(acanthus_stdlib STATIC)
  add_library(Acanthus::stdlib ALIAS acanthus_stdlib)
  set_target_properties(acanthus_stdlib PROPERTIES OUTPUT_NAME acanthus_stdlib EXPORT_NAME stdlib
    LINKER_LANGUAGE CXX)
  foreach(name IN LISTS names)
    target_sources(acanthus_stdlib PRIVATE $<TARGET_OBJECTS:acanthus_stdlib_${name}>)
  endforeach()
  acanthus_stdlib_get(include_dirs INCLUDE_DIRS)
  foreach(dir IN LISTS include_dirs)
    target_include_directories(acanthus_stdlib PUBLIC $<BUILD_INTERFACE:${dir}>)
  endforeach()
  target_include_directories(acanthus_stdlib PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # A static archive's link dependencies reach its consumers (exported as $<LINK_ONLY:...>).
  acanthus_stdlib_get(link_targets LINK_TARGETS)
  target_link_libraries(acanthus_stdlib PUBLIC acanthus_runtime PRIVATE ${link_targets})
endfunction()

# The target a DEPENDS entry of library `name` stands for: another stdlib library's object
# library, or a declared dependency's imported target.
function(_acanthus_stdlib_dependency_target name dep out_var)
  get_property(declared GLOBAL PROPERTY ACANTHUS_STDLIB_DEPENDENCIES)
  get_property(libraries GLOBAL PROPERTY ACANTHUS_STDLIB_LIBRARIES)
  if(dep IN_LIST declared)
    get_property(target GLOBAL PROPERTY ACANTHUS_STDLIB_DEP_${dep}_TARGET)
    set(${out_var} ${target} PARENT_SCOPE)
  elseif(dep IN_LIST libraries)
    set(${out_var} acanthus_stdlib_${dep} PARENT_SCOPE)
  else()
    message(FATAL_ERROR "acanthus_stdlib_library(${name}): DEPENDS ${dep} is neither a stdlib "
      "library registered before it nor a dependency declared with acanthus_stdlib_dependency()")
  endif()
endfunction()
