# The format check (ctest `format`): every C++ file of the tree is formatted as .clang-format (and
# doc/.clang-format for the tutorials) say, by clang-format 14.
#
#   cmake -DROOT=<source dir> -DCLANG_FORMAT=<clang-format 14> -P cmake/check_format.cmake
#
# To format the tree: clang-format -i $(git ls-files '*.cc' '*.h')

if(NOT ROOT OR NOT CLANG_FORMAT)
  message(FATAL_ERROR "check_format.cmake: pass -DROOT=<source dir> -DCLANG_FORMAT=<program>")
endif()
file(GLOB_RECURSE files "${ROOT}/source/*.cc" "${ROOT}/source/*.h" "${ROOT}/include/*.h"
     "${ROOT}/tests/*.cc" "${ROOT}/tests/*.h" "${ROOT}/doc/*.cc" "${ROOT}/doc/*.h")
set(unformatted "")
foreach(file IN LISTS files)
  execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${file}
                  RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
  if(NOT result EQUAL 0)
    file(RELATIVE_PATH name "${ROOT}" "${file}")
    list(APPEND unformatted "${name}")
  endif()
endforeach()
list(LENGTH files n)
include(${CMAKE_CURRENT_LIST_DIR}/check_report.cmake)
check_report(format "${unformatted}" "file(s) not formatted (clang-format -i FILE)" ${n})
