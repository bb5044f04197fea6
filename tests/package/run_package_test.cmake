# cmake -P script: install, configure the consumer, build it, run it.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()

run(${CMAKE_COMMAND} --install ${MINK_BUILD_DIR} --prefix ${prefix})
# The compiler that built mink (a user links a library with the compiler that built it).
set(flags "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${prefix} ${flags})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)

# A user's program built by GCC, Debian's compiler, when mink itself was built by another (Clang in
# scripts/test): the public headers' templates (GJK, EPA, contact, manifold) then compile under
# GCC too, at the build type's optimization and with its warnings.
if(GXX AND NOT CXX_COMPILER_ID STREQUAL "GNU")
  set(gcc_flags "-Wall -Wextra -Wpedantic -Wshadow")
  if(WERROR)
    string(APPEND gcc_flags " -Werror")
  endif()
  run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build-gcc -G ${GENERATOR}
      -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${GXX} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
      "-DCMAKE_CXX_FLAGS=${gcc_flags}")
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/build-gcc)
  run(${WORK_DIR}/build-gcc/consumer)
endif()
