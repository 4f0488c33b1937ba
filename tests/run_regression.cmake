# Run a program on a parameter file and compare its screen output with the
# expected one. Called by the tests that dualcontact_regression_test() (in
# tests/CMakeLists.txt) adds:
#
#   cmake -DNAME=<test name> -DMPIEXEC=<mpirun> -DMPIEXEC_NUMPROC_FLAG=-np
#         -DNP=<n> -DPROGRAM=<program> -DPRM=<scene.prm> -DEXPECTED=<name.out>
#         -DNUMDIFF=<numdiff> -DWORK_DIR=<dir>
#         [-DOVERRIDES=<file with extra prm lines>]
#         [-DTOLERANCE_RELATIVE=<r>] [-DTOLERANCE_ABSOLUTE=<a>]
#         [-DNOISY_LINES=<regex>|NONE]
#         -P run_regression.cmake
#
# 1. WORK_DIR is emptied, and WORK_DIR/scene.prm written: the text of PRM,
#    then the lines of OVERRIDES (if given), then
#        subsection Output
#          set Print timing = false
#          set Write vtu    = false
#          set Directory    = output
#        end
#    A relative <Geometry/Mesh file> or include is made absolute (from PRM's
#    folder).
#    An entry set twice in a parameter file is an error (exit status 4), so
#    the 'set' lines of PRM for the entries that OVERRIDES or the Output
#    block set are left out of scene.prm (found by subsection and name; PRM
#    must not use '\' continuation lines or 'include' for them). So OVERRIDES
#    can change any entry of PRM (e.g. fewer Refinement/Number of cycles),
#    and the Output block always holds: no wall times on screen, no .vtu
#    files, everything written to WORK_DIR/output/. An override of an entry
#    that does not exist fails like any unknown entry (exit status 4), so a
#    misspelt override cannot pass unnoticed.
# 2. `mpirun -np NP PROGRAM scene.prm` runs in WORK_DIR; its stdout goes to
#    WORK_DIR/screen.raw.out.
# 3. Wall times that the program prints even with Print timing = false are
#    replaced by '-' (the last four columns, refine/assemble/solve/total, of
#    the rows of dualcontact's "Convergence table (...; times in s)", and
#    "time <t> s vs <t> s" of the cold-start comparison); the result,
#    WORK_DIR/screen.out, is what is compared. Nothing else is changed.
# 4. screen.out is compared with EXPECTED by numdiff, in two passes
#    (tolerances below).
#
# With the environment variable DUALCONTACT_UPDATE_EXPECTED=1, screen.out is
# copied to EXPECTED instead (after a deliberate change, or to create the file
# of a new test; review the diff before committing it).
#
# ---------------------------------------------------------------- tolerances
# numdiff splits every line into fields at blanks and at = : , ( ) (so that
# "E = 2.1e+11," or "21(0)" give bare numbers). Words must match exactly; two
# numbers x and y count as equal if
#     |x - y| <= a   or   |x - y| / min(|x|, |y|) <= r
# (numdiff without -2). A line more or less (one more Uzawa step) is always a
# difference, whatever the tolerances. There are two comparisons:
#
# (1) Everything except the per-iteration residual figures, with
#     r = TOLERANCE_RELATIVE (default 1e-5), a = TOLERANCE_ABSOLUTE (default
#     1e-9). The residual figures are the 3-digit numbers like 2.38e-05 on the
#     lines that match NOISY_LINES (default: the rows of dualcontact's
#     Uzawa table, "   Uzawa   <k> ...", and step-1's own "   Uzawa   <k>:"
#     lines; "   threshold step", "   Uzawa contraction rate" and, at
#     Output/Verbosity = detailed, "      Newton <j>:"); both files are
#     compared with those figures replaced by '~'. All integers on those
#     lines (Newton, CG, active, stick/slip) stay in this comparison.
#       - Iteration counts (Uzawa, Newton, CG, loop 1 steps, AMG set-ups,
#         nodes in contact, stick/slip) are integers below a few thousand:
#         one more is an absolute change of 1 >> a and a relative change
#         >= 2e-4 >> r, so every changed count fails.
#       - Results (total contact and tangential force, peak pressure,
#         half-widths, pressure/half-width/peak errors, ||u||_L2) are printed
#         with 7 or 8 significant digits, so r = 1e-5 is what the printed
#         digits resolve to within a factor ~10..100, and a relative change of
#         1e-4 is 10 times r: it fails, provided it also exceeds a. The
#         smallest such value in the scenes' output is a peak error of
#         2.6e-4 (hertz_adaptive): its 1e-4 change, 2.6e-8, is 26 times
#         a = 1e-9. ||u||_L2 is 8e-4 or more in the scenes; a test whose
#         results are smaller (regression_elastic_half_disc: ||u|| = 1e-6)
#         sets a smaller TOLERANCE_ABSOLUTE.
#       - Measured round-off noise (each scene run with Young's modulus or
#         Poisson's ratio changed by one unit in the last place, 1e-16
#         relative, which perturbs every operation like a reordered sum or
#         another compiler would): results moved by at most 5.5e-8
#         relatively (r = 1e-5 has a margin of 180), and the total
#         tangential force of hertz_friction, zero by symmetry, moved between
#         1e-11 and 1.1e-10 (a = 1e-9 has a margin of 10). Iteration counts of
#         Uzawa, Newton and loop 1 never moved; CG counts of single Uzawa
#         steps did move by 1 or 2 in sliding_block and hertz_friction:
#         such a change fails, as every changed count must.
# (2) The residual figures themselves, loosely: r = 1 (a factor of 2),
#     a = 1e-8. They are relative changes, violations, complementarity
#     (down to 1e-13) and the contraction rate of the last two; the inner
#     solves are inexact, so the same perturbation moved them by up to 32 %
#     (3.01e-08 vs 4.43e-08; 2.38e-05 vs 2.44e-05; the rate 1.29e-01 vs
#     1.02e-01), 60 % below 1e-10. With r = 1e-5 and any a that small
#     (a < 2.6e-8 is needed above), such noise would fail every scene. This
#     comparison still catches a convergence history that changed by more
#     than a factor of 2 without changing a count.
# An identical build gives bit-identical output (every test was run twice),
# so the tolerances only matter across compilers, libraries and refactorings
# that reorder floating-point operations.

cmake_minimum_required(VERSION 3.13)

foreach(_var NAME MPIEXEC MPIEXEC_NUMPROC_FLAG NP PROGRAM PRM EXPECTED NUMDIFF
             WORK_DIR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "run_regression.cmake: -D${_var}=... is required.")
  endif()
endforeach()
if(NOT DEFINED TOLERANCE_RELATIVE OR "${TOLERANCE_RELATIVE}" STREQUAL "")
  set(TOLERANCE_RELATIVE 1e-5)
endif()
if(NOT DEFINED TOLERANCE_ABSOLUTE OR "${TOLERANCE_ABSOLUTE}" STREQUAL "")
  set(TOLERANCE_ABSOLUTE 1e-9)
endif()
if(NOT DEFINED NOISY_LINES OR "${NOISY_LINES}" STREQUAL "")
  set(NOISY_LINES "   Uzawa +[0-9]+[: ]|   threshold step|   Uzawa contraction rate|      Newton +[0-9]+:")
endif()
set(_noisy_relative 1)
set(_noisy_absolute 1e-8)
if(NOT NUMDIFF OR NUMDIFF MATCHES "NOTFOUND$")
  message(FATAL_ERROR "numdiff was not found when the build was configured "
    "(Debian: apt-get install numdiff, then re-run cmake).")
endif()
if(NOT EXISTS "${PRM}")
  message(FATAL_ERROR "${NAME}: there is no parameter file ${PRM}.")
endif()
if(DEFINED OVERRIDES AND NOT "${OVERRIDES}" STREQUAL "" AND
   NOT EXISTS "${OVERRIDES}")
  message(FATAL_ERROR "${NAME}: there is no override file ${OVERRIDES}.")
endif()

set(_update_hint "DUALCONTACT_UPDATE_EXPECTED=1 ctest -R '^${NAME}$'")

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# ------------------------------------------------------------ scene file
# The lines of a .prm text as a CMake list; ';', '[' and ']' (list syntax)
# are spelt <sc>, <lb>, <rb> until _prm_text() puts them back.
function(_prm_lines text out)
  string(REPLACE ";" "<sc>" text "${text}")
  string(REPLACE "[" "<lb>" text "${text}")
  string(REPLACE "]" "<rb>" text "${text}")
  string(REPLACE "\n" ";" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

function(_prm_text lines out)
  string(REPLACE ";" "\n" text "${lines}")
  string(REPLACE "<sc>" ";" text "${text}")
  string(REPLACE "<lb>" "[" text "${text}")
  string(REPLACE "<rb>" "]" text "${text}")
  set(${out} "${text}\n" PARENT_SCOPE)
endfunction()

# Walk the lines of a .prm text: `keys` gets "Subsection/Entry" of every
# 'set' line; `kept` gets the lines, without the 'set' lines of `drop`.
function(_prm_walk lines drop keys kept)
  set(_path "")
  set(_keys "")
  set(_kept "")
  foreach(_line IN LISTS lines)
    string(REGEX REPLACE "#.*" "" _code "${_line}")
    string(STRIP "${_code}" _code)
    set(_keep TRUE)
    if(_code MATCHES "^(subsection|SUBSECTION) +(.*)$")
      string(STRIP "${CMAKE_MATCH_2}" _name)
      list(APPEND _path "${_name}")
    elseif(_code MATCHES "^(end|END)$")
      list(LENGTH _path _depth)
      if(_depth GREATER 0)
        list(REMOVE_AT _path -1)
      endif()
    elseif(_code MATCHES "^(set|SET) +([^=]*)=")
      string(STRIP "${CMAKE_MATCH_2}" _name)
      string(REPLACE ";" "/" _key "${_path}")
      set(_key "${_key}/${_name}")
      list(APPEND _keys "${_key}")
      if("${_key}" IN_LIST drop)
        set(_keep FALSE)
        set(_line "# (run_regression.cmake: set below) ${_line}")
      endif()
    endif()
    list(APPEND _kept "${_line}")
  endforeach()
  set(${keys} "${_keys}" PARENT_SCOPE)
  set(${kept} "${_kept}" PARENT_SCOPE)
endfunction()

set(_overlay "")
if(DEFINED OVERRIDES AND NOT "${OVERRIDES}" STREQUAL "")
  file(READ "${OVERRIDES}" _overrides)
  string(APPEND _overlay
    "\n# ---- run_regression.cmake: overrides from ${OVERRIDES}\n"
    "${_overrides}\n")
endif()
string(APPEND _overlay
  "\n# ---- run_regression.cmake: always\n"
  "subsection Output\n"
  "  set Print timing = false\n"
  "  set Write vtu    = false\n"
  "  set Directory    = output\n"
  "end\n")
file(READ "${PRM}" _scene)
# scene.prm is written to WORK_DIR, so a relative <Geometry/Mesh file> or
# include (taken from the folder of the file that names it) is made absolute
# from PRM's folder
get_filename_component(_prm_folder "${PRM}" DIRECTORY)
string(REGEX REPLACE "(\n[ \t]*set[ \t]+Mesh file[ \t]*=[ \t]*)([^/ \t\n#][^\n#]*)"
  "\\1${_prm_folder}/\\2" _scene "${_scene}")
string(REGEX REPLACE "(\n[ \t]*include[ \t]+)([^/ \t\n#][^\n#]*)"
  "\\1${_prm_folder}/\\2" _scene "${_scene}")
_prm_lines("${_overlay}" _overlay_lines)
_prm_walk("${_overlay_lines}" "" _overlay_keys _unused)
_prm_lines("${_scene}" _scene_lines)
_prm_walk("${_scene_lines}" "${_overlay_keys}" _unused _scene_lines)
_prm_text("${_scene_lines}" _scene)
string(APPEND _scene "${_overlay}")
set(_scene_file "${WORK_DIR}/scene.prm")
file(WRITE "${_scene_file}" "${_scene}")

# ------------------------------------------------------------ run
set(_raw "${WORK_DIR}/screen.raw.out")
set(_actual "${WORK_DIR}/screen.out")
set(_command ${MPIEXEC} ${MPIEXEC_NUMPROC_FLAG} ${NP} ${PROGRAM} scene.prm)
string(REPLACE ";" " " _command_text "${_command}")
message(STATUS "in ${WORK_DIR}: ${_command_text}")
execute_process(
  COMMAND ${_command}
  WORKING_DIRECTORY "${WORK_DIR}"
  RESULT_VARIABLE _exit
  OUTPUT_FILE "${_raw}"
  ERROR_VARIABLE _stderr)
file(READ "${_raw}" _actual_text)

# Details go to the log unformatted (message() without a mode), then a short
# FATAL_ERROR fails the test.
if(NOT "${_exit}" STREQUAL "0")
  message("---------------- scene file (${_scene_file})\n${_scene}"
    "---------------- stdout\n${_actual_text}"
    "---------------- stderr\n${_stderr}")
  message(FATAL_ERROR "${NAME}: ${_command_text} failed with exit code "
    "${_exit}.")
endif()

# ------------------------------------------------------------ wall times out
# Only after the convergence table's header, whose rows end in the four time
# columns (each printed as %.3f): replace each of those four numbers by '-'.
string(FIND "${_actual_text}" "times in s):" _table)
if(_table GREATER -1)
  string(SUBSTRING "${_actual_text}" 0 ${_table} _head)
  string(SUBSTRING "${_actual_text}" ${_table} -1 _tail)
  set(_time " +[0-9]+\\.[0-9][0-9][0-9]")
  string(REGEX REPLACE "${_time}${_time}${_time}${_time}\n"
    "        -         -        -       -\n" _tail "${_tail}")
  set(_actual_text "${_head}${_tail}")
endif()
string(REGEX REPLACE "time [-+.0-9eE]+ s vs [-+.0-9eE]+ s" "time - s vs - s"
  _actual_text "${_actual_text}")
file(WRITE "${_actual}" "${_actual_text}")

# ------------------------------------------------------------ compare
if("$ENV{DUALCONTACT_UPDATE_EXPECTED}")
  configure_file("${_actual}" "${EXPECTED}" COPYONLY)
  message(STATUS "updated ${EXPECTED}")
  return()
endif()

if(NOT EXISTS "${EXPECTED}")
  message("---------------- output (${_actual})\n${_actual_text}")
  message(FATAL_ERROR "${NAME}: there is no expected output ${EXPECTED}. "
    "Create it from the output above by running, in the build directory,\n"
    "  ${_update_hint}\n"
    "then review the new file and add it to git.")
endif()

# Both files with the residual figures of the NOISY_LINES replaced by '~'
# (NOISY_LINES is a regular expression for the start of such a line; NONE: no
# line is).
function(_mask_residual_figures input output)
  file(READ "${input}" _text)
  if(NOT "${NOISY_LINES}" STREQUAL "NONE")
    set(_text "\n${_text}")
    set(_figure "[0-9]\\.[0-9][0-9]e[-+][0-9][0-9]")
    # each pass replaces the last remaining figure of every such line
    while(TRUE)
      string(REGEX REPLACE "(\n(${NOISY_LINES})[^\n]*[ =:,(])${_figure}"
        "\\1~" _masked "${_text}")
      if("${_masked}" STREQUAL "${_text}")
        break()
      endif()
      set(_text "${_masked}")
    endwhile()
    string(SUBSTRING "${_text}" 1 -1 _text)
  endif()
  file(WRITE "${output}" "${_text}")
endfunction()
_mask_residual_figures("${EXPECTED}" "${WORK_DIR}/expected.masked.out")
_mask_residual_figures("${_actual}" "${WORK_DIR}/screen.masked.out")

# numdiff splits fields at these characters (blank, tab, newline and = : , ( )),
# so that "E = 2.1e+11," or "1 MPI rank(s)" give bare numbers.
set(_separators -s " \t\n=:,()")
set(_passes strict loose)
set(_strict_files "${WORK_DIR}/expected.masked.out" "${WORK_DIR}/screen.masked.out")
set(_strict_options -r ${TOLERANCE_RELATIVE} -a ${TOLERANCE_ABSOLUTE})
set(_strict_what "everything but the residual figures of the iteration lines")
set(_loose_files "${EXPECTED}" "${_actual}")
set(_loose_options -r ${_noisy_relative} -a ${_noisy_absolute})
set(_loose_what "the residual figures of the iteration lines")
foreach(_pass ${_passes})
  execute_process(
    COMMAND ${NUMDIFF} -q ${_${_pass}_options} ${_separators} ${_${_pass}_files}
    RESULT_VARIABLE _differ)
  if(NOT "${_differ}" STREQUAL "0")
    execute_process(
      COMMAND ${NUMDIFF} ${_${_pass}_options} ${_separators} ${_${_pass}_files}
      OUTPUT_VARIABLE _differences
      ERROR_VARIABLE _differences)
    string(REPLACE ";" " " _options_text "${_${_pass}_options}")
    file(READ "${EXPECTED}" _expected_text)
    message("---------------- numdiff ${_options_text} (${_${_pass}_what})\n"
      "${_differences}"
      "---------------- expected (${EXPECTED})\n${_expected_text}"
      "---------------- actual (${_actual})\n${_actual_text}"
      "---------------- stderr\n${_stderr}")
    message(FATAL_ERROR "${NAME}: the output differs from ${EXPECTED} in "
      "${_${_pass}_what} (numdiff ${_options_text}, details above). If the "
      "change is intended, run\n  ${_update_hint}\nand review the diff.")
  endif()
endforeach()
message(STATUS "output matches ${EXPECTED}")
