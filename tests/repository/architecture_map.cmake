# Checks docs/architecture.md's map of libraries and folders against the tree: every folder the picture
# under "## Libraries and folders" names exists, and every library target the build declares
# (add_library, strata_concern_library or strata_add_plugin outside tests/ and sdk/examples/) is named on
# the page. Run by ctest as
#   cmake -DSOURCE_DIR=<repository> -P architecture_map.cmake
file(READ ${SOURCE_DIR}/docs/architecture.md page)
string(FIND "${page}" "## Libraries and folders" start)
if(start EQUAL -1)
  message(FATAL_ERROR "docs/architecture.md has no section '## Libraries and folders'")
endif()
string(SUBSTRING "${page}" ${start} -1 section)
string(REGEX MATCH "```text\n([^`]*)```" picture "${section}")
set(picture "${CMAKE_MATCH_1}")
if(picture STREQUAL "")
  message(FATAL_ERROR "docs/architecture.md: '## Libraries and folders' has no ```text picture")
endif()

set(problems "")
# A folder is a word of the picture that ends in '/', written from the repository's root.
string(REGEX MATCHALL "[A-Za-z0-9_.<>-]+(/[A-Za-z0-9_.<>-]+)*/" folders "${picture}")
list(REMOVE_DUPLICATES folders)
foreach(folder IN LISTS folders)
  string(REPLACE "<name>" "source-gdal" folder_on_disk "${folder}")
  if(NOT IS_DIRECTORY ${SOURCE_DIR}/${folder_on_disk})
    string(APPEND problems "  the picture names '${folder}', which does not exist\n")
  endif()
endforeach()

file(GLOB_RECURSE lists RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/*CMakeLists.txt ${SOURCE_DIR}/cmake/*.cmake)
foreach(list_file IN LISTS lists)
  if(list_file MATCHES "^(tests|sdk/examples|build[^/]*)/")
    continue()
  endif()
  file(READ ${SOURCE_DIR}/${list_file} text)
  string(REGEX REPLACE "#[^\n]*" "" text "${text}")
  string(REGEX MATCHALL "(add_library|strata_add_plugin|strata_concern_library)\\([A-Za-z0-9_-]+[ \t\n]+[A-Za-z]" declarations "${text}")
  foreach(declaration IN LISTS declarations)
    string(REGEX REPLACE "^[a-z_]+\\(([A-Za-z0-9_-]+).*" "\\1" target "${declaration}")
    if(NOT declaration MATCHES "\\(${target}[ \t\n]+(ALIAS|IMPORTED)" AND NOT page MATCHES "[^A-Za-z0-9_-]${target}[^A-Za-z0-9_-]")
      string(APPEND problems "  ${list_file} builds '${target}', which the page does not name\n")
    endif()
  endforeach()
endforeach()

if(NOT problems STREQUAL "")
  message(FATAL_ERROR "docs/architecture.md is out of date with the tree:\n${problems}"
                      "fix: bring the picture under '## Libraries and folders' up to date")
endif()
list(LENGTH folders folder_count)
message(STATUS "docs/architecture.md: ${folder_count} folders checked, every library target named")
