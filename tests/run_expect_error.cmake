# Run `dualcontact` on bad input and check that it fails the way it should.
#
#   cmake -DPROGRAM=<dualcontact> -DWORK_DIR=<dir>
#         [-DPRM=<file.prm>] [-DARGS=<arg>|<arg>...]
#         [-DLAUNCHER=<command>|<arg>...]
#         [-DEXPECTED_EXIT=<n>] [-DSTDERR_REGEX=<re>] [-DSTDOUT_REGEX=<re>]
#         [-DALLOWED_OUTPUT=<name>] [-DFILE=<path> -DFILE_REGEX=<re>]
#         -P run_expect_error.cmake
#
# The program runs in WORK_DIR, emptied first. The test passes if
#   - the exit code is EXPECTED_EXIT,
#   - stderr matches STDERR_REGEX and stdout matches STDOUT_REGEX (if given),
#   - WORK_DIR is still empty afterwards: bad input writes no file at all.
#     Only a run that is meant to succeed may be given ALLOWED_OUTPUT: then
#     WORK_DIR may hold that one entry (its output folder) and nothing else;
#   - the file FILE (relative to WORK_DIR), if given, matches FILE_REGEX.
# With PRM, the file is the program's argument (after those of ARGS), and
# unless EXPECTED_EXIT is given, EXPECTED_EXIT and STDERR_REGEX are what its
# leading comment says:
#   # expected exit code: 5
#   # expected message: <Material/Poisson's ratio>
# ARGS separates several arguments by '|'. LAUNCHER, if given, comes in front
# of the program and its arguments, e.g. a shell that lowers a limit first:
#   -DLAUNCHER=sh|-c|ulimit -v 2000000 && exec "$0" "$@"
# (the shell gets the program as $0 and its arguments as $@).

cmake_minimum_required(VERSION 3.13)

foreach(_var PROGRAM WORK_DIR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "run_expect_error.cmake: -D${_var}=... is required.")
  endif()
endforeach()

set(_arguments "")
if(DEFINED ARGS)
  string(REPLACE "|" ";" _arguments "${ARGS}")
endif()
set(_launcher "")
if(DEFINED LAUNCHER)
  string(REPLACE "|" ";" _launcher "${LAUNCHER}")
endif()

if(DEFINED PRM)
  if(NOT EXISTS "${PRM}")
    message(FATAL_ERROR "run_expect_error.cmake: no file ${PRM}")
  endif()
  list(APPEND _arguments "${PRM}")
  set(_exit_given FALSE)
  if(DEFINED EXPECTED_EXIT)
    set(_exit_given TRUE)
  endif()
  file(STRINGS "${PRM}" _code_line REGEX "^# expected exit code: *[0-9]+ *$")
  file(STRINGS "${PRM}" _message_line REGEX "^# expected message: ")
  if(NOT DEFINED EXPECTED_EXIT)
    if(NOT _code_line)
      message(FATAL_ERROR "${PRM} has no line '# expected exit code: <n>'.")
    endif()
    list(GET _code_line 0 _code_line)
    string(REGEX REPLACE "^# expected exit code: *([0-9]+) *$" "\\1"
      EXPECTED_EXIT "${_code_line}")
  endif()
  # a caller that gives EXPECTED_EXIT gives its own checks
  if(NOT DEFINED STDERR_REGEX AND NOT _exit_given)
    if(NOT _message_line)
      message(FATAL_ERROR "${PRM} has no line '# expected message: <regex>'.")
    endif()
    list(GET _message_line 0 _message_line)
    string(REGEX REPLACE "^# expected message: *" "" STDERR_REGEX
      "${_message_line}")
    string(STRIP "${STDERR_REGEX}" STDERR_REGEX)
  endif()
endif()

if(NOT DEFINED EXPECTED_EXIT)
  message(FATAL_ERROR "run_expect_error.cmake: -DEXPECTED_EXIT=<n> is required.")
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

string(REPLACE ";" " " _command "${_launcher} ${PROGRAM} ${_arguments}")
string(STRIP "${_command}" _command)
message(STATUS "in ${WORK_DIR}: ${_command}")
execute_process(
  COMMAND ${_launcher} ${PROGRAM} ${_arguments}
  WORKING_DIRECTORY "${WORK_DIR}"
  RESULT_VARIABLE _exit
  OUTPUT_VARIABLE _stdout
  ERROR_VARIABLE _stderr)

set(_failures "")
if(NOT "${_exit}" STREQUAL "${EXPECTED_EXIT}")
  string(APPEND _failures
    "  exit code: expected ${EXPECTED_EXIT}, got ${_exit}\n")
endif()
if(DEFINED STDERR_REGEX AND NOT "${_stderr}" MATCHES "${STDERR_REGEX}")
  string(APPEND _failures
    "  stderr does not match the regular expression '${STDERR_REGEX}'\n")
endif()
if(DEFINED STDOUT_REGEX AND NOT "${_stdout}" MATCHES "${STDOUT_REGEX}")
  string(APPEND _failures
    "  stdout does not match the regular expression '${STDOUT_REGEX}'\n")
endif()
if(DEFINED FILE)
  if(NOT EXISTS "${WORK_DIR}/${FILE}")
    string(APPEND _failures "  the run wrote no file ${FILE}\n")
  else()
    file(READ "${WORK_DIR}/${FILE}" _file_text)
    if(NOT "${_file_text}" MATCHES "${FILE_REGEX}")
      string(APPEND _failures
        "  ${FILE} does not match the regular expression '${FILE_REGEX}'\n")
    endif()
  endif()
endif()
file(GLOB _left_behind LIST_DIRECTORIES true RELATIVE "${WORK_DIR}"
  "${WORK_DIR}/*" "${WORK_DIR}/.*")
if(DEFINED ALLOWED_OUTPUT)
  list(REMOVE_ITEM _left_behind "${ALLOWED_OUTPUT}")
endif()
if(_left_behind)
  string(REPLACE ";" ", " _left_behind "${_left_behind}")
  string(APPEND _failures
    "  the run created files or directories in its working directory: "
    "${_left_behind}\n")
endif()

# Details go to the log unformatted (message() without a mode), then a short
# FATAL_ERROR fails the test.
if(_failures)
  message("${_command}\n${_failures}"
    "---------------- stdout\n${_stdout}"
    "---------------- stderr\n${_stderr}")
  message(FATAL_ERROR "the bad input was not handled as expected (see above)")
endif()

message(STATUS "exit code ${_exit} as expected")
if(DEFINED STDERR_REGEX)
  message(STATUS "stderr matches '${STDERR_REGEX}'")
endif()
if(DEFINED STDOUT_REGEX)
  message(STATUS "stdout matches '${STDOUT_REGEX}'")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
