# hil_man_page(TARGET <executable> SECTION <n> NAME <one-line description> COMPONENT <component>)
# Makes the executable's manual page from its --help text with help2man (Debian help2man), gzip
# -9n as Debian ships them, and installs it into share/man/man<n>. A cross-built executable runs
# under CMAKE_CROSSCOMPILING_EMULATOR (through a wrapper of the same name, so the page is named for
# it). Without help2man the page is left out and configure says so. help2man runs in the C.UTF-8
# locale: in its default C locale it writes each non-ASCII character of --help as ??? (the page
# read `hil ??? hardware-in-the-loop…` for hil's em dash).
find_program(HIL_HELP2MAN help2man)
if(NOT HIL_HELP2MAN)
  message(STATUS "help2man not found: no manual pages (the executables' --help says the same)")
endif()
function(hil_man_page)
  cmake_parse_arguments(M "" "TARGET;SECTION;NAME;COMPONENT" "" ${ARGN})
  if(NOT HIL_HELP2MAN)
    return()
  endif()
  set(exe $<TARGET_FILE:${M_TARGET}>)
  if(CMAKE_CROSSCOMPILING_EMULATOR)
    list(JOIN CMAKE_CROSSCOMPILING_EMULATOR " " emulator)
    set(exe ${CMAKE_CURRENT_BINARY_DIR}/man-run/${M_TARGET})
    file(GENERATE OUTPUT ${exe} CONTENT "#!/bin/sh\nexec ${emulator} $<TARGET_FILE:${M_TARGET}> \"$@\"\n"
      FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
  endif()
  set(page ${CMAKE_CURRENT_BINARY_DIR}/${M_TARGET}.${M_SECTION})
  add_custom_command(OUTPUT ${page}.gz
    COMMAND ${HIL_HELP2MAN} --locale=C.UTF-8 --no-info --no-discard-stderr --version-string=${PROJECT_VERSION}
      --section=${M_SECTION} --name=${M_NAME} --output=${page} ${exe}
    COMMAND gzip -9nf ${page}
    DEPENDS ${M_TARGET} VERBATIM COMMENT "Manual page ${M_TARGET}(${M_SECTION}) from ${M_TARGET} --help")
  add_custom_target(${M_TARGET}_man ALL DEPENDS ${page}.gz)
  install(FILES ${page}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man${M_SECTION} COMPONENT ${M_COMPONENT})
endfunction()
