# Writes OUT (a C++ source defining agglo::kGitHash) with the commit of SRC's checkout, at every build
# (CMakeLists.txt, target agglo_git_hash), so that an incremental build after a commit records that
# commit and not the one of its configure step. The file is rewritten only when the hash changes, so an
# unchanged checkout recompiles nothing.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${SRC}
                OUTPUT_VARIABLE hash OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT hash)
  set(hash "unknown")
endif()
set(text "// Generated at build time by cmake/git_hash.cmake.\n#include \"agglo/core/version.hpp\"\nnamespace agglo {\nconst char* const kGitHash = \"${hash}\";\n}  // namespace agglo\n")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE ${OUT} "${text}")
endif()
