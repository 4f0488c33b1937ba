// <Solver>: CG + AMG for the linear systems, the Uzawa iteration and, inside
// each of its steps, the Newton iteration.
#include <deal.II/base/utilities.h>

#include <dualcontact/friction_law.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

#include <cmath>
#include <cstdlib>

namespace dualcontact
{
  using namespace dealii;

  namespace
  {
    /** CG and its AMG: tolerance, iterations, near-null space. */
    void
    declare_linear_solver_entries(EntryDeclarer &declarer)
    {
      declarer.declare_entry(
        "Linear solver tolerance",
        "1e-10",
        EntryPattern::number(1e-16, 1.),
        "Relative tolerance of CG: stop when |residual| <= tol "
        "|right-hand side| [-].");
      declarer.declare_entry(
        "Maximum linear iterations",
        "2000",
        EntryPattern::whole_number(1),
        "Maximum number of CG iterations per linear solve [-].");
      declarer.declare_entry(
        "AMG with rotation modes",
        "true",
        EntryPattern::boolean(),
        "Give the algebraic multigrid all rigid-body modes (translations and "
        "rotations) as near-null space; false gives it the translations only.");
    }

    /** The Uzawa iteration: the augmentation and proximal parameters, its
     * tolerance and steps. */
    void
    declare_uzawa_entries(EntryDeclarer &declarer)
    {
      declarer.declare_entry(
        "Augmentation parameter",
        "10",
        EntryPattern::number(1e-3, 1e12),
        "r_rel [-], > 0: the augmentation parameter of the modified Lagrangian "
        "is r = r_rel (lambda + 2 mu) / h_k [stress/length], with h_k = h_C / "
        "k the spacing of the contact nodes (h_C the smallest face diameter "
        "on the contact boundary, k the polynomial degree) and lambda + 2 mu "
        "the P-wave modulus (E (1 - nu) / ((1 + nu) (1 - 2 nu)); 1.35 E at nu = "
        "0.3), which follows the stiffness of nearly incompressible materials. "
        "Any r > 0 converges; larger r means fewer Uzawa steps and harder "
        "Newton problems (more Newton steps where many nodes slip), smaller r "
        "more Uzawa steps (below 0.1, more than the default <Solver/Maximum "
        "Uzawa steps>). From 1e-3 to 1e12: below, the contact terms vanish "
        "beside the proximal term and the body drifts for thousands of "
        "steps.");
      declarer.declare_entry(
        "Tangential augmentation parameter",
        "auto",
        EntryPattern::text(),
        "r_t,rel [-]: 'auto' or a number > 0. The friction terms use their own "
        "augmentation r_t = r_t,rel (lambda + 2 mu) / h_k [stress/length] (as "
        "r, with r_t,rel for r_rel), in the update l2 <- proj_g(l2 + r_t v_t) "
        "and in the Newton terms of l2. 'auto' is r_rel in 2D and r_rel / 4 in "
        "3D: in 3D, friction terms as large as the normal ones make the "
        "Newton matrices hard for CG and need 3-4 Newton steps per Uzawa "
        "step (the projection onto the friction disc), and r_rel / 4 halves "
        "the Coulomb solves; in 2D (an interval, no disc) a smaller r_t only "
        "costs Uzawa steps (doc/theory.md §5). Ignored without friction.");
      declarer.declare_entry(
        "Proximal parameter",
        "1e-3",
        EntryPattern::number(0., 1e3),
        "chi_rel [-], > 0: the proximal weight is chi = chi_rel E / L^2 "
        "[stress/length^2], with L the body's size (longest side, or radius). "
        "It makes each Uzawa step strongly convex, also when only contact "
        "holds the body. At most 1e3: a proximal term that outweighs the "
        "stiffness of coarse meshes (chi_rel 1e6 on 8 x 4 cells) holds v "
        "where it is, and the Newton and Uzawa iterations stall; from 1 on "
        "the Uzawa steps already stop before the solution is reached to the "
        "tolerance (doc/robustness.md).");
      declarer.declare_entry(
        "Uzawa tolerance",
        "1e-8",
        EntryPattern::number(1e-15, 1.),
        "The Uzawa iteration stops when the relative changes of l1 and of v "
        "and the relative constraint violation are all below "
        "this [-].");
      declarer.declare_entry(
        "Maximum Uzawa steps",
        "500",
        EntryPattern::whole_number(1),
        "The Uzawa iteration gives up (with an error) after this many steps "
        "[-].");
    }

    /** The Newton iteration inside each Uzawa step: its tolerances, steps,
     * line search, and the reuse of its AMG. */
    void
    declare_newton_entries(EntryDeclarer &declarer)
    {
      declarer.declare_entry(
        "Newton tolerance factor",
        "1e-2",
        EntryPattern::number(1e-8, 1.),
        "The Newton iteration's final tolerance on the relative gradient is this factor "
        "times the Uzawa tolerance [-] (at most 0.01 is advised).");
      declarer.declare_entry(
        "Newton initial tolerance",
        "1e-2",
        EntryPattern::number(0., 1.),
        "The Newton iteration's relative gradient tolerance in the first Uzawa step [-]; it "
        "shrinks geometrically from step to step (summable errors, as the "
        "convergence theorem needs) down to the final tolerance.");
      declarer.declare_entry(
        "Newton tolerance reduction",
        "0.5",
        EntryPattern::number(0., 1.),
        "The Newton iteration's tolerance stays below its initial tolerance times "
        "this factor to the power (Uzawa step - 1) [-], in "
        "(0, 1): a geometric envelope that keeps the errors "
        "summable.");
      declarer.declare_entry(
        "Newton gradient reduction",
        "1e-2",
        EntryPattern::number(0., 1.),
        "The Newton iteration stops once its gradient fell by this factor "
        "within the Uzawa step (and is below the envelope), or "
        "is below the final tolerance [-]: no Uzawa step is "
        "solved much more accurately than the iteration can "
        "use.");
      declarer.declare_entry(
        "Maximum Newton steps",
        "50",
        EntryPattern::whole_number(1),
        "The Newton iteration gives up (with an error) after this many full "
        "steps in one Uzawa step [-]. Steps that the line search cuts short "
        "at a change of the node statuses (gross slip with a large r) come "
        "on top, at most one per contact node.");
      declarer.declare_entry(
        "Line search",
        "true",
        EntryPattern::boolean(),
        "Line search on the Uzawa step's functional (a convex piecewise "
        "quadratic along each Newton direction): the full step when it "
        "passes Armijo's sufficient-decrease test, else the minimiser along "
        "the direction; makes Newton globally convergent. false: full "
        "steps.");
      declarer.declare_entry(
        "AMG rebuild fraction",
        "0.05",
        EntryPattern::number(0., 1.),
        "Rebuild the AMG preconditioner of the Newton matrix only when the "
        "number of contact nodes that changed status since it was built "
        "exceeds this fraction of the active set [-], or when the last CG "
        "solve needed more than 1.5 times (plus 10) the iterations of the "
        "first one after the set-up; 0 rebuilds it at every Newton step.");
    }

    /** The timing of a reference linear solve, for benchmarks. */
    void
    declare_reference_solve_entry(EntryDeclarer &declarer)
    {
      declarer.declare_entry(
        "Time a reference linear solve",
        "false",
        EntryPattern::boolean(),
        "After each contact solve, also time one linear elasticity solve on "
        "the same mesh (AMG set-up and CG to the linear tolerance on the final "
        "Newton matrix, i.e. with the contact nodes held) and report the ratio "
        "of the times (assembly included in both). For benchmarks.");
    }
  } // namespace

  void
  SolverParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Solver");
    declare_linear_solver_entries(declarer);
    declare_uzawa_entries(declarer);
    declare_newton_entries(declarer);
    declare_reference_solve_entry(declarer);
    declarer.leave_subsection();
  }

  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    linear_tolerance      = prm.get_double("Linear solver tolerance");
    max_linear_iterations = prm.get_integer("Maximum linear iterations");
    amg_rotation_modes    = prm.get_bool("AMG with rotation modes");
    augmentation          = prm.get_double("Augmentation parameter");
    // 'auto' (0) is resolved per dimension
    tangential_augmentation =
      parse_auto_or_positive(prm.get("Tangential augmentation parameter"),
                             "Solver/Tangential augmentation parameter");
    proximal                   = prm.get_double("Proximal parameter");
    uzawa_tolerance            = prm.get_double("Uzawa tolerance");
    max_uzawa_steps            = prm.get_integer("Maximum Uzawa steps");
    newton_tolerance_factor    = prm.get_double("Newton tolerance factor");
    newton_initial_tolerance   = prm.get_double("Newton initial tolerance");
    newton_tolerance_reduction = prm.get_double("Newton tolerance reduction");
    newton_gradient_reduction  = prm.get_double("Newton gradient reduction");
    max_newton_steps           = prm.get_integer("Maximum Newton steps");
    line_search                = prm.get_bool("Line search");
    amg_rebuild_fraction       = prm.get_double("AMG rebuild fraction");
    time_reference_solve       = prm.get_bool("Time a reference linear solve");
    prm.leave_subsection();
    if (!(augmentation > 0.))
      throw InputError("The entry <Solver/Augmentation parameter> must be "
                       "positive.",
                       exit_invalid_value);
    if (!(proximal > 0.))
      throw InputError("The entry <Solver/Proximal parameter> must be "
                       "positive (chi = 0 leaves semi-coercive scenes "
                       "singular).",
                       exit_invalid_value);
    if (!(newton_tolerance_reduction > 0. && newton_tolerance_reduction < 1.))
      throw InputError("The entry <Solver/Newton tolerance reduction> must lie "
                       "in (0, 1).",
                       exit_invalid_value);
  }

  std::vector<IneffectiveRule>
  SolverParameters::ineffective_rules(const Parameters &parameters) const
  {
    const bool         contact = parameters.boundary.has_contact();
    const std::string &law     = parameters.friction.law;
    return {{contact && create_friction_law(law)->parameter_entry().empty(),
             "Solver",
             {"Tangential augmentation parameter"},
             "<Friction/Law> is " + quoted(law) +
               " (frictionless): there are no friction terms"},
            {!contact,
             "Solver",
             {"Augmentation parameter",
              "Tangential augmentation parameter",
              "Proximal parameter",
              "Uzawa tolerance",
              "Maximum Uzawa steps",
              "Newton tolerance factor",
              "Newton initial tolerance",
              "Newton tolerance reduction",
              "Newton gradient reduction",
              "Maximum Newton steps",
              "Line search",
              "AMG rebuild fraction",
              "Time a reference linear solve"},
             "the scene has no contact boundary (one linear elasticity solve "
             "per mesh, no Uzawa or Newton iteration)"}};
  }
} // namespace dualcontact
