set(MINK_TEST_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/oracle/oracle_self_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/unit/gjk/smoke_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/unit/gjk/analytic_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/unit/gjk/brute_force_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/property/gjk_property_test.cpp
)
