# install.cmake - `cmake --install` (GNUInstallDirs), the version line's commit and the Debian
# package (`cpack -G DEB` in the build folder). Included by CMakeLists.txt after the targets.
include(GNUInstallDirs)
# Directories 0755 whatever the umask of the person packaging.
set(CMAKE_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ
  GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

# The installed program finds its data and helpers relative to itself (util/program_paths.h),
# so an installed tree runs wherever it is copied: these are bin/ -> share/idview, libexec/idview.
set(IDVIEW_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/idview)
set(IDVIEW_INSTALL_HELPERDIR ${CMAKE_INSTALL_LIBEXECDIR}/idview)
file(RELATIVE_PATH IDVIEW_DATA_FROM_BIN ${CMAKE_INSTALL_FULL_BINDIR}
  ${CMAKE_INSTALL_PREFIX}/${IDVIEW_INSTALL_DATADIR})
file(RELATIVE_PATH IDVIEW_HELPERS_FROM_BIN ${CMAKE_INSTALL_FULL_BINDIR}
  ${CMAKE_INSTALL_PREFIX}/${IDVIEW_INSTALL_HELPERDIR})
set_source_files_properties(src/util/program_paths.cpp PROPERTIES COMPILE_DEFINITIONS
  "IDVIEW_DATA_FROM_BIN=\"${IDVIEW_DATA_FROM_BIN}\";IDVIEW_HELPERS_FROM_BIN=\"${IDVIEW_HELPERS_FROM_BIN}\"")

# `idview --version` names the commit: written at every build (cmake/version.cmake rewrites the
# header only when the commit changed, so one file recompiles).
find_package(Git QUIET)
set(IDVIEW_COMMIT_HEADER ${CMAKE_BINARY_DIR}/generated/idview_commit.h)
add_custom_target(idview_commit
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DGIT=${GIT_EXECUTABLE}
    -DOUTPUT=${IDVIEW_COMMIT_HEADER} -P ${CMAKE_SOURCE_DIR}/cmake/version.cmake
  BYPRODUCTS ${IDVIEW_COMMIT_HEADER}
  COMMENT "Reading the commit for idview --version")
add_dependencies(idview_core idview_commit)
set_source_files_properties(src/app/version.cpp PROPERTIES
  INCLUDE_DIRECTORIES ${CMAKE_BINARY_DIR}/generated)

install(TARGETS idview idview-step-copies RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS idview-load-worker RUNTIME DESTINATION ${IDVIEW_INSTALL_HELPERDIR})
install(DIRECTORY shaders DESTINATION ${IDVIEW_INSTALL_DATADIR})
install(FILES assets/default.glb DESTINATION ${IDVIEW_INSTALL_DATADIR}/assets)

# What Debian policy asks of every package: the copyright and, for a native package, the
# changelog compressed with gzip -9n (reproducible: no name or time in it).
set(IDVIEW_DEBIAN_DOC ${CMAKE_INSTALL_DATADIR}/doc/idview)
# Its entry names the package's version and maintainer (set below, before CPack).
add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/debian/changelog.gz
  COMMAND gzip -9n --force --keep ${CMAKE_BINARY_DIR}/debian/changelog
  DEPENDS ${CMAKE_BINARY_DIR}/debian/changelog)
add_custom_target(idview_changelog ALL DEPENDS ${CMAKE_BINARY_DIR}/debian/changelog.gz)
install(FILES cmake/debian/copyright ${CMAKE_BINARY_DIR}/debian/changelog.gz
  DESTINATION ${IDVIEW_DEBIAN_DOC})

# The package: idview_VERSION_ARCH.deb, its libraries found by dpkg-shlibdeps.
set(CPACK_PACKAGE_NAME idview)
set(CPACK_PACKAGE_VENDOR "idview")
set(CPACK_PACKAGE_CONTACT "idview maintainers <maintainers@users.noreply.h-seed-0abe3601.example>"
  CACHE STRING "The package's Maintainer field")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Vulkan viewer for CAD assemblies that knows the part at each pixel")
set(CPACK_PACKAGE_DESCRIPTION [=[idview opens STEP, IGES, BREP, glTF and STL models of many small parts
and draws them with Vulkan, knowing in the fragment shader which unique part
covers each pixel. It picks, selects, hides, sections and measures parts in a
window, renders headless to images and ID images, and compares the cost of
thirteen part-ID techniques on the same model.]=])
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# zenity: the file chooser's fallback without a desktop portal; mesa-vulkan-drivers: a Vulkan
# driver (lavapipe) where the machine has no GPU driver of its own.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "zenity, mesa-vulkan-drivers")

configure_file(cmake/debian/changelog.in ${CMAKE_BINARY_DIR}/debian/changelog @ONLY)
