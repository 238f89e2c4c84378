# Warnings for our own code; generated parser/scanner sources use acanthus_base_warnings.
function(acanthus_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
function(acanthus_base_warnings target)
  target_compile_options(${target} PRIVATE -w)
endfunction()
