# The verdict of a tree check (included by check_floors.cmake and check_format.cmake):
#   check_report(NAME FINDINGS HEADLINE CHECKED)
# fails with HEADLINE and one finding per line when the list FINDINGS is not empty, else reports
# that NAME checked CHECKED files.
function(check_report name findings headline checked)
  if(findings)
    list(LENGTH findings n)
    string(REPLACE ";" "\n  " text "${findings}")
    message(FATAL_ERROR "${name} check: ${n} ${headline}:\n  ${text}")
  endif()
  message(STATUS "${name} check: ${checked} files, all pass")
endfunction()
