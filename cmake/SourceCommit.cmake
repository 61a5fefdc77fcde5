# Records the git commit of the source tree and whether it had uncommitted changes, for the
# report's provenance (studies/installation/InstalledFiles.hpp). Run at every build by the target
# granwave_source_commit; the file changes only when the commit or the state does, and it is
# read at run time, so the executable's bytes (and with them the run cache's key) do not
# depend on it.
#   cmake -DSOURCE_DIR=<repository> -DOUTPUT=<file> -P SourceCommit.cmake
set(commit unknown)
set(state unknown)
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse HEAD
                  OUTPUT_VARIABLE head RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET)
  if(rc EQUAL 0)
    set(commit ${head})
    # Tracked files only; --no-optional-locks: do not refresh the index of the checkout.
    execute_process(COMMAND ${GIT_EXECUTABLE} --no-optional-locks -C ${SOURCE_DIR} status
                            --porcelain --untracked-files=no
                    OUTPUT_VARIABLE changes RESULT_VARIABLE rc ERROR_QUIET)
    if(rc EQUAL 0 AND changes STREQUAL "")
      set(state clean)
    elseif(rc EQUAL 0)
      set(state dirty)
    endif()
  endif()
endif()
file(WRITE ${OUTPUT}.tmp "${commit} ${state}\n")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUTPUT}.tmp ${OUTPUT})
file(REMOVE ${OUTPUT}.tmp)
