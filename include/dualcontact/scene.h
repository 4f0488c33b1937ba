// A scene: the body's geometry and mesh, which condition holds on which
// boundary part, the loads as functions, the foundation, and from all of that
// the list of effects the solver has to simulate (doc/theory.md §1).
#ifndef dualcontact_scene_h
#define dualcontact_scene_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/distributed/tria_base.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/full_matrix.h>

#include <dualcontact/bodies.h>
#include <dualcontact/discretization.h>
#include <dualcontact/expressions.h>
#include <dualcontact/friction_law.h>
#include <dualcontact/geometry.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameters.h>

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /** What a scene calls for; the solver composes only these. */
  struct Effects
  {
    // contact of any kind: with the obstacle, or between bodies
    bool contact          = false;
    bool obstacle_contact = false;
    // the contact pairs, 'slave id on master id, ...'; empty if none
    std::string pairs;
    // how their slave nodes see the master surface: 'dual mortar' or 'node
    // to segment'
    std::string pair_coupling;
    // the friction law, chosen once from <Friction/Law>; frictionless
    // ('none') also when the scene asked for friction whose coefficient or
    // threshold is zero (zero_friction: the log says so)
    std::shared_ptr<const FrictionLaw> friction;
    bool                               zero_friction = false;
    bool                               body_force    = false;
    bool                               tractions     = false;
    std::string                        obstacle; // its description

    const FrictionLaw &
    friction_law() const
    {
      return *friction;
    }

    /** One line per effect, saying what runs and what does not. */
    std::string
    describe() const;
  };

  template <int dim>
  class Scene
  {
  public:
    /**
     * Build every function the scene needs from the parameters, and read
     * the coarse mesh of a mesh file (its size sets the lengths below).
     * Throws InputError naming the entry if an expression does not parse,
     * or the mesh file is bad or does not fit the entries (mesh_file.h).
     * `before_building`, if given, gets the number of cells the mesh of a
     * mesh file will have after the initial global refinement, once the
     * file is checked and before the coarse mesh is built from it: the
     * caller can stop a mesh too large for the memory.
     */
    explicit Scene(const Parameters                  &parameters,
                   const std::function<void(double)> &before_building = {});

    /**
     * Coarse mesh, manifolds, initial global refinement, pre-refinement.
     * `before_refining`, if given, gets the number of cells the mesh will
     * have at least after the next refinement (the global one, then each
     * pre-refinement step), before that refinement is made, and for a box
     * what the global refinement will make of it before the box is built:
     * the caller can stop a mesh too large for the memory before it is
     * built.
     */
    void
    create_mesh(parallel::TriangulationBase<dim>  &triangulation,
                const std::function<void(double)> &before_refining = {}) const;

    /**
     * The two parts of create_mesh(): the coarse mesh with its boundary
     * ids and manifolds (what a checkpoint's mesh is loaded onto), then the
     * initial global refinement and the pre-refinement.
     */
    void
    create_coarse_mesh(
      parallel::TriangulationBase<dim>  &triangulation,
      const std::function<void(double)> &before_refining = {}) const;
    void
    refine_initial_mesh(
      parallel::TriangulationBase<dim>  &triangulation,
      const std::function<void(double)> &before_refining = {}) const;
    /**
     * The kind of cells the mesh is made of: <Geometry/Cell type>, or the
     * cells of a mesh file of triangles or tetrahedra.
     */
    CellKind
    cell_kind() const
    {
      return discretization_->cell_kind();
    }

    /** The body's shape (<Geometry/Type>). */
    const Geometry<dim> &
    geometry() const
    {
      return *geometry_;
    }

    /** The element, mapping, quadratures and triangulation of the cells. */
    const Discretization<dim> &
    discretization() const
    {
      return *discretization_;
    }

    /**
     * Throw InputError if the scene leaves a rigid motion free and nothing
     * (no contact boundary) could hold it: the elastic problem would then
     * be singular. Semi-coercive scenes with contact are allowed.
     */
    void
    check_rigid_motions(const Triangulation<dim> &triangulation) const;

    /** dim translations, then dim(dim-1)/2 rotations. */
    static constexpr unsigned int n_rigid_motions = dim * (dim + 1) / 2;

    /**
     * The rigid motion i at x: the unit translation along e_i for i < dim,
     * then the rotations about center(), scaled by 1/characteristic_length()
     * so that all have magnitudes of order one on the body.
     */
    Tensor<1, dim>
    rigid_motion(const unsigned int i, const Point<dim> &x) const;

    /**
     * The Gram matrix G_ij = int_{fixed} m_i.m_j + int_{normal fixed}
     * (m_i.n)(m_j.n) of the rigid motions m_i over the part of the boundary
     * where displacements are prescribed, summed over the ranks; `measure`
     * gets that part's length (area). A combination c of rigid motions is
     * left free by the boundary conditions iff G c = 0. With `bodies`
     * each body moves on its own: the index
     * b n_rigid_motions + i is the motion i of body b, zero on the others.
     * Collective.
     */
    FullMatrix<double>
    rigid_motion_gram(const Triangulation<dim> &triangulation,
                      double                   &measure,
                      const Bodies<dim>        *bodies = nullptr) const;

    /**
     * Whether the rigid translation along e is left free by the fixed and
     * normal-fixed boundaries (only contact could stop it): of the whole
     * mesh, or, with `bodies`, of body
     * `body` alone. Collective.
     */
    bool
    translation_is_free(const Tensor<1, dim>     &e,
                        const Triangulation<dim> &triangulation,
                        const Bodies<dim>        *bodies = nullptr,
                        unsigned int              body   = 0) const;

    const Effects &
    effects() const
    {
      return effects_;
    }

    /** The contact pairs between bodies: slave id -> master id. */
    const std::map<types::boundary_id, types::boundary_id> &
    contact_pairs() const
    {
      return parameters.boundary.contact_pairs;
    }

    /** <Boundary conditions/Pair coupling> = node to segment. */
    bool
    pairs_node_to_segment() const
    {
      return parameters.boundary.node_to_segment;
    }

    /**
     * The ids whose faces carry contact nodes: those of the condition
     * 'contact', and the slave ids of the contact pairs.
     */
    std::set<types::boundary_id>
    contact_ids() const
    {
      return parameters.boundary.contact_ids();
    }

    /** Boundary ids carrying each condition. */
    std::set<types::boundary_id>
    ids_with(const BoundaryCondition condition) const;

    /** Prescribed displacement on a 'fixed' id (zero if none was given). */
    const Function<dim> &
    displacement(const types::boundary_id id) const;
    /** Traction on a 'traction' id, or nullptr if it is zero. */
    const Function<dim> *
    traction(const types::boundary_id id) const;
    /** Body force, or nullptr if the scene has none. */
    const Function<dim> *
    body_force() const
    {
      return body_force_.get();
    }
    /** Friction coefficient F (Coulomb) or threshold g (given), scalar;
     * nullptr without friction. */
    const Function<dim> *
    friction_function() const
    {
      return friction_.get();
    }

    /** Exact contact pressure (scalar), or nullptr if none is known. */
    const Function<dim> *
    exact_pressure() const
    {
      return exact_pressure_.get();
    }
    /** Exact displacement, or nullptr if none is known. */
    const Function<dim> *
    exact_displacement() const
    {
      return exact_.get();
    }

    /**
     * Set the time t of the load path (doc/theory.md §11): the loads and
     * the obstacle's translation U(t) follow. The scene starts at the first
     * step's time.
     */
    void
    set_time(double t);

    /**
     * Whether <Obstacle/Displacement> moves the obstacle: away from where
     * it is given at the first step, or along the load path.
     */
    bool
    obstacle_moves() const
    {
      return obstacle_moves_;
    }

    /** The time the loads and the obstacle are at. */
    double
    time() const
    {
      return time_;
    }

    /** The rigid obstacle, in its prescribed position. */
    const PlacedObstacle<dim> &
    obstacle() const
    {
      return *obstacle_;
    }

    /** Signed distance of x from the obstacle: the initial gap g0(x). */
    double
    initial_gap(const Point<dim> &x) const
    {
      return obstacle_->distance(x);
    }

    /** A point in the middle of the body (the rectangle's centre, the
     * disc's centre, the centre of a mesh file's bounding box): rotations
     * are taken about it. */
    Point<dim>
    center() const;

    /** A length that characterises the body (for relative measures): the
     * rectangle's longest side, the disc's radius, the longest side of a
     * mesh file's bounding box. */
    double
    characteristic_length() const;

    const Parameters &parameters;

  private:
    /** The loads, prescribed displacements and exact solutions. */
    void
    make_loads(double length, const std::vector<double> &times);
    /** The obstacle and its path; returns <Obstacle/Displacement>'s
     * components joined by ';'. */
    std::string
    make_obstacle(double length, const std::vector<double> &times);
    /** The effects, and the friction law with its function. */
    void
    find_effects(double                     length,
                 const std::vector<double> &times,
                 const std::string         &path);

    std::unique_ptr<Geometry<dim>>       geometry_;
    std::unique_ptr<Discretization<dim>> discretization_;

    Effects                                                      effects_;
    std::map<types::boundary_id, std::unique_ptr<Function<dim>>> displacements;
    std::map<types::boundary_id, std::unique_ptr<Function<dim>>> tractions;
    std::unique_ptr<Function<dim>>                               body_force_;
    std::unique_ptr<Function<dim>>                               exact_;
    std::unique_ptr<Function<dim>>       exact_pressure_;
    std::unique_ptr<Function<dim>>       friction_;
    std::unique_ptr<PlacedObstacle<dim>> obstacle_;
    // <Obstacle/Displacement>, dim functions of t evaluated at the point t
    // (nullptr: not moved)
    std::unique_ptr<Function<1>> obstacle_path;
    double                       time_           = 0.;
    bool                         obstacle_moves_ = false;
    Functions::ZeroFunction<dim> zero{dim};
  };
} // namespace dualcontact

#endif
