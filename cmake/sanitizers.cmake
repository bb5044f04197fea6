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
