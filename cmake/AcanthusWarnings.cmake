# Warnings for our own code. The generated parser and scanner build with the compiler's default
# warnings only: their code is Bison's and Flex's, not ours to make -Wextra clean.
function(acanthus_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
