# MINK_SANITIZE builds every mink target with AddressSanitizer and UndefinedBehaviorSanitizer;
# undefined behaviour aborts instead of printing and going on, so CTest sees it.
if(MINK_SANITIZE)
  # -O1: the instrumented build of the template-heavy tests compiles several times faster than
  # at -O2 and still inlines enough to run the sweeps quickly. Line tables only (overriding the
  # build type's -g): reports keep file and line, and the tests compile about 16 % faster.
  add_compile_options(-O1 -gline-tables-only -fsanitize=address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

# The few files that instantiate the queries for every pair of shape types took 7 to 12 minutes
# each to compile at -O1 under the sanitizers (CI's critical path); at -O0 they take under one,
# and the tests that run them still finish in tens of seconds. Every other file stays at -O1,
# where the brute-force oracles of the tests run 20 to 50 times faster than at -O0.
function(mink_sanitized_at_O0)
  if(MINK_SANITIZE)
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS -O0)
  endif()
endfunction()
