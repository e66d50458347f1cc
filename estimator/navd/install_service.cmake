# Run at install time (install(SCRIPT)): navd's systemd unit and its default configuration, with
# the paths of the prefix being installed to (cmake --install --prefix, CPack's /usr). A /usr prefix
# keeps its configuration in /etc (FHS), any other in PREFIX/etc. Expects HIL_NAVD_SOURCE_DIR and
# HIL_NAVD_BINARY_DIR (set by the install(CODE) before it).
if(CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(HIL_NAVD_SYSCONFDIR /etc)
else()
  set(HIL_NAVD_SYSCONFDIR ${CMAKE_INSTALL_PREFIX}/etc)
endif()
set(HIL_NAVD_BINDIR ${CMAKE_INSTALL_PREFIX}/bin)
configure_file(${HIL_NAVD_SOURCE_DIR}/navd.service.in ${HIL_NAVD_BINARY_DIR}/navd.service @ONLY)
file(INSTALL ${HIL_NAVD_BINARY_DIR}/navd.service DESTINATION ${CMAKE_INSTALL_PREFIX}/lib/systemd/system
  FILE_PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ)
file(INSTALL ${HIL_NAVD_SOURCE_DIR}/navd.conf.example DESTINATION ${HIL_NAVD_SYSCONFDIR}/navd
  RENAME navd.conf FILE_PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ)
