# The experiment of step-2's "Possibilities for extensions" that runs with
# step-2.prm and one changed entry, held by a test: step-2.prm with the
# entries of extensions/<what>.prm, compared with extensions/<what>.out
# (tutorials/CMakeLists.txt includes this file). The other experiments
# change the program itself; README.md states their outcomes.
foreach(_what large_r)
  dualcontact_regression_test(
    NAME tutorial_step-2_extension_${_what}
    PROGRAM step-2
    PRM ${CMAKE_CURRENT_LIST_DIR}/step-2.prm
    OVERRIDES ${CMAKE_CURRENT_LIST_DIR}/extensions/${_what}.prm
    NP 2
    EXPECTED ${CMAKE_CURRENT_LIST_DIR}/extensions/${_what}.out)
endforeach()
