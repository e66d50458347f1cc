# hil_add_test(NAME <name> SOURCES <files…> [LIBS <targets…>] LABELS <unit|golden|pty|vcan|e2e|bench…>
#              [TIMEOUT <s>] [ARGS <args…>])
# Registers one GoogleTest executable as one ctest test with its labels. Tests run from the build
# directory with HIL_SOURCE_DIR (the checkout) and HIL_BIN_DIR (hil, navd) in their environment.
function(hil_add_test)
  cmake_parse_arguments(T "" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS;ARGS" ${ARGN})
  if(NOT T_NAME OR NOT T_SOURCES OR NOT T_LABELS)
    message(FATAL_ERROR "hil_add_test needs NAME, SOURCES and LABELS")
  endif()
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main hil::build_flags)
  if(TARGET hil_test_pch)
    target_precompile_headers(${T_NAME} REUSE_FROM hil_test_pch)
    set_target_properties(${T_NAME} PROPERTIES CXX_COMPILER_LAUNCHER "${HIL_TEST_PCH_LAUNCHER}")
  endif()
  set_target_properties(${T_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests/bin)
  add_test(NAME ${T_NAME} COMMAND ${T_NAME} ${T_ARGS})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 300)
  endif()
  # under an emulator (the cross builds' qemu-user, TCG) a test runs some 40 x slower than native:
  # navigator_robustness_test, 3 s native, took 120 s on the CI machine and passed 300 s under
  # armhf on a loaded one. The bound stays a hang detector, not a speed judgement.
  if(CMAKE_CROSSCOMPILING_EMULATOR)
    math(EXPR T_TIMEOUT "${T_TIMEOUT} * 4")
  endif()
  set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
    ENVIRONMENT "HIL_SOURCE_DIR=${PROJECT_SOURCE_DIR};HIL_BIN_DIR=${CMAKE_BINARY_DIR}/bin")
endfunction()

# hil_test_precompiled_headers([<header>…] [LIBS <targets…>])
# The test programs' precompiled header (option HIL_TEST_PCH): GoogleTest, Eigen and the standard
# headers most tests include, plus the given headers (LIBS: the targets that bring them), compiled
# once into the object library hil_test_pch that every hil_add_test program then reuses, instead of
# each of them parsing the same headers again. The library has the test programs' flags
# (hil::build_flags, GoogleTest's definitions), which GCC requires to accept the header; CMake adds
# -Winvalid-pch, so with HIL_WERROR a header GCC cannot use fails the build instead of going slow.
# Call it before the tests are added.
# Through a precompiled header GCC 12 no longer treats libstdc++'s code as a system header's: its
# -Warray-bounds false positive on std::string concatenation (`std::string&& + ...`, the move out of
# the sum: char_traits.h's __builtin_memcpy "forming offset [32, N] is out of the bounds [0, 32]")
# then fires, an error with HIL_WERROR (68 sites in 16 programs until they were reworded: the tests
# join text with hil::test::Joined, tests/support/joined_text.h, instead).
# On by default and in the presets (default, ci, asan, cross-*); off in tidy, which is configured
# only, for clang-tidy (clang cannot use a GCC precompiled header).
# Measured (fresh ci build, CCACHE_DISABLE=1, -j2, the libraries built first): the tests' build
# 1209 s of CPU without, 1013 s with (-16 %; their 269 compiles 1107 s -> 909 s with the header's
# 8 s, links 76 -> 78 s). One TU each, loaded machine: geodesy_test 3.16 -> 1.85 s CPU,
# mount_angle_test 6.80 -> 5.47 s; asan flags 3.56 -> 2.71 s and 13.67 -> 10.77 s.
option(HIL_TEST_PCH "Compile the headers every test program includes once (precompiled header)" ON)
function(hil_test_precompiled_headers)
  cmake_parse_arguments(P "" "" "LIBS" ${ARGN})
  if(NOT HIL_TEST_PCH)
    return()
  endif()
  add_library(hil_test_pch OBJECT ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/support/precompiled_headers.cc)
  target_link_libraries(hil_test_pch PRIVATE GTest::gtest Eigen3::Eigen hil::build_flags ${P_LIBS})
  # ccache caches a compile that uses a precompiled header only with this sloppiness (its manual,
  # "Precompiled headers"); without it every test program would be a ccache miss
  set(launcher "${CMAKE_CXX_COMPILER_LAUNCHER}")
  if(launcher MATCHES "ccache")
    set(launcher env CCACHE_SLOPPINESS=pch_defines,time_macros ${launcher})
  endif()
  set(HIL_TEST_PCH_LAUNCHER "${launcher}" PARENT_SCOPE)
  set_target_properties(hil_test_pch PROPERTIES CXX_COMPILER_LAUNCHER "${launcher}")
  target_precompile_headers(hil_test_pch PRIVATE <gtest/gtest.h> <Eigen/Core> <Eigen/Geometry>
    <algorithm> <array> <chrono> <cmath> <cstdint> <cstdio> <cstdlib> <filesystem> <fstream>
    <map> <numbers> <optional> <random> <set> <sstream> <string> <string_view> <thread> <vector>
    ${P_UNPARSED_ARGUMENTS})
endfunction()
