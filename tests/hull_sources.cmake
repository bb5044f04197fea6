# Sources of the convex hull unit tests (no dependency beyond GoogleTest); the CGAL oracle tests
# are a separate executable in hull/CMakeLists.txt.
set(MINK_HULL_TEST_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/unit/hull/predicates_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/unit/hull/convex_hull_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/unit/hull/hull_support_test.cpp
)
