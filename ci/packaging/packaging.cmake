# Debian packages with CPack (cpack -G DEB in a build tree): `navd` (the daemon, its manual page,
# systemd unit and /etc/navd/navd.conf) and `hil` (the harness, its manual page and scenarios;
# depends on navd, which it runs). The estimator-only builds (the cross presets) make navd alone,
# for their target's Debian architecture. Files land under /usr (CPACK_SET_DESTDIR: the install
# rules see the prefix /usr, so the configuration goes to /etc); binaries are stripped.
# `make install` and cpack install what is built, without building the whole tree first (the package
# test runs cpack inside ctest; build hil, navd and the manual pages, or all, before)
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME hil)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "the hil developers")
set(CPACK_PACKAGE_CONTACT "hil developers <hil-dev@example.org>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_INSTALL_PREFIX /usr)  # what the install rules see as CMAKE_INSTALL_PREFIX (with DESTDIR)
set(CPACK_SET_DESTDIR ON)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)  # the quickest to make; the package test makes it each run
if(HIL_ESTIMATOR_ONLY)
  set(CPACK_COMPONENTS_ALL navd)
else()
  set(CPACK_COMPONENTS_ALL navd hil)
endif()
if(CMAKE_CROSSCOMPILING)
  # dpkg-shlibdeps knows only the host's libraries: a cross-built navd names its own. It links
  # libc, libstdc++ and libgcc_s alone; the newest symbol versions it uses (objdump -T: GLIBC_2.35,
  # GLIBCXX_3.4.29, GCC_3.0 on arm64 and armhf) give what dpkg-shlibdeps gives the host's navd
  set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${HIL_DEB_ARCH})
  set(CPACK_DEBIAN_NAVD_PACKAGE_DEPENDS "libc6 (>= 2.35), libgcc-s1 (>= 3.0), libstdc++6 (>= 11)")
else()
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
endif()

set(CPACK_DEBIAN_NAVD_PACKAGE_NAME navd)
set(CPACK_DEBIAN_NAVD_PACKAGE_SECTION misc)
set(CPACK_COMPONENT_NAVD_DESCRIPTION "GNSS/INS navigation estimator daemon for field robots
navd reads a GNSS receiver (NMEA 0183 or u-blox UBX) and an IMU
microcontroller over serial ports or SocketCAN, fuses them in an
error-state EKF, and writes the solution as JSON lines, NMEA 0183 and
NMEA 2000. Runs as the systemd service navd with /etc/navd/navd.conf.")
set(CPACK_DEBIAN_NAVD_PACKAGE_CONTROL_EXTRA ${CMAKE_BINARY_DIR}/packaging/navd/conffiles)
set(CPACK_DEBIAN_HIL_PACKAGE_NAME hil)
set(CPACK_DEBIAN_HIL_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_HIL_PACKAGE_DEPENDS "navd (= ${PROJECT_VERSION}), proj-data")
set(CPACK_DEBIAN_HIL_PACKAGE_SUGGESTS "gpsd, can-utils")
set(CPACK_COMPONENT_HIL_DESCRIPTION "hardware-in-the-loop test harness for agricultural-robot navigation
hil emulates a u-blox NEO-5M GPS receiver and an IMU microcontroller
byte for byte over virtual serial ports and SocketCAN, from a ground
truth integrated with SUNDIALS CVODE, runs the estimator under test
(navd by default) and measures its solution against the truth.")

file(WRITE ${CMAKE_BINARY_DIR}/packaging/navd/conffiles "/etc/navd/navd.conf\n")
# each package's /usr/share/doc/<package>: copyright and the (native) changelog, gzip -9n
foreach(HIL_DEB_PACKAGE IN LISTS CPACK_COMPONENTS_ALL)
  set(dir ${CMAKE_BINARY_DIR}/packaging/${HIL_DEB_PACKAGE})
  configure_file(${CMAKE_CURRENT_LIST_DIR}/changelog.in ${dir}/changelog @ONLY)
  add_custom_command(OUTPUT ${dir}/changelog.gz COMMAND gzip -9nkf ${dir}/changelog
    DEPENDS ${dir}/changelog VERBATIM)
  add_custom_target(${HIL_DEB_PACKAGE}_changelog ALL DEPENDS ${dir}/changelog.gz)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/copyright ${dir}/changelog.gz
    DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/${HIL_DEB_PACKAGE} COMPONENT ${HIL_DEB_PACKAGE})
endforeach()
include(CPack)
