// <Discretization>: the finite element of the displacement and the mapping
// of the cells (doc/theory.md §4).
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

namespace dualcontact
{
  using namespace dealii;

  void
  DiscretizationParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Discretization");
    declarer.declare_entry(
      "Polynomial degree",
      "1",
      EntryPattern::whole_number(1, 3),
      "The polynomial degree k of the displacement's elements, FE_Q(k) in "
      "each component, and of the mapping of the cells, MappingQ(k), which "
      "follows curved boundaries (the built-in half disc and ball, the "
      "manifolds of a mesh file) at that order [-]. The contact nodes are "
      "the support points of the contact faces, with the face integrals of "
      "their shape functions as weights (positive for every k: "
      "doc/theory.md §4).");
    declarer.leave_subsection();
  }

  void
  DiscretizationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    degree = prm.get_integer("Polynomial degree");
    prm.leave_subsection();
  }
} // namespace dualcontact
