# version.cmake - run at every build (cmake -P): writes the commit idview is built from into
# OUTPUT as IDVIEW_COMMIT (git describe of SOURCE_DIR; "unknown" outside git or without GIT),
# rewriting the file only when it changed so a build recompiles nothing more.
set(commit unknown)
if(GIT)
  execute_process(COMMAND ${GIT} describe --always --dirty --abbrev=12
    WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE described
    OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed ERROR_QUIET)
  if(NOT failed AND described)
    set(commit ${described})
  endif()
endif()
set(text "// Written by cmake/version.cmake: the commit idview was built from.\n#define IDVIEW_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUTPUT} "${text}")
endif()
