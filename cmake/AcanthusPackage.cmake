# Installation and export: the runtime, its headers, the compiler, the stdlib, and the files that
# let find_package(Acanthus CONFIG) work from the install tree and from this build tree, plus
# acanthus.pc for pkg-config. Included (optionally) by the top-level CMakeLists.txt.
include(CMakePackageConfigHelpers)

set(ACANTHUS_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/Acanthus")
set(ACANTHUS_INSTALL_STDLIBDIR "${CMAKE_INSTALL_DATADIR}/acanthus/stdlib")

# Inside the tree the same names work as for consumers of the package.
if(TARGET acanthus AND NOT TARGET Acanthus::acanthus)
  add_executable(Acanthus::acanthus ALIAS acanthus)
endif()
set(ACANTHUS_STDLIB_DIR "${PROJECT_SOURCE_DIR}/stdlib")
include("${CMAKE_CURRENT_LIST_DIR}/AcanthusRules.cmake")

# --- what is installed --------------------------------------------------------------------------
install(TARGETS acanthus_runtime EXPORT Acanthus
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/runtime/include/acanthus"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" FILES_MATCHING PATTERN "*.hpp")

if(TARGET acanthus)
  set_target_properties(acanthus PROPERTIES EXPORT_NAME acanthus)
  install(TARGETS acanthus EXPORT Acanthus RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
endif()

file(GLOB ACANTHUS_STDLIB_RULE_FILES "${PROJECT_SOURCE_DIR}/stdlib/*.acr")
install(DIRECTORY DESTINATION "${ACANTHUS_INSTALL_STDLIBDIR}")  # exists even while empty
install(FILES ${ACANTHUS_STDLIB_RULE_FILES} DESTINATION "${ACANTHUS_INSTALL_STDLIBDIR}")

set(ACANTHUS_CONFIG_DEPENDENCIES "")
set(ACANTHUS_PC_LIBS "-lacanthus")
set(ACANTHUS_PC_REQUIRES "cairo pugixml 2geom polyclipping")
if(TARGET acanthus_stdlib)
  install(TARGETS acanthus_stdlib EXPORT Acanthus ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
  # Each library's public header: stdlib/<name>/include/acanthus/<name>.hpp.
  file(GLOB stdlib_include_dirs LIST_DIRECTORIES true "${PROJECT_SOURCE_DIR}/stdlib/*/include")
  foreach(dir ${stdlib_include_dirs})
    if(IS_DIRECTORY "${dir}")
      install(DIRECTORY "${dir}/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        FILES_MATCHING PATTERN "*.hpp")
    endif()
  endforeach()
  # CGAL's exact arithmetic needs GMP and MPFR when the stdlib is linked.
  list(APPEND ACANTHUS_CONFIG_DEPENDENCIES CGAL)
  set(ACANTHUS_PC_LIBS "-lacanthus_stdlib -lacanthus")
  string(APPEND ACANTHUS_PC_REQUIRES " mpfr gmp")
endif()

install(EXPORT Acanthus NAMESPACE Acanthus:: FILE AcanthusTargets.cmake
  DESTINATION "${ACANTHUS_INSTALL_CMAKEDIR}")
export(EXPORT Acanthus NAMESPACE Acanthus:: FILE "${PROJECT_BINARY_DIR}/AcanthusTargets.cmake")

# --- AcanthusConfig.cmake for the install tree and for the build tree ----------------------------
set(ACANTHUS_CONFIG_STDLIB_DIR "${ACANTHUS_INSTALL_STDLIBDIR}")
set(ACANTHUS_CONFIG_MODULE_DIR "${ACANTHUS_INSTALL_CMAKEDIR}")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/AcanthusConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/install-config/AcanthusConfig.cmake"
  INSTALL_DESTINATION "${ACANTHUS_INSTALL_CMAKEDIR}"
  PATH_VARS ACANTHUS_CONFIG_STDLIB_DIR ACANTHUS_CONFIG_MODULE_DIR)

set(ACANTHUS_CONFIG_STDLIB_DIR "${PROJECT_SOURCE_DIR}/stdlib")
set(ACANTHUS_CONFIG_MODULE_DIR "${PROJECT_SOURCE_DIR}/cmake")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/AcanthusConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/AcanthusConfig.cmake"
  INSTALL_DESTINATION "${PROJECT_BINARY_DIR}" INSTALL_PREFIX "${PROJECT_BINARY_DIR}"
  PATH_VARS ACANTHUS_CONFIG_STDLIB_DIR ACANTHUS_CONFIG_MODULE_DIR)

# 0.x releases break compatibility between minor versions.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/AcanthusConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)

install(FILES
  "${PROJECT_BINARY_DIR}/install-config/AcanthusConfig.cmake"
  "${PROJECT_BINARY_DIR}/AcanthusConfigVersion.cmake"
  "${CMAKE_CURRENT_LIST_DIR}/AcanthusRules.cmake"
  "${CMAKE_CURRENT_LIST_DIR}/AcanthusImports.cmake"
  "${CMAKE_CURRENT_LIST_DIR}/AcanthusScanImports.cmake"
  DESTINATION "${ACANTHUS_INSTALL_CMAKEDIR}")

# --- acanthus.pc: relocatable, the prefix is found from the .pc file's own directory -------------
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  message(WARNING "acanthus.pc: CMAKE_INSTALL_LIBDIR is absolute; the .pc file is not relocatable")
  set(ACANTHUS_PC_PREFIX_FROM_PCDIR "")
else()
  file(RELATIVE_PATH ACANTHUS_PC_PREFIX_FROM_PCDIR "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
  string(REGEX REPLACE "/$" "" ACANTHUS_PC_PREFIX_FROM_PCDIR "${ACANTHUS_PC_PREFIX_FROM_PCDIR}")
endif()
configure_file("${CMAKE_CURRENT_LIST_DIR}/acanthus.pc.in" "${PROJECT_BINARY_DIR}/acanthus.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/acanthus.pc" DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
