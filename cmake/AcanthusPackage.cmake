# Installation and export: the runtime, its headers, the compiler, the stdlib, and the files that
# let find_package(Acanthus CONFIG) work from the install tree and from this build tree, plus
# acanthus.pc for pkg-config. Included by the top-level CMakeLists.txt, after stdlib/ registered
# its libraries (cmake/AcanthusStdlib.cmake).
include(CMakePackageConfigHelpers)

set(ACANTHUS_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/Acanthus")
set(ACANTHUS_INSTALL_STDLIBDIR "${CMAKE_INSTALL_DATADIR}/acanthus/stdlib")

# Inside the tree the same names work as for consumers of the package.
add_executable(Acanthus::acanthus ALIAS acanthus)
acanthus_stdlib_get(ACANTHUS_STDLIB_DIR RULE_DIR)
include("${CMAKE_CURRENT_LIST_DIR}/AcanthusRules.cmake")

# --- what is installed --------------------------------------------------------------------------
install(TARGETS acanthus_runtime EXPORT Acanthus
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/runtime/include/acanthus"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" FILES_MATCHING PATTERN "*.hpp")

set_target_properties(acanthus PROPERTIES EXPORT_NAME acanthus)
install(TARGETS acanthus EXPORT Acanthus RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")

# The stdlib, as its libraries registered themselves (cmake/AcanthusStdlib.cmake): the archive,
# each public header directory, each rule file, and what the archive links.
install(TARGETS acanthus_stdlib EXPORT Acanthus ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
acanthus_stdlib_get(stdlib_include_dirs INCLUDE_DIRS)
foreach(dir IN LISTS stdlib_include_dirs)
  install(DIRECTORY "${dir}/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" FILES_MATCHING PATTERN "*.hpp")
endforeach()
acanthus_stdlib_get(stdlib_rule_files RULE_FILES)
install(FILES ${stdlib_rule_files} DESTINATION "${ACANTHUS_INSTALL_STDLIBDIR}")
# `acanthus preview`: its page, and the panels it offers.
install(FILES "${PROJECT_SOURCE_DIR}/preview/index.html" "${PROJECT_SOURCE_DIR}/preview/preview.js"
  "${PROJECT_SOURCE_DIR}/preview/preview.css"
  DESTINATION "${CMAKE_INSTALL_DATADIR}/acanthus/preview")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/examples/panels/" DESTINATION "${CMAKE_INSTALL_DATADIR}/acanthus/panels"
  FILES_MATCHING PATTERN "*.svg")

acanthus_stdlib_get(ACANTHUS_CONFIG_DEPENDENCIES PACKAGES)
acanthus_stdlib_get(ACANTHUS_CONFIG_RUNTIME_PACKAGES RUNTIME_PACKAGES)
acanthus_stdlib_get(ACANTHUS_CONFIG_RUNTIME_PKG_TARGETS RUNTIME_PKG_TARGETS)
acanthus_stdlib_get(runtime_pc_modules RUNTIME_PKG_CONFIG)
acanthus_stdlib_get(stdlib_pc_modules PKG_CONFIG)
set(ACANTHUS_PC_REQUIRES ${runtime_pc_modules} ${stdlib_pc_modules})
list(REMOVE_DUPLICATES ACANTHUS_PC_REQUIRES)
list(JOIN ACANTHUS_PC_REQUIRES " " ACANTHUS_PC_REQUIRES)
set(ACANTHUS_PC_LIBS "-lacanthus_stdlib -lacanthus")

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

set(ACANTHUS_CONFIG_STDLIB_DIR "${ACANTHUS_STDLIB_DIR}")
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
