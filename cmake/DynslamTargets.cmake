# Helpers that give every module, program and test the same shape.

set(DYNSLAM_WARNINGS -Wall -Wextra -Wpedantic -Wno-unused-parameter)

# dynslam_add_module(NAME SOURCES a.cpp ... [DEPS public libs] [PRIVATE_DEPS libs])
# Creates dynslam_<NAME> (alias dynslam::<NAME>) with include/ as its public include dir.
function(dynslam_add_module name)
  cmake_parse_arguments(M "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(dynslam_${name} STATIC ${M_SOURCES})
  add_library(dynslam::${name} ALIAS dynslam_${name})
  target_include_directories(dynslam_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(dynslam_${name} PUBLIC ${M_DEPS} PRIVATE ${M_PRIVATE_DEPS})
  target_compile_options(dynslam_${name} PRIVATE ${DYNSLAM_WARNINGS})
endfunction()

# dynslam_add_program(NAME SOURCES ... DEPS ...): an executable installed as build/bin/NAME.
function(dynslam_add_program name)
  cmake_parse_arguments(P "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${P_SOURCES})
  target_link_libraries(${name} PRIVATE ${P_DEPS})
  target_compile_options(${name} PRIVATE ${DYNSLAM_WARNINGS})
endfunction()

# dynslam_add_test(NAME SOURCES ... DEPS ...): a GoogleTest binary registered with CTest.
# dynslam::testing tells it where ../shared, build/bin, the sources and its scratch space are.
function(dynslam_add_test name)
  cmake_parse_arguments(T "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_DEPS} dynslam::testing GTest::gtest GTest::gtest_main)
  target_compile_options(${name} PRIVATE ${DYNSLAM_WARNINGS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60)
endfunction()
