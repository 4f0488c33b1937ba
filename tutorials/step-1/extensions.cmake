# The experiments of step-1's "Possibilities for extensions" whose outcome
# README.md states and whose run is short, each held by a test: step-1.prm
# with the entries of extensions/<what>.prm, compared with
# extensions/<what>.out (tutorials/CMakeLists.txt includes this file).
foreach(_what large_r proximal_weight quarter_disc half_load)
  dualcontact_regression_test(
    NAME tutorial_step-1_extension_${_what}
    PROGRAM step-1
    PRM ${CMAKE_CURRENT_LIST_DIR}/step-1.prm
    OVERRIDES ${CMAKE_CURRENT_LIST_DIR}/extensions/${_what}.prm
    NP 2
    EXPECTED ${CMAKE_CURRENT_LIST_DIR}/extensions/${_what}.out)
endforeach()
