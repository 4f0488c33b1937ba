// All run-time parameters of a dualcontact scene: one struct per subsection of
// the .prm file, each with its own file in source/parameters/ that declares
// its entries through an EntryDeclarer (pattern, default, help text with
// units), parses them, checks them (alone, against the dimension or the
// boundary conditions) and says which of them have no effect in a scene.
#ifndef dualcontact_parameters_h
#define dualcontact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <dualcontact/cell_kind.h>
#include <dualcontact/entry_declaration.h>
#include <dualcontact/material_parameters.h>
#include <dualcontact/name_table.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace dualcontact
{
  using dealii::ParameterHandler;
  using dealii::types::boundary_id;

  class ParameterReader;
  struct Parameters;

  /** The condition on one part of the boundary (doc/theory.md §1). */
  enum class BoundaryCondition
  {
    free,         // zero traction
    fixed,        // all displacement components prescribed (Gamma_D)
    normal_fixed, // v.n = 0, tangential part free: a frictionless slider
                  // (Gamma_0)
    traction,     // traction vector prescribed (Gamma_N)
    contact       // unilateral contact with the rigid foundation (Gamma_C)
  };

  /** The threshold iteration: how a pressure-dependent threshold is found. */
  enum class FrictionStrategy
  {
    nested, // successive approximations around converged Uzawa solves
    merged  // g updated inside every Uzawa step (one loop)
  };

  enum class InitialThreshold
  {
    zero,        // g^0 = 0
    frictionless // g^0 = F times the frictionless contact pressure
  };

  /** The names of the choices, as the .prm file writes them. */
  const NameTable<CellKind> &
  cell_kind_names();
  const NameTable<BoundaryCondition> &
  boundary_condition_names();
  const NameTable<FrictionStrategy> &
  friction_strategy_names();
  const NameTable<InitialThreshold> &
  initial_threshold_names();

  std::string
  to_string(const BoundaryCondition condition);

  /**
   * Entries that have no effect in a scene when `applies`, and why: each
   * subsection gives its own (ineffective_rules()), and
   * Parameters::ineffective_entries() names those the input gave.
   */
  struct IneffectiveRule
  {
    bool                     applies;
    std::string              subsection;
    std::vector<std::string> entries;
    std::string              why;
  };

  /**
   * A curved boundary part of a mesh read from a file: the boundary faces
   * with this id lie on a circle (2D), a sphere or a cylinder (3D), which
   * refinement follows (<Geometry/Manifolds>).
   */
  struct BoundaryManifold
  {
    enum class Kind
    {
      circle,  // 2D: |x - center| = radius
      sphere,  // 3D: |x - center| = radius
      cylinder // 3D: distance from the axis through center = radius
    };
    boundary_id         id   = 0;
    Kind                kind = Kind::circle;
    std::vector<double> center;
    double              radius = 0.;
    std::vector<double> axis; // cylinder only

    /** "circle", "sphere", "cylinder". */
    std::string
    kind_name() const;
  };

  const NameTable<BoundaryManifold::Kind> &
  manifold_kind_names();

  /** Geometry and initial mesh. */
  struct GeometryParameters
  {
    unsigned int              dimension = 2;
    std::string               type      = "rectangle"; // a kind of geometry.h
    CellKind                  cell_kind = CellKind::quadrilateral;
    std::vector<double>       lower_left;
    std::vector<double>       upper_right;
    std::vector<unsigned int> subdivisions;
    std::vector<unsigned int> upper_subdivisions; // two blocks: the upper's
    double upper_overhang = 0.; // two blocks: the upper's reach beyond
    std::vector<double> center;
    double              radius                  = 1.;
    double              lower_radius            = 1.; // two half discs
    unsigned int        pre_refinement_steps    = 0;
    double              pre_refinement_distance = 0.;
    double              pre_refinement_grading  = 1.;
    // Type 'mesh file': the file as the input gave it, and the path it was
    // resolved to (relative to the folder of the .prm file that set it;
    // Parameters::read_file resolves it)
    std::string                   mesh_file_given;
    std::string                   mesh_file;
    std::vector<BoundaryManifold> manifolds;

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    /**
     * The shape against the dimension (counts of coordinates, the ids'
     * kinds of manifold), the magnitudes (Parameters::check_magnitudes), a
     * mesh file named; throws InputError.
     */
    void
    check(const Parameters &parameters) const;
    /** The magnitudes of the lengths and radii (see check_magnitudes). */
    void
    check_magnitudes() const;
    /** Pre-refinement refines toward the contact boundary: it needs one. */
    void
    check_pre_refinement(const Parameters &parameters) const;
    /**
     * What simplices do not take (degree 3, degree 2 on tetrahedra, local
     * refinement but the 2D pre-refinement); `why` says where the simplices
     * come from (the entry, or the cells of the mesh file). Throws
     * InputError.
     */
    static void
    check_simplices(const Parameters &parameters, const std::string &why);
    std::vector<IneffectiveRule>
    ineffective_rules(const Parameters &parameters) const;
  };

  /** Which condition holds on which boundary id, with its data. */
  struct BoundaryParameters
  {
    std::map<boundary_id, BoundaryCondition> conditions;
    std::map<boundary_id, std::string>       displacements; // "u_x; u_y"
    std::map<boundary_id, std::string>       tractions;     // "T_x; T_y"
    // contact between two parts of the mesh (two bodies): slave id ->
    // master id, dual mortar (doc/two_bodies.md)
    std::map<boundary_id, boundary_id> contact_pairs;
    // <Pair coupling> = node to segment: the one-pass node-to-segment gap
    // in place of the dual mortar (for comparison)
    bool node_to_segment = false;

    BoundaryCondition
    condition(const boundary_id id) const;
    std::vector<boundary_id>
    ids_with(const BoundaryCondition condition) const;
    /** The ids whose faces carry contact nodes: those of the condition
     * 'contact', and the slave ids of the contact pairs. */
    std::set<boundary_id>
    contact_ids() const;
    /** Each id's condition, and each pair's slave and master ids, in words
     * ("id 3 fixed", "id 4 slave, id 5 master of a contact pair"). */
    std::vector<std::string>
    parts_in_words() const;
    /** The pairs as "slave on master", comma-separated ("" without). */
    std::string
    pairs_in_words() const;
    /** Contact of any kind: with the obstacle, or a contact pair. */
    bool
    has_contact() const
    {
      return !ids_with(BoundaryCondition::contact).empty() ||
             !contact_pairs.empty();
    }

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    /** The ids against the geometry, the data against the conditions. */
    void
    check(const Parameters &parameters) const;
  };

  /** Volume loads. */
  struct LoadParameters
  {
    std::string body_force;

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /**
   * The rigid obstacle (doc/theory.md §10): its kind (a name registered in
   * obstacle.h, whose file declares, reads and checks the entries below),
   * the entries of every kind (so that a program may change the kind), and a
   * prescribed rigid translation.
   * Declared and parsed in obstacle.cc.
   */
  struct ObstacleParameters
  {
    std::string type = "plane";
    EntryValues values; // the entries of every kind
    // U(t): components separated by ';', or by ',' if there is no ';'
    std::string displacement;

    /** The components of <Obstacle/Displacement> (empty: not moved). */
    std::vector<std::string>
    displacement_components() const;

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    /**
     * With a contact boundary: the kind's own check, and the displacement
     * against the dimension. Defined in source/parameters/obstacle.cc.
     */
    void
    check(const Parameters &parameters) const;
    /** The entries of the kinds the scene's kind does not read. */
    std::vector<IneffectiveRule>
    ineffective_rules(const Parameters &parameters) const;
  };

  /** Friction law on the contact boundary. */
  struct FrictionParameters
  {
    std::string law = "none"; // a name registered in friction_law.h
    // the expression of the law's own entry (FrictionLaw::parameter_entry:
    // a coefficient, a threshold); empty for a law without one
    std::string parameter;

    // the threshold iteration (laws whose threshold depends on l1)
    FrictionStrategy strategy          = FrictionStrategy::merged;
    InitialThreshold initial_threshold = InitialThreshold::zero;
    double           tolerance         = 1e-6;
    unsigned int     max_steps         = 100;

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    /** A law with friction needs contact, and its own entry. */
    void
    check(const Parameters &parameters) const;
    std::vector<IneffectiveRule>
    ineffective_rules(const Parameters &parameters) const;
  };

  /**
   * The solvers: CG + algebraic multigrid for every linear system, the
   * Uzawa iteration and, inside each of its steps, the Newton iteration.
   */
  struct SolverParameters
  {
    double       linear_tolerance      = 1e-10;
    unsigned int max_linear_iterations = 2000;
    bool         amg_rotation_modes    = true;

    // the Uzawa iteration on the modified Lagrangian (doc/theory.md §5):
    // r = r_rel (lambda + 2 mu) / h_C, chi = chi_rel E / L^2
    double       augmentation            = 10.; // r_rel
    double       tangential_augmentation = 0.;  // r_t,rel; 0: 'auto'
    double       proximal        = 1e-3; // chi_rel: chi = chi_rel E / L^2
    double       uzawa_tolerance = 1e-8;
    unsigned int max_uzawa_steps = 500;
    // the Newton iteration (semi-smooth, with a line search)
    double       newton_tolerance_factor    = 1e-2;
    double       newton_initial_tolerance   = 1e-2;
    double       newton_tolerance_reduction = 0.5;
    double       newton_gradient_reduction  = 1e-2;
    unsigned int max_newton_steps           = 50;
    bool         line_search                = true;
    double       amg_rebuild_fraction       = 0.05;
    bool         time_reference_solve       = false;

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    std::vector<IneffectiveRule>
    ineffective_rules(const Parameters &parameters) const;
  };

  /** The sequence of meshes. */
  struct RefinementParameters
  {
    unsigned int initial_global_refinement = 0;
    unsigned int n_cycles                  = 1;
    // a name registered in refinement_indicator.h, and the entries of
    // every indicator (so that a program may change the strategy)
    std::string strategy = "global";
    EntryValues values;
    double      refine_fraction  = 0.3;
    double      coarsen_fraction = 0.;
    // carry v, l1, l2 and g from one mesh to the next (nested iteration)
    bool nested_iteration = true;
    // also solve every refined mesh from a cold start, for comparison
    bool compare_cold_start = false;

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    std::vector<IneffectiveRule>
    ineffective_rules(const Parameters &parameters) const;
  };

  /** How much of a run the screen shows (the CSV files get everything). */
  enum class Verbosity
  {
    quiet,   // the scene, one line per cycle, the summary
    normal,  // and one line per Uzawa and threshold step, the cycle's results
    detailed // and one line per Newton step
  };

  const NameTable<Verbosity> &
  verbosity_names();

  /** The finite element and the mapping. */
  struct DiscretizationParameters
  {
    unsigned int degree = 1; // of FE_Q and MappingQ

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** What is written where. */
  struct OutputParameters
  {
    std::string directory    = "output";
    bool        write_vtu    = true;
    bool        print_timing = true;
    Verbosity   verbosity    = Verbosity::normal;
    // every n-th later step writes a checkpoint (0: none)
    unsigned int checkpoint_interval = 0;
    // <Output/Probe points>: each point with its coordinates (dim of them,
    // checked against the dimension with the other entries)
    std::vector<std::vector<double>> probe_points;

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    /** One coordinate per dimension in every probe point. */
    void
    check(const Parameters &parameters) const;
    std::vector<IneffectiveRule>
    ineffective_rules(const Parameters &parameters) const;
  };

  /**
   * The load path (doc/theory.md §11): the times t_1 < ... < t_N at which
   * the scene is solved in turn, uniform (n steps to the end time) or
   * given as a list; by default one step at t = 1, the static problem.
   */
  struct LoadPathParameters
  {
    unsigned int        n_steps  = 1;
    double              end_time = 1.;
    std::vector<double> times; // empty: uniform
    bool                adapt_at_every_step = false;
    unsigned int        output_interval     = 1;
    bool                predictor           = true;
    bool                adaptive_steps      = false; // <Step control>
    double              minimum_step        = 0.;    // 0: 'auto'

    /** The times of the steps, from the list or uniform. */
    std::vector<double>
    step_times() const;

    /** Their number, step_times().size() (without building the list). */
    std::size_t
    n_steps_on_path() const
    {
      return times.empty() ? n_steps : times.size();
    }

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    /** The times increase; the end time is positive. */
    void
    check(const Parameters &parameters) const;
    std::vector<IneffectiveRule>
    ineffective_rules(const Parameters &parameters) const;
  };

  /** An exact solution, if the scene has one: errors are then reported. */
  struct ExactSolutionParameters
  {
    std::string displacement;            // empty: none known
    std::string contact_pressure;        // empty: none known
    double      contact_half_width = 0.; // 0: not known
    double      stick_half_width   = 0.; // 0: not known
    double      peak_pressure      = 0.; // 0: not known

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    std::vector<IneffectiveRule>
    ineffective_rules(const Parameters &parameters) const;
  };

  /**
   * All parameters of a run. `declare_parameters` declares every entry, the
   * registered plugins' too, through an EntryDeclarer; `parse_parameters`
   * reads the handler back and checks the entries against each other
   * (throwing InputError naming the entry on any inconsistency).
   */
  struct Parameters
  {
    GeometryParameters       geometry;
    MaterialParameters       material;
    BoundaryParameters       boundary;
    LoadParameters           loads;
    ObstacleParameters       obstacle;
    FrictionParameters       friction;
    SolverParameters         solver;
    RefinementParameters     refinement;
    OutputParameters         output;
    ExactSolutionParameters  exact;
    LoadPathParameters       load_path;
    DiscretizationParameters discretization;

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Read a .prm file, then the overrides "Subsection/Entry=value" (the
     * command line's --set); InputError with the matching exit code on
     * failure (parameter_reader.h has the rules).
     */
    void
    read_file(const std::string              &filename,
              const std::vector<std::string> &overrides = {});
    /**
     * Read parameters from a string in .prm syntax (for tests, tutorials),
     * then `overlay`, .prm text whose entries override the string's.
     */
    void
    read_string(const std::string &text, const std::string &overlay = "");

    /**
     * The checks of the subsections that need more than their own entries
     * (the dimension, the boundary conditions), in a fixed order (the first
     * error found is reported); throws InputError.
     */
    void
    check_consistency() const;

    /**
     * Refuse (exit 5) magnitudes the solver cannot represent: E and the
     * body's lengths outside 1e-100 to 1e100, curved boundaries that
     * deal.II's manifolds cannot refine (radius below 1e-6, and in 3D a
     * centre farther than 100 radii from the origin).
     */
    void
    check_magnitudes() const;

    /**
     * One line per entry that was given but has no effect in this scene (a
     * friction coefficient without a friction law, refinement fractions with
     * global refinement, ...): which entry, why, and where it was set; in
     * the order the input gives them.
     */
    std::vector<std::string>
    ineffective_entries() const;

    /**
     * The entries the input set to a value other than their default
     * ("Subsection/Entry"), each with where its value comes from
     * ("scene.prm:12", "--set"); empty for parameters not read from text.
     */
    std::map<std::string, std::string> given;

    /**
     * The parameters as read (file and overrides), in the form of
     * --print-parameters: every entry with its value, default and help
     * text. dualcontact writes it to the output folder as parameters.prm.
     * It is not updated when a program changes the members afterwards.
     */
    std::string parameter_file;

  private:
    void
    use(ParameterHandler &prm, const ParameterReader &reader);
  };

  /** The default parameter file, with every help text, as a string. */
  std::string
  default_parameter_file();

  /** The values of `entries` ("Subsection/Entry") in the handler. */
  EntryValues
  read_entry_values(ParameterHandler               &prm,
                    const std::vector<std::string> &entries);

  /** The numbers of a comma-separated entry value. */
  std::vector<double>
  numbers_of(const EntryValues &values, const std::string &entry);

  /**
   * numbers_of(), checked: n values (InputError, exit 6, otherwise) and,
   * with `nonzero`, not the zero vector (exit 5).
   */
  std::vector<double>
  vector_of(const EntryValues &values,
            const std::string &entry,
            unsigned int       n,
            bool               nonzero = false);

  /** True if every component of the "a; b; c" expression is the number 0. */
  bool
  is_zero_expression(const std::string &expression);

  /**
   * True if the expression names a coordinate (x, y, and in 3D z) as a
   * variable, i.e. if its value may depend on the position.
   */
  bool
  uses_coordinates(const std::string &expression, unsigned int dim);

  /** The names an expression uses (variables, constants, functions). */
  std::set<std::string>
  identifiers(const std::string &expression);

  /** True if the expression names the time t of the load path. */
  bool
  uses_time(const std::string &expression);
} // namespace dualcontact

#endif
