// The rigid obstacle the body meets on Gamma_C (doc/theory.md §10): a signed
// distance d(x), positive outside the obstacle where the body is, and its
// outward unit normal m(x) = grad d. Each kind is one file in
// source/obstacles/, registered by name for <Obstacle/Type>, chosen once.
#ifndef dualcontact_obstacle_h
#define dualcontact_obstacle_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dualcontact/entry_declaration.h>
#include <dualcontact/material_parameters.h>

#include <array>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  template <int dim>
  class Obstacle
  {
  public:
    virtual ~Obstacle() = default;

    /** The name in <Obstacle/Type>. */
    virtual std::string
    name() const = 0;

    /** One line for the log: what the obstacle is, with its data. */
    virtual std::string
    description() const = 0;

    /**
     * Signed distance of x from the obstacle's surface, in the obstacle's
     * initial position: > 0 outside (where the body is), < 0 inside.
     */
    virtual double
    distance(const Point<dim> &x) const = 0;

    /** Outward unit normal m(x) = grad d(x): from the obstacle toward x. */
    virtual Tensor<1, dim>
    normal(const Point<dim> &x) const = 0;

    /**
     * Whether the point of the surface nearest to x is a corner or an edge,
     * where the surface has no normal (m jumps across it). A contact node
     * there takes its own surface's normal (ContactSet::place_obstacle()).
     */
    virtual bool
    has_corner_near(const Point<dim> &) const
    {
      return false;
    }

    /**
     * Whether the surface is a plane: then every contact node has the same
     * normal, and a tangential load can only be held by friction (the
     * equilibrium check before a solve uses that).
     */
    virtual bool
    is_plane() const
    {
      return false;
    }

    /**
     * The smallest radius of curvature of the surface (infinite for a
     * plane, unknown ones too): gaps and normals are taken before
     * deformation, which needs displacements small against it.
     */
    virtual double
    radius_of_curvature() const
    {
      return std::numeric_limits<double>::infinity();
    }
  };

  /**
   * The obstacle of a scene, moved by the rigid translation U of
   * <Obstacle/Displacement>: d_U(x) = d(x - U), m_U(x) = m(x - U).
   */
  template <int dim>
  class PlacedObstacle
  {
  public:
    PlacedObstacle(std::unique_ptr<Obstacle<dim>> shape,
                   const Tensor<1, dim>          &translation,
                   const std::string             &entries)
        : shape(std::move(shape))
        , translation(translation)
        , entries_(entries)
    {}

    double
    distance(const Point<dim> &x) const
    {
      return shape->distance(x - translation);
    }

    Tensor<1, dim>
    normal(const Point<dim> &x) const
    {
      return shape->normal(x - translation);
    }

    bool
    has_corner_near(const Point<dim> &x) const
    {
      return shape->has_corner_near(x - translation);
    }

    const Obstacle<dim> &
    operator*() const
    {
      return *shape;
    }
    const Obstacle<dim> *
    operator->() const
    {
      return shape.get();
    }

    /** The prescribed rigid translation U [length]. */
    const Tensor<1, dim> &
    displacement() const
    {
      return translation;
    }

    /** Move the obstacle to the translation U (a step of a load path). */
    void
    move_to(const Tensor<1, dim> &U)
    {
      translation = U;
    }

    /**
     * The entries that give the obstacle's shape and place, for messages
     * ("<Foundation/Point> and <Foundation/Normal>").
     */
    const std::string &
    entries() const
    {
      return entries_;
    }

  private:
    std::unique_ptr<Obstacle<dim>> shape;
    Tensor<1, dim>                 translation;
    std::string                    entries_;
  };

  template <int dim>
  using ObstacleFactory = std::function<
    std::unique_ptr<Obstacle<dim>>(const EntryValues        &values,
                                   const MaterialParameters &material,
                                   const double              length)>;

  /**
   * What a kind of obstacle registers from its own file: the help text of
   * its name in <Obstacle/Type>, the declaration of its entries, which of
   * them it reads, their checks, and its factories. No other file knows its
   * name or its entries.
   */
  struct ObstacleKind
  {
    /** What <Obstacle/Type> = this name gives: a sentence or two. */
    std::string help;

    /**
     * Declares the kind's entries through `declarer` (entry_declaration.h),
     * in the subsections it names itself. The kinds of one file that share
     * entries register the same function, which is called once.
     */
    void (*declare_parameters)(EntryDeclarer &declarer) = nullptr;

    /**
     * The entries ("Subsection/Entry") the kind reads in a scene of
     * dimension dim; those it declares but does not read there have no
     * effect (a warning names them).
     */
    std::vector<std::string> (*entries)(unsigned int dim) = nullptr;

    /**
     * The values of its points and vectors in a 3D scene that does not set
     * them: {subsection, entry, value}.
     */
    std::vector<std::array<std::string, 3>> defaults_3d;

    /**
     * Checks the values against each other and the dimension; throws
     * InputError naming the entry. Called where the parameters are read.
     */
    void (*check)(const EntryValues &values, unsigned int dim) = nullptr;

    ObstacleFactory<2> create_2d;
    ObstacleFactory<3> create_3d;
  };

  /**
   * Make `name` known to <Obstacle/Type>, in 2D and 3D. Called once per
   * kind, at load time, from the kind's own file (a program may register
   * its own kinds the same way). Returns true (for the static initialiser).
   */
  bool
  register_obstacle(const std::string &name, ObstacleKind kind);

  /** The registered names, in alphabetical order. */
  std::vector<std::string>
  obstacle_names();

  /** The kind registered as `name`; InputError naming <Obstacle/Type>. */
  const ObstacleKind &
  obstacle_kind(const std::string &name);

  /**
   * The entries the registered kinds read in a scene of dimension dim, each
   * with the names of the kinds that read it.
   */
  std::map<std::string, std::vector<std::string>>
  obstacle_entry_readers(unsigned int dim);

  /**
   * Declares <Obstacle/Type> and <Obstacle/Displacement>, and every
   * registered kind's entries.
   */
  void
  declare_obstacle_parameters(EntryDeclarer &declarer);

  /**
   * The obstacle <Obstacle/Type> names, built from the parameters; `length`
   * is the body's size (the step of numerical gradients). Throws InputError
   * naming the entry when the data is unusable.
   */
  template <int dim>
  std::unique_ptr<Obstacle<dim>>
  create_obstacle(const std::string        &type,
                  const EntryValues        &values,
                  const MaterialParameters &material,
                  const double              length);

  /**
   * The entries that place the obstacle of the scene, for messages:
   * "<Foundation/Point> and <Foundation/Normal>".
   */
  std::string
  obstacle_entries_text(const std::string &type, const unsigned int dim);

  /**
   * The point (or vector) of a list of coordinates from a parameter entry;
   * missing coordinates are 0, extra ones are ignored (entries of a
   * subsection a scene does not use are not checked for their length).
   */
  template <int dim>
  Point<dim>
  to_point(const std::vector<double> &values)
  {
    Point<dim> p;
    for (unsigned int d = 0; d < dim && d < values.size(); ++d)
      p[d] = values[d];
    return p;
  }

  /**
   * An orthonormal basis of the plane orthogonal to the unit vector n: 2D
   * t = (-n_2, n_1); 3D t_1 = e_x (or e_y where |n_x| >= 0.9) made
   * orthogonal to n, and t_2 = n x t_1. A function of n alone, so that the
   * tangential multiplier's components mean the same at nearby nodes and
   * can be carried to the next mesh.
   */
  template <int dim>
  std::array<Tensor<1, dim>, dim - 1>
  tangent_basis(const Tensor<1, dim> &n);
} // namespace dualcontact

#endif
