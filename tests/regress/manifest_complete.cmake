# Fails when a rule file of rules/, a panel of examples/panels/ or a facade of
# examples/facades/ is missing from the regression manifest (a new one would go unchecked).
#   cmake -DMANIFEST=<regress.toml> -DSOURCE=<source dir> -P manifest_complete.cmake
cmake_minimum_required(VERSION 3.20)
file(READ "${MANIFEST}" manifest)
file(GLOB files "${SOURCE}/rules/*.acr" "${SOURCE}/examples/panels/*.svg"
  "${SOURCE}/examples/facades/*.svg")
set(missing "")
foreach(file IN LISTS files)
  file(RELATIVE_PATH relative "${SOURCE}" "${file}")
  string(FIND "${manifest}" "\"../../${relative}\"" at)
  if(at EQUAL -1)
    list(APPEND missing "${relative}")
  endif()
endforeach()
if(missing)
  list(JOIN missing "\n  " missing)
  message(FATAL_ERROR "not in ${MANIFEST} (add them, then scripts/update-references):\n  ${missing}")
endif()
