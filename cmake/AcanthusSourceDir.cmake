# acanthus_use_source_dir(TARGET): gives TARGET's sources ACANTHUS_SOURCE_DIR, the checkout's root,
# through one small library, so the target's own compile commands name no absolute path.
function(acanthus_use_source_dir target)
  if(NOT TARGET acanthus_test_source_dir)
    add_library(acanthus_test_source_dir STATIC "${PROJECT_SOURCE_DIR}/tests/support/source_dir.cpp")
    target_compile_definitions(acanthus_test_source_dir PRIVATE
      ACANTHUS_CHECKOUT_DIR="${PROJECT_SOURCE_DIR}")
    target_include_directories(acanthus_test_source_dir PUBLIC "${PROJECT_SOURCE_DIR}/tests/support")
  endif()
  target_link_libraries(${target} PRIVATE acanthus_test_source_dir)
  target_compile_options(${target} PRIVATE -include source_dir.hpp)
endfunction()
