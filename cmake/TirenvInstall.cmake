# SPDX-License-Identifier: Apache-2.0
# What 'cmake --install build --prefix P' (and 'make install PREFIX=P') puts where. Every path
# is relative to the prefix, so an installed tree can be moved as a whole: the CMake package
# and tirenv.pc locate themselves, the CLI finds its data from its own location.
#
#   bin/tirenv                         the CLI
#   lib/libtirenv.so.MAJOR.MINOR.PATCH shared library, soname libtirenv.so.MAJOR
#   lib/libtirenv.a                    static library
#   include/tirenv/*.h                 public headers, version.h among them
#   lib/pkgconfig/tirenv.pc            pkg-config --cflags --libs tirenv
#   lib/cmake/tirenv/                  find_package(tirenv): tirenv::tirenv (shared),
#                                      tirenv::tirenv_static
#   share/man/man1/tirenv*.1           man pages
#   share/tirenv/                      data: tires, vehicles, the embedded data set
#   share/tirenv/fmu/                  the FMI 2.0 FMU, tirenv_effective_road.fmu
#   share/doc/tirenv/                  README.md, LICENSE, NOTICE and docs/
include(CMakePackageConfigHelpers)
set(TIRENV_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/tirenv)

install(TARGETS tirenv_shared EXPORT tirenvTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS tirenv_lib EXPORT tirenvStaticTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/tirenv DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/include/tirenv/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tirenv)

# The CMake package. The static library's targets are a file of their own: they need jansson
# at link time, which tirenvConfig.cmake looks for only to offer tirenv::tirenv_static.
install(EXPORT tirenvTargets NAMESPACE tirenv:: DESTINATION ${TIRENV_CMAKE_DIR})
install(EXPORT tirenvStaticTargets NAMESPACE tirenv:: DESTINATION ${TIRENV_CMAKE_DIR})
configure_package_config_file(cmake/tirenvConfig.cmake.in
  ${PROJECT_BINARY_DIR}/tirenvConfig.cmake INSTALL_DESTINATION ${TIRENV_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tirenvConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)  # as the soname
install(FILES ${PROJECT_BINARY_DIR}/tirenvConfig.cmake
              ${PROJECT_BINARY_DIR}/tirenvConfigVersion.cmake
        DESTINATION ${TIRENV_CMAKE_DIR})

# pkg-config, with the prefix found from the .pc file's own directory.
if(IS_ABSOLUTE ${CMAKE_INSTALL_LIBDIR})
  message(FATAL_ERROR "tirenv: CMAKE_INSTALL_LIBDIR must be relative to the prefix "
                      "(got ${CMAKE_INSTALL_LIBDIR})")
endif()
file(RELATIVE_PATH TIRENV_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
configure_file(cmake/tirenv.pc.in ${PROJECT_BINARY_DIR}/tirenv.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/tirenv.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

if(TIRENV_BUILD_CLI)
  install(TARGETS tirenv RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY ${TIRENV_MAN_DIR}/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1
          FILES_MATCHING PATTERN "*.1")
endif()
# Every data directory (tires, vehicles, dataset, ...), where the CLI looks for them.
install(DIRECTORY data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/tirenv)
install(FILES README.md LICENSE NOTICE DESTINATION ${CMAKE_INSTALL_DOCDIR})
# README.md links to these: beside it in the same relative places, so that the links work in
# the installed tree (tests/package/install.sh follows every one).
install(FILES python/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR}/python)
install(FILES fmu/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR}/fmu)
install(DIRECTORY docs DESTINATION ${CMAKE_INSTALL_DOCDIR})
