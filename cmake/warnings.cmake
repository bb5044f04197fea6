# Warnings for mink's own targets; MINK_WERROR makes them errors (CI turns it on).
# -ffp-contract=off: no fused multiply-add behind our back, so results do not depend on the
# compiler's contraction choices (determinism across builds). -ffast-math is never used: it
# would defeat the NaN checks that guard every query.
function(mink_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -ffp-contract=off)
  if(MINK_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
