# The experiments of README.md's "Possibilities for extensions" whose outcome
# the README states: this program on step-6.prm with the experiment's
# entries (the OVERRIDES file), its screen output held by EXPECTED.
# Included by tutorials/CMakeLists.txt.
foreach(_experiment no_manifold contact_weight)
  dualcontact_regression_test(
    NAME tutorial_step-6_extension_${_experiment}
    PROGRAM step-6
    PRM ${CMAKE_CURRENT_LIST_DIR}/step-6.prm
    OVERRIDES ${CMAKE_CURRENT_LIST_DIR}/extension_${_experiment}.prm
    NP 2
    EXPECTED ${CMAKE_CURRENT_LIST_DIR}/extension_${_experiment}.out)
endforeach()
