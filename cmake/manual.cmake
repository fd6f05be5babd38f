# The manual page and the bash completion: written from idview's own flag table by
# idview-docs (src/tools/flag_docs.h), committed in data/ so that a build without running it
# installs them, and kept current by the test manual_current (tests/manual_test.sh), which
# regenerates them and fails on any difference. `cmake --build build --target docs-data`
# rewrites them.
include(GNUInstallDirs)

add_executable(idview-docs src/tools/docs_main.cpp src/tools/manual_page.cpp
  src/tools/completion.cpp)
target_compile_options(idview-docs PRIVATE ${IDVIEW_WARNINGS})
target_link_libraries(idview-docs PRIVATE idview_core)
# The page's version is the project's alone: a commit in it would make every commit's page
# differ from the committed one.
target_compile_definitions(idview-docs PRIVATE IDVIEW_DOCS_VERSION="${PROJECT_VERSION}")

add_custom_target(docs-data
  COMMAND idview-docs man > ${PROJECT_SOURCE_DIR}/data/idview.1
  COMMAND idview-docs bash > ${PROJECT_SOURCE_DIR}/data/idview.bash-completion
  DEPENDS idview-docs
  COMMENT "Writing data/idview.1 and data/idview.bash-completion from the flag table")

# Debian policy (and lintian's uncompressed-manual-page) wants manual pages gzipped, with
# -n so that the package is reproducible (no name or time stamp in the .gz).
find_program(IDVIEW_GZIP gzip REQUIRED)
set(IDVIEW_MAN_GZ ${CMAKE_CURRENT_BINARY_DIR}/idview.1.gz)
add_custom_command(OUTPUT ${IDVIEW_MAN_GZ}
  COMMAND ${IDVIEW_GZIP} -9 -n -c ${PROJECT_SOURCE_DIR}/data/idview.1 > ${IDVIEW_MAN_GZ}
  DEPENDS ${PROJECT_SOURCE_DIR}/data/idview.1
  COMMENT "Compressing the manual page")
add_custom_target(idview-man ALL DEPENDS ${IDVIEW_MAN_GZ})

install(FILES ${IDVIEW_MAN_GZ} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
# Where bash-completion loads it on demand, by the command's name.
install(FILES ${PROJECT_SOURCE_DIR}/data/idview.bash-completion DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
  RENAME idview)
