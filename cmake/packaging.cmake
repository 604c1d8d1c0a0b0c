# `cpack -G DEB` in the build folder builds four Debian packages, one per install component:
#   libfieldlines-detect0  the robot's runtime: libfieldlines_detect.so.* and nothing else
#   libfieldlines0         the tuning libraries (data, train, synth) the tools need
#   libfieldlines-dev      headers, CMake package, .so links (static archives when built static)
#   fieldlines             the CLI, the studio (when built) and the default thresholds
set(CPACK_PACKAGE_NAME fieldlines)
set(CPACK_PACKAGE_VENDOR "fieldlines")
set(CPACK_PACKAGE_CONTACT "fieldlines maintainers <fieldlines@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Soccer-field line detection (ELSED + colour transitions) for robots")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL detect libs dev tools)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Our own libraries are resolved from the build tree; the packages depend on each other through
# CPACK_COMPONENT_<C>_DEPENDS.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${PROJECT_BINARY_DIR}/core)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)
set(_fieldlines_soversion ${PROJECT_VERSION_MAJOR})
set(CPACK_DEBIAN_DETECT_PACKAGE_NAME libfieldlines-detect${_fieldlines_soversion})
set(CPACK_DEBIAN_DETECT_PACKAGE_SECTION libs)
set(CPACK_COMPONENT_DETECT_DESCRIPTION "fieldlines line detector and classifier (the robot's runtime library)")
set(CPACK_DEBIAN_LIBS_PACKAGE_NAME libfieldlines${_fieldlines_soversion})
set(CPACK_DEBIAN_LIBS_PACKAGE_SECTION libs)
set(CPACK_COMPONENT_LIBS_DESCRIPTION "fieldlines data, training and synthetic-field libraries")
set(CPACK_COMPONENT_LIBS_DEPENDS detect)
set(CPACK_DEBIAN_DEV_PACKAGE_NAME libfieldlines-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_COMPONENT_DEV_DESCRIPTION "fieldlines headers and CMake package (find_package(fieldlines COMPONENTS detect))")
set(CPACK_COMPONENT_DEV_DEPENDS detect libs)
# The headers include those of the dependencies.
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "libopencv-dev (>= 4.5), libeigen3-dev, nlohmann-json3-dev")
set(CPACK_DEBIAN_TOOLS_PACKAGE_NAME fieldlines)
set(CPACK_COMPONENT_TOOLS_DESCRIPTION "fieldlines command-line tool and studio")
set(CPACK_COMPONENT_TOOLS_DEPENDS detect libs)
include(CPack)
