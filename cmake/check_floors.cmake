# The floor check (ctest `floors`): fvfsi's folders are floors, and a file may include fvfsi
# headers only from its own folder or from a lower floor. Folders on one floor are siblings and do
# not include each other. The order, lowest first, is written once, here:
set(FVFSI_FLOORS
    "base"                     # exceptions, expressions, patch lists, the clock
    "mesh"                     # building meshes, FV geometry, swept volumes
    "fv,io"                    # FV operators and solvers; output
    "fluid,solid,ale,coupling" # the physics, mesh motion, the interface
    "scenes"                   # the programs
    "app")                     # command line, parameter file, dispatch
# The same folder names under include/fvfsi/ and source/; source/main.cc is on the app floor.
#
#   cmake -DROOT=<source dir> -P cmake/check_floors.cmake     (fails with the offending lines)

if(NOT ROOT)
  message(FATAL_ERROR "check_floors.cmake: pass -DROOT=<fvfsi source directory>")
endif()

get_filename_component(ROOT "${ROOT}" ABSOLUTE)
# LEVEL_<folder>: the floor number of every folder.
set(level 0)
foreach(floor IN LISTS FVFSI_FLOORS)
  string(REPLACE "," ";" folders "${floor}")
  foreach(folder IN LISTS folders)
    set(LEVEL_${folder} ${level})
  endforeach()
  math(EXPR level "${level} + 1")
endforeach()

file(GLOB_RECURSE files RELATIVE "${ROOT}" "${ROOT}/include/fvfsi/*" "${ROOT}/source/*")
set(violations "")
foreach(file IN LISTS files)
  if(file STREQUAL "source/main.cc")
    set(folder app)
  else()
    string(REGEX REPLACE "^(include/fvfsi|source)/([^/]+)/.*$" "\\2" folder "${file}")
  endif()
  if(NOT DEFINED LEVEL_${folder})
    list(APPEND violations "${file}: folder `${folder}` is on no floor (add it to cmake/check_floors.cmake)")
    continue()
  endif()
  file(STRINGS "${ROOT}/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]fvfsi/")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^.*[<\"]fvfsi/([^/]+)/.*$" "\\1" target "${line}")
    if(NOT DEFINED LEVEL_${target})
      list(APPEND violations "${file}: `${line}` includes folder `${target}`, which is on no floor")
    elseif(NOT target STREQUAL folder AND NOT LEVEL_${target} LESS LEVEL_${folder})
      list(APPEND violations "${file}: `${line}`: ${folder}/ (floor ${LEVEL_${folder}}) may not include ${target}/ (floor ${LEVEL_${target}})")
    endif()
  endforeach()
endforeach()

list(LENGTH files n)
include(${CMAKE_CURRENT_LIST_DIR}/check_report.cmake)
check_report(floor "${violations}" "include(s) against the floors (base < mesh < fv, io < fluid, solid, ale, coupling < scenes < app)" ${n})
