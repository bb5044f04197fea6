# MINK_SANITIZE builds every mink target with AddressSanitizer and UndefinedBehaviorSanitizer;
# undefined behaviour aborts instead of printing and going on, so CTest sees it.
if(MINK_SANITIZE)
  # -O1: the instrumented build of the template-heavy tests compiles several times faster than
  # at -O2 and still inlines enough to run the sweeps quickly. Line tables only (overriding the
  # build type's -g): reports keep file and line, and the tests compile about 16 % faster.
  # AddressSanitizer's checks as calls into its runtime rather than inline code: the same checks
  # in much less code, so the template-heavy files compile faster (a batch of property sweeps at
  # -O0: 224 s against 154 s; the library's shape_queries.cpp 160 s against 136 s), and run
  # slower: the long sweeps keep inline checks (tests/CMakeLists.txt).
  add_compile_options(-O1 -gline-tables-only -fsanitize=address,undefined -fno-sanitize-recover=all
                      -fsanitize-address-outline-instrumentation -fno-omit-frame-pointer)
  # Executables not position independent: the test program's 2.6 million relocations took half
  # of the 0.25 s that each of its ~280 CTest processes spends starting (0.12 s without).
  add_link_options(-fsanitize=address,undefined -no-pie)
endif()

# The test programs leave out UBSan's alignment, pointer-overflow and null checks: in
# template-heavy code they are most of the instrumentation (a static property test file: 89 s
# to compile with them, 46 s without, 44 s under ASan alone). The library's, the tool's and the
# examples' files keep every check (an inline function that a test file also instantiates may
# link from the test file's copy).
function(mink_test_sanitizer_checks target)
  if(MINK_SANITIZE)
    target_compile_options(${target} PRIVATE -fno-sanitize=alignment,pointer-overflow,null)
  endif()
endfunction()

# Files that instantiate many queries compile several times faster at -O0 than at -O1 under the
# sanitizers (the library's files for every pair of shape types: 7 to 12 minutes each at -O1,
# under one at -O0; a test file of a few dozen pairs: 108 s against 20 s), and CI's time is
# mostly compiling. The files whose tests run long brute-force sweeps stay at -O1, where the
# oracles run 20 to 50 times faster.
function(mink_sanitized_at_O0)
  if(MINK_SANITIZE)
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS -O0)
  endif()
endfunction()

# Test files of that kind whose tests run in a second or less at -O0 all the same: -O0 in the
# optimized build too (unless MINK_TESTS_OPTIMIZED), where they compile in 40 % of their -O1
# time (a property test file: 43 s against 114 s; these files were half of that build's CPU
# time). Their answers stay the same bit for bit, for the reason given below. Takes the target
# (an object library) that holds them.
function(mink_quick_tests_at_O0 target)
  if(MINK_SANITIZE OR NOT MINK_TESTS_OPTIMIZED)
    target_compile_options(${target} PRIVATE -O0)
  endif()
endfunction()

# The test programs of an optimized build at -O1: they compile in 57 % of the time of -O3 (a
# property test file: 70 s against 123 s), CI's time is mostly compiling, and their sweeps run in
# seconds either way. Their answers are the same bit for bit: -ffp-contract=off and no fast-math
# (warnings.cmake) leave the optimizer no freedom over floating-point results. The library, the
# tools and the benchmarks keep the build type's level, and the tests through the library's
# runtime dispatch run its -O3 code. MINK_TESTS_OPTIMIZED=ON keeps the build type's level for
# the tests too.
option(MINK_TESTS_OPTIMIZED "Compile the tests at the build type's optimization level" OFF)
function(mink_test_optimization target)
  if(NOT MINK_SANITIZE AND NOT MINK_TESTS_OPTIMIZED AND CMAKE_BUILD_TYPE MATCHES "^(Release|RelWithDebInfo|MinSizeRel)$")
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()
