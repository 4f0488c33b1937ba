# The experiments of step-4's "Possibilities for extensions" whose outcome
# README.md states, each held by a test: step-4.prm with the entries of
# extensions/<what>.prm, compared with extensions/<what>.out
# (tutorials/CMakeLists.txt includes this file).
foreach(_what similarity)
  dualcontact_regression_test(
    NAME tutorial_step-4_extension_${_what}
    PROGRAM step-4
    PRM ${CMAKE_CURRENT_LIST_DIR}/step-4.prm
    OVERRIDES ${CMAKE_CURRENT_LIST_DIR}/extensions/${_what}.prm
    NP 2
    EXPECTED ${CMAKE_CURRENT_LIST_DIR}/extensions/${_what}.out)
endforeach()
