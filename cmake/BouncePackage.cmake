# The CLI's man page and bash completion, and the Debian packages of `make package`
# (scripts/package.sh configures build-package with /usr as the prefix and runs CPack).
#
# * bash completion: `bounce completion`, which the CLI generates from its own commands and
#   options and from the library's registries (models, contact laws, materials).
# * man page: help2man from `bounce --help-all` and `bounce --version`, when help2man is
#   installed (scripts/package.sh makes sure it is).
# * packages (CPack DEB, one per install component, dependencies from dpkg-shlibdeps):
#   libbounce0 (library), libbounce-dev (headers, CMake package), bounce (CLI, man page,
#   completion), python3-bounce (/usr/lib/python3/dist-packages/bounce) and, when the plugin
#   is built (LAMMPS_SOURCE_DIR), bounce-lammps-plugin (<libdir>/lammps/plugins).

option(BOUNCE_PACKAGE "Configured for `make package`: the man page is required (help2man)" OFF)
set(BOUNCE_SHARE_DIR ${PROJECT_BINARY_DIR}/share)

set(BOUNCE_COMPLETION ${BOUNCE_SHARE_DIR}/bash-completion/completions/bounce)
add_custom_command(OUTPUT ${BOUNCE_COMPLETION}
  COMMAND ${CMAKE_COMMAND} -DCLI=$<TARGET_FILE:bounce_cli> -DARGS=completion -DOUT=${BOUNCE_COMPLETION}
          -P ${PROJECT_SOURCE_DIR}/cmake/BounceCliOutput.cmake
  DEPENDS bounce_cli ${PROJECT_SOURCE_DIR}/cmake/BounceCliOutput.cmake
  COMMENT "Generating the bash completion from the CLI and the registries")
add_custom_target(bounce_completion ALL DEPENDS ${BOUNCE_COMPLETION})
install(FILES ${BOUNCE_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions COMPONENT cli)

find_program(BOUNCE_HELP2MAN help2man)
find_program(BOUNCE_GZIP gzip)
if(BOUNCE_HELP2MAN AND BOUNCE_GZIP)
  set(BOUNCE_MAN ${BOUNCE_SHARE_DIR}/man/man1/bounce.1)
  add_custom_command(OUTPUT ${BOUNCE_MAN}.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${BOUNCE_SHARE_DIR}/man/man1
    COMMAND ${BOUNCE_HELP2MAN} --no-info --help-option=--help-all --version-option=--version
            "--name=collision physics of adhesive, viscoelastic grains" --section=1
            --output=${BOUNCE_MAN} $<TARGET_FILE:bounce_cli>
    COMMAND ${BOUNCE_GZIP} -9nf ${BOUNCE_MAN}
    DEPENDS bounce_cli
    COMMENT "Generating the man page from bounce --help-all (help2man)"
    VERBATIM)
  add_custom_target(bounce_man ALL DEPENDS ${BOUNCE_MAN}.gz)
  install(FILES ${BOUNCE_MAN}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT cli)
elseif(BOUNCE_PACKAGE)
  message(FATAL_ERROR "bounce: help2man = (not found) is invalid: expected help2man and gzip for the man page "
                      "(Debian packages help2man, gzip)")
endif()

# --- CPack: the Debian packages ------------------------------------------------------------
set(BOUNCE_PACKAGE_DIR ${PROJECT_SOURCE_DIR}/dist CACHE PATH "where `make package` writes the .deb files")
set(BOUNCE_PACKAGE_MAINTAINER "bounce maintainers <maintainers@bounce.invalid>" CACHE STRING
    "the Maintainer field of the Debian packages")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME bounce)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_CONTACT "${BOUNCE_PACKAGE_MAINTAINER}")
set(CPACK_OUTPUT_FILE_PREFIX ${BOUNCE_PACKAGE_DIR})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# libbounce.so.0 is needed by the other packages but in none installed: dpkg-shlibdeps finds
# it in the build; the dependency on libbounce0 is the components' (below).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${PROJECT_BINARY_DIR}/lib)
# A shlibs file for libbounce0, so that packages built against libbounce-dev depend on it
# (cpack notes that the Python extension and the plugin have no soname: they are modules).
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)

set(CPACK_COMPONENTS_ALL library dev cli)
set(CPACK_DEBIAN_LIBRARY_PACKAGE_NAME libbounce${PROJECT_VERSION_MAJOR})
set(CPACK_DEBIAN_LIBRARY_PACKAGE_SECTION libs)
set(CPACK_COMPONENT_LIBRARY_DESCRIPTION
    "bounce's shared library: collision physics of adhesive, viscoelastic grains")
set(CPACK_DEBIAN_DEV_PACKAGE_NAME libbounce-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_COMPONENT_DEV_DEPENDS library)
set(CPACK_COMPONENT_DEV_DESCRIPTION "bounce's C++20 headers and CMake package (find_package(bounce))")
set(CPACK_DEBIAN_CLI_PACKAGE_NAME bounce)
set(CPACK_COMPONENT_CLI_DEPENDS library)
set(CPACK_COMPONENT_CLI_DESCRIPTION
    "bounce command line: will two adhesive, viscoelastic spheres bounce or stick? (man page, bash completion)")
if(BOUNCE_BUILD_PYTHON)
  list(APPEND CPACK_COMPONENTS_ALL python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-bounce)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_COMPONENT_PYTHON_DEPENDS library)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "${BOUNCE_PYTHON_DEPENDS}, python3-numpy")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_RECOMMENDS python3-matplotlib)
  set(CPACK_COMPONENT_PYTHON_DESCRIPTION "bounce for Python 3 (numpy arrays in and out, type stubs)")
endif()
if(TARGET bounceplugin)
  list(APPEND CPACK_COMPONENTS_ALL lammps)
  set(CPACK_DEBIAN_LAMMPS_PACKAGE_NAME bounce-lammps-plugin)
  set(CPACK_COMPONENT_LAMMPS_DEPENDS library)
  set(CPACK_COMPONENT_LAMMPS_DESCRIPTION
      "pair_style bounce for LAMMPS with the PLUGIN package (LAMMPS_PLUGIN_PATH=/usr/${CMAKE_INSTALL_LIBDIR}/lammps/plugins)")
endif()
include(CPack)
