# The experiments of step-3's "Possibilities for extensions" whose outcome
# README.md states, each held by a test: step-3.prm with the entries of
# extensions/<what>.prm, compared with extensions/<what>.out
# (tutorials/CMakeLists.txt includes this file).
foreach(_what friction_coefficient small_friction_coefficient initial_threshold
              threshold_tolerance)
  dualcontact_regression_test(
    NAME tutorial_step-3_extension_${_what}
    PROGRAM step-3
    PRM ${CMAKE_CURRENT_LIST_DIR}/step-3.prm
    OVERRIDES ${CMAKE_CURRENT_LIST_DIR}/extensions/${_what}.prm
    NP 2
    EXPECTED ${CMAKE_CURRENT_LIST_DIR}/extensions/${_what}.out)
endforeach()
