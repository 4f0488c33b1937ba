# Run a scene and compare its screen output with the expected one.
#
#   cmake -DMPIEXEC=<mpirun> -DMPIEXEC_NUMPROC_FLAG=-np -DNP=<n>
#         -DPROGRAM=<dualcontact> -DPRM=<scene.prm> -DEXPECTED=<name.out>
#         -DNUMDIFF=<numdiff> -DWORK_DIR=<dir> -P run_regression.cmake
#
# `mpirun -np NP dualcontact PRM` runs in WORK_DIR (emptied first); its stdout
# goes to WORK_DIR/screen.out and is compared with EXPECTED by numdiff with a
# relative tolerance of 1e-6 (absolute 1e-12), numbers being split at blanks
# and at = : , ( ). The scene must set <Output/Print timing> = false.
#
# With the environment variable DUALCONTACT_UPDATE_EXPECTED=1 the output is
# copied to EXPECTED instead (after a deliberate change; review the diff).

cmake_minimum_required(VERSION 3.13)

foreach(_var MPIEXEC MPIEXEC_NUMPROC_FLAG NP PROGRAM PRM EXPECTED NUMDIFF WORK_DIR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "run_regression.cmake: -D${_var}=... is required.")
  endif()
endforeach()
if(NOT NUMDIFF OR NUMDIFF MATCHES "NOTFOUND$")
  message(FATAL_ERROR "numdiff was not found when the build was configured "
    "(Debian: apt-get install numdiff, then re-run cmake).")
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(_actual "${WORK_DIR}/screen.out")

set(_command ${MPIEXEC} ${MPIEXEC_NUMPROC_FLAG} ${NP} ${PROGRAM} ${PRM})
string(REPLACE ";" " " _command_text "${_command}")
message(STATUS "in ${WORK_DIR}: ${_command_text}")
execute_process(
  COMMAND ${_command}
  WORKING_DIRECTORY "${WORK_DIR}"
  RESULT_VARIABLE _exit
  OUTPUT_FILE "${_actual}"
  ERROR_VARIABLE _stderr)
file(READ "${_actual}" _actual_text)

# Details go to the log unformatted (message() without a mode), then a short
# FATAL_ERROR fails the test.
if(NOT "${_exit}" STREQUAL "0")
  message("---------------- stdout\n${_actual_text}"
    "---------------- stderr\n${_stderr}")
  message(FATAL_ERROR "${_command_text} failed with exit code ${_exit}.")
endif()

if("$ENV{DUALCONTACT_UPDATE_EXPECTED}")
  configure_file("${_actual}" "${EXPECTED}" COPYONLY)
  message(STATUS "updated ${EXPECTED}")
  return()
endif()

if(NOT EXISTS "${EXPECTED}")
  message(FATAL_ERROR "There is no expected output ${EXPECTED}. The output "
    "was:\n${_actual_text}\n(DUALCONTACT_UPDATE_EXPECTED=1 ctest -R "
    "regression_ writes it.)")
endif()

# numdiff splits fields at these characters (blank, tab, newline and = : , ( )),
# so that "E = 2.1e+11," or "1 MPI rank(s)" give bare numbers.
set(_numdiff_options -r 1e-6 -a 1e-12 -s " \t\n=:,()")
execute_process(
  COMMAND ${NUMDIFF} -q ${_numdiff_options} "${EXPECTED}" "${_actual}"
  RESULT_VARIABLE _differ)
if(NOT "${_differ}" STREQUAL "0")
  execute_process(
    COMMAND ${NUMDIFF} ${_numdiff_options} "${EXPECTED}" "${_actual}"
    OUTPUT_VARIABLE _differences
    ERROR_VARIABLE _differences)
  file(READ "${EXPECTED}" _expected_text)
  message("---------------- numdiff\n${_differences}"
    "---------------- expected (${EXPECTED})\n${_expected_text}"
    "---------------- actual (${_actual})\n${_actual_text}"
    "---------------- stderr\n${_stderr}")
  message(FATAL_ERROR "The output differs from ${EXPECTED} (numdiff "
    "-r 1e-6 -a 1e-12, details above). If the change is intended, run "
    "DUALCONTACT_UPDATE_EXPECTED=1 ctest -R regression_ and review the diff.")
endif()
message(STATUS "output matches ${EXPECTED}")
