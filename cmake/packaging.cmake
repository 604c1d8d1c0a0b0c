# `cpack -G DEB` in the build folder builds one Debian package with the library, headers,
# CMake package and the CLI (and the studio when it is built).
set(CPACK_PACKAGE_NAME fieldlines)
set(CPACK_PACKAGE_VENDOR "fieldlines")
set(CPACK_PACKAGE_CONTACT "fieldlines maintainers <fieldlines@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Soccer-field line detection (ELSED + colour transitions) for robots")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL OFF)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
# The static library's users need the headers of its dependencies.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libopencv-dev (>= 4.5), libeigen3-dev, nlohmann-json3-dev")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
include(CPack)
