# Runs one command and checks its exit status and output; used by cli_tests.cmake.
#   cmake -DCOMMAND="prog|arg1|arg2" -DEXPECT_RC=2 -DEXPECT_REGEX="solver\\.dt" -P expect_exit.cmake
# COMMAND separates the program and its arguments with '|' (not ';', which CTest would split
# and which --set values may need). EXPECT_REGEX (optional; empty = any output) is matched
# against stdout and stderr together; EXPECT_REGEX=<nothing> asks for no output at all.
foreach(var COMMAND EXPECT_RC)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_exit.cmake: -D${var}=... is required")
  endif()
endforeach()

string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command}
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
set(output "${out}${err}")

# rc is a number, or text such as "Segmentation fault" when the program crashed: both must equal
# the expected status exactly (a crash is never a pass, nor is exit 1 where 2 is due).
if(NOT "${rc}" STREQUAL "${EXPECT_RC}")
  message(FATAL_ERROR "exit status ${rc}, expected ${EXPECT_RC}\n"
    "command: ${command}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if("${EXPECT_REGEX}" STREQUAL "<nothing>")
  if(NOT "${output}" STREQUAL "")
    message(FATAL_ERROR "expected no output\ncommand: ${command}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
elseif(NOT "${EXPECT_REGEX}" STREQUAL "" AND NOT "${output}" MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match /${EXPECT_REGEX}/\n"
    "command: ${command}\nstdout:\n${out}\nstderr:\n${err}")
endif()
message(STATUS "ok: exit ${rc}, output matches /${EXPECT_REGEX}/")
