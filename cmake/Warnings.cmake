# Strict warnings for our own targets only; third-party headers come in as SYSTEM includes.
function(cutcalc_strict_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror -Wshadow
                                           -Wconversion -Wno-sign-conversion)
endfunction()
