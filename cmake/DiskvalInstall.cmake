# Install rules, the CMake package (diskval::diskval), the pkg-config module
# and the Debian package (cpack -G DEB): included from the top CMakeLists.txt
# once every target exists.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(DISKVAL_SCENARIO_DIR ${CMAKE_INSTALL_DATADIR}/diskval/scenarios)
set(DISKVAL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/diskval)

install(TARGETS diskval RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(TARGETS diskval_lib EXPORT diskvalTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime
  PUBLIC_HEADER DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/diskval COMPONENT development
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT diskvalTargets NAMESPACE diskval:: DESTINATION ${DISKVAL_CMAKE_DIR}
        COMPONENT development)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenarios/ DESTINATION ${DISKVAL_SCENARIO_DIR}
        COMPONENT runtime FILES_MATCHING PATTERN "*.ini")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/league/ DESTINATION ${CMAKE_INSTALL_DATADIR}/diskval/league
        COMPONENT runtime FILES_MATCHING PATTERN "*.ini" PATTERN "*.md")
# the README and its manual side by side, so the README's links to docs/ hold
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        COMPONENT runtime FILES_MATCHING PATTERN "*.md")

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/diskvalConfig.cmake.in
  ${PROJECT_BINARY_DIR}/diskvalConfig.cmake INSTALL_DESTINATION ${DISKVAL_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR DISKVAL_SCENARIO_DIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/diskvalConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion) # 0.x: minor versions may break
install(FILES ${PROJECT_BINARY_DIR}/diskvalConfig.cmake ${PROJECT_BINARY_DIR}/diskvalConfigVersion.cmake
        DESTINATION ${DISKVAL_CMAKE_DIR} COMPONENT development)

# pkg-config: relocatable, the prefix found from the .pc file's own
# directory, so an install under any --prefix (or the .deb's /usr) is right
file(RELATIVE_PATH DISKVAL_PC_UP /pfx/${CMAKE_INSTALL_LIBDIR}/pkgconfig /pfx)
string(REGEX REPLACE "/$" "" DISKVAL_PC_UP "${DISKVAL_PC_UP}")
foreach(d LIBDIR INCLUDEDIR DATADIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${d}}")
    set(DISKVAL_PC_${d} "${CMAKE_INSTALL_${d}}")
  else()
    set(DISKVAL_PC_${d} "\${prefix}/${CMAKE_INSTALL_${d}}")
  endif()
endforeach()
configure_file(${CMAKE_CURRENT_LIST_DIR}/diskval.pc.in ${PROJECT_BINARY_DIR}/diskval.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/diskval.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT development)

# a man page from --help, where help2man is installed (optional: apt-get install help2man)
find_program(HELP2MAN help2man)
if(HELP2MAN AND NOT CMAKE_CROSSCOMPILING AND NOT DV_SANITIZE) # not run under ASan at build time
  add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/diskval.1
    COMMAND ${HELP2MAN} --no-info --version-string=${PROJECT_VERSION}
            --name "validate physics engines against an exact rolling-disk reference"
            --output ${PROJECT_BINARY_DIR}/diskval.1 $<TARGET_FILE:diskval>
    DEPENDS diskval VERBATIM)
  add_custom_target(diskval_man ALL DEPENDS ${PROJECT_BINARY_DIR}/diskval.1)
  install(FILES ${PROJECT_BINARY_DIR}/diskval.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1
          COMPONENT runtime)
endif()

# cpack -G DEB: one package with the command, library, headers and scenarios;
# its dependencies are the runtime packages dpkg-shlibdeps finds for the
# binaries (libgsl27, libsundials-cvode6, libode8, libmujoco2.2.2, ...)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME diskval)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "diskval developers")
set(CPACK_PACKAGE_CONTACT "diskval developers <diskval@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "validates physics engines (MuJoCo, ODE) against an exact rolling-disk reference")
set(CPACK_PACKAGE_DESCRIPTION "diskval runs rolling-disk scenarios through MuJoCo and ODE and compares \
them with an exact reference (the reduced equations of the rolling disk), with verdicts, reports and \
JUnit output for CI. The package holds the diskval command, libdiskval with its C API and headers, \
the CMake and pkg-config files, and the example scenarios.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_STRIP_FILES ON)
include(CPack)
