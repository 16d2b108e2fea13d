# The face-rule check (ctest `face_rule`): which faces a rank evaluates and who gets a face's
# share (P always, N only where the rank owns it) is written once, in fv/face_loop.h and
# fv/face_matrix.h. The physics and everything above it (fluid, solid, ale, coupling, scenes,
# app) loop over faces with its helpers (for_each_face, add_outflow, face_value, ...): no file
# there tests a FaceKind or writes a loop over all of a mesh's faces. (Loops over a list of
# boundary faces, FVGeometry::boundary_faces(), need no rule and are allowed.)
#
#   cmake -DROOT=<source dir> -P cmake/check_face_rule.cmake     (fails with the offending lines)

if(NOT ROOT)
  message(FATAL_ERROR "check_face_rule.cmake: pass -DROOT=<fvfsi source directory>")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)

set(files "")
foreach(folder fluid solid ale coupling scenes app)
  file(GLOB_RECURSE found RELATIVE "${ROOT}" "${ROOT}/include/fvfsi/${folder}/*"
       "${ROOT}/source/${folder}/*")
  list(APPEND files ${found})
endforeach()

set(violations "")
foreach(file IN LISTS files)
  # One list entry per line (a `;` inside a line would split it and brackets would join lines:
  # replaced).
  file(READ "${ROOT}/${file}" text)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "[" "<" text "${text}")
  string(REPLACE "]" ">" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    string(STRIP "${line}" line)
    string(REPLACE "<semicolon>" "," shown "${line}")
    if(line MATCHES "FaceKind::")
      list(APPEND violations "${file}:${number}: tests a FaceKind: `${shown}`")
    elseif(line MATCHES "for \\(.*(faces\\.size\\(\\)|(\\.|->)faces\\))")
      list(APPEND violations "${file}:${number}: loops over all faces: `${shown}`")
    endif()
  endforeach()
endforeach()

list(LENGTH files n)
include(${CMAKE_CURRENT_LIST_DIR}/check_report.cmake)
check_report(face_rule "${violations}"
             "face loop(s) that apply the owner / neighbour / ghost rule by hand (use fv/face_loop.h)"
             ${n})
