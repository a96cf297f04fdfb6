# Runs CMD (arguments separated by "|") and passes if it exits with a
# non-zero status and its standard output and error together match REGEX:
# a clean failure, neither a success nor a crash with no message. With RC,
# the exit code must be that one.
string(REPLACE "|" ";" command "${CMD}")
execute_process(COMMAND ${command} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("exit status: ${rc}\n--- stdout:\n${out}\n--- stderr:\n${err}")
if(rc EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit status")
endif()
if(NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "the command did not exit normally: ${rc}")
endif()
if(DEFINED RC AND NOT rc EQUAL RC)
  message(FATAL_ERROR "expected exit code ${RC}")
endif()
if(NOT "${out}${err}" MATCHES "${REGEX}")
  message(FATAL_ERROR "output does not match ${REGEX}")
endif()
