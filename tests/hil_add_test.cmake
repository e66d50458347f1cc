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
