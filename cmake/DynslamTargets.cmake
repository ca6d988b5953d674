# Helpers that give every module, program and test the same shape.
include(GNUInstallDirs)

set(DYNSLAM_WARNINGS -Wall -Wextra -Wpedantic -Wno-unused-parameter)

# dynslam_add_module(NAME SOURCES a.cpp ... [DEPS public libs] [PRIVATE_DEPS libs] [NO_INSTALL])
# Creates dynslam_<NAME> (alias dynslam::<NAME>) with include/ as its public include dir;
# `cmake --install` puts the library and the headers under the prefix, and the target into
# dynslamTargets.cmake as dynslam::<NAME> (NO_INSTALL: test support only).
function(dynslam_add_module name)
  cmake_parse_arguments(M "NO_INSTALL" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(dynslam_${name} STATIC ${M_SOURCES})
  add_library(dynslam::${name} ALIAS dynslam_${name})
  set_target_properties(dynslam_${name} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(dynslam_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(dynslam_${name} PUBLIC ${M_DEPS} PRIVATE ${M_PRIVATE_DEPS})
  target_compile_options(dynslam_${name} PRIVATE ${DYNSLAM_WARNINGS})
  if(DYNSLAM_SANITIZE)
    # An instrumented static library needs the sanitizer run-time wherever it is linked: the
    # exported target carries the flag, so a program outside the tree links too.
    target_link_options(dynslam_${name} INTERFACE -fsanitize=${DYNSLAM_SANITIZE})
  endif()
  if(NOT M_NO_INSTALL)
    install(TARGETS dynslam_${name} EXPORT dynslamTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endfunction()

# dynslam_add_program(NAME SOURCES ... DEPS ... [NO_INSTALL]): an executable built as
# build/bin/NAME and installed into PREFIX/bin (NO_INSTALL: the benchmarks, run from the tree).
function(dynslam_add_program name)
  cmake_parse_arguments(P "NO_INSTALL" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${P_SOURCES})
  target_link_libraries(${name} PRIVATE ${P_DEPS})
  target_compile_options(${name} PRIVATE ${DYNSLAM_WARNINGS})
  if(NOT P_NO_INSTALL)
    install(TARGETS ${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
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
