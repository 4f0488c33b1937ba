# The experiments of step-9's "Possibilities for extensions" that run another
# program than step-9 (tutorials/CMakeLists.txt registers those on step-9.prm
# from extensions/ and includes this file).
# "A flat contact" runs the dualcontact program on prm/patch.prm at
# degree 3: the pressure is exact (p L2 err at the Uzawa tolerance).
dualcontact_regression_test(
  NAME tutorial_step-9_extension_flat_contact
  PROGRAM dualcontact
  PRM ${CMAKE_CURRENT_LIST_DIR}/../../prm/patch.prm
  OVERRIDES ${CMAKE_CURRENT_LIST_DIR}/patch/flat_contact.prm
  NP 2
  TOLERANCE_ABSOLUTE 1e-8
  EXPECTED ${CMAKE_CURRENT_LIST_DIR}/patch/flat_contact.out)
