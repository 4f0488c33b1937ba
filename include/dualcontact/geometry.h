// The body's shape, <Geometry/Type>: each kind is one file in
// source/geometries/, registered by name, which owns its entries (their
// declaration, parsing, checks and the rules saying when they have no
// effect), its boundary ids, and its coarse mesh with boundary ids and
// manifolds on either kind of cell, its centre and its size. No other file
// knows a kind's name; a program may register its own kinds.
#ifndef dualcontact_geometry_h
#define dualcontact_geometry_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <dualcontact/cell_kind.h>
#include <dualcontact/entry_declaration.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  struct BoundaryManifold;   // parameters.h
  struct GeometryParameters; // parameters.h
  struct Parameters;         // parameters.h

  /** A body's shape, built from the parameters for one scene. */
  template <int dim>
  class Geometry
  {
  public:
    virtual ~Geometry() = default;

    /**
     * The kind of cells of the coarse mesh: <Geometry/Cell type>, or what
     * the shape is made of (a mesh file of triangles or tetrahedra).
     */
    virtual CellKind
    cell_kind() const = 0;

    /**
     * The number of cells of the coarse mesh if it is known before the mesh
     * is built, 0 otherwise: the memory check stops a mesh too large before
     * it is built.
     */
    virtual double
    n_coarse_cells() const
    {
      return 0.;
    }

    /**
     * The coarse mesh into the empty `triangulation`, with its boundary ids,
     * material ids (one per body) and manifolds.
     */
    virtual void
    create_coarse_mesh(Triangulation<dim> &triangulation) const = 0;

    /** A point in the middle of the body: rotations are taken about it. */
    virtual Point<dim>
    center() const = 0;

    /** A length that characterises the body (for relative measures). */
    virtual double
    characteristic_length() const = 0;

    /**
     * A warning for a mapping of polynomial degree `degree` that cannot
     * follow the boundary (a shape whose curved parts are not named), or
     * the empty string.
     */
    virtual std::string
    mapping_warning(const unsigned int /*degree*/) const
    {
      return "";
    }
  };

  /**
   * Builds the geometry from the parameters; `before_building`, if given,
   * gets the number of cells a mesh read from elsewhere (a file) will have
   * after the initial global refinement, before its coarse mesh is built.
   */
  template <int dim>
  using GeometryFactory = std::function<std::unique_ptr<Geometry<dim>>(
    const Parameters                  &parameters,
    const std::function<void(double)> &before_building)>;

  /**
   * Entries of subsection Geometry that a kind (or the kinds of one file)
   * owns, and for what: "<Geometry/Type> is '...' (it is for `purpose`)"
   * when the chosen kind reads none of them.
   */
  struct GeometryEntryGroup
  {
    std::vector<std::string> entries;
    std::string              purpose;
  };

  /**
   * What a kind of geometry registers from its own file. The kinds of one
   * file that share entries register the same functions, which are called
   * once.
   */
  struct GeometryKind
  {
    /** Where its name and help stand in <Geometry/Type>: ascending. */
    unsigned int listing_position = 0;

    /** Its part of <Geometry/Type>'s help: "'name': what it is ...". */
    std::string help;

    /** Declares its entries in subsection Geometry (entered). */
    void (*declare_parameters)(EntryDeclarer &declarer) = nullptr;

    /** Reads its entries of subsection Geometry (entered). */
    void (*parse_parameters)(ParameterHandler   &prm,
                             GeometryParameters &geometry) = nullptr;

    /** The entries of subsection Geometry it reads. */
    std::vector<std::string> entries;

    /** The entries it owns, which have no effect for the other kinds. */
    std::vector<GeometryEntryGroup> owned_entries;

    /** Its points and vectors' 3D defaults: {subsection, entry, value}. */
    std::vector<std::array<std::string, 3>> defaults_3d;

    /** Checks of its parsed values alone; InputError naming the entry. */
    void (*check_parsed)(const GeometryParameters &geometry) = nullptr;

    /** Checks of the counts of its values against the dimension. */
    void (*check_sizes)(const GeometryParameters &geometry) = nullptr;

    /** Checks of the magnitudes of its lengths (check_magnitude()). */
    void (*check_magnitudes)(const GeometryParameters &geometry) = nullptr;

    /** Checks against the rest of the scene (cell type, dimension). */
    void (*check)(const Parameters &parameters) = nullptr;

    /**
     * Its boundary ids are 0 to n - 1 in dimension dim; nullptr: the mesh
     * says which (they are checked once it is read).
     */
    unsigned int (*n_boundary_ids)(unsigned int dim) = nullptr;

    /**
     * The entries that set the size of its coarse mesh, with their values
     * as the input gave them: {entry, value} (for the memory check's
     * message).
     */
    std::vector<std::pair<std::string, std::string>> (*size_entries)(
      const GeometryParameters &geometry) = nullptr;

    GeometryFactory<2> create_2d;
    GeometryFactory<3> create_3d;
  };

  /**
   * Make `name` known to <Geometry/Type>, in 2D and 3D. Called once per
   * kind, at load time, from the kind's own file (a program may register
   * its own kinds the same way, before the parameters are declared).
   * Returns true (for the static initialiser).
   */
  bool
  register_geometry(const std::string &name, GeometryKind kind);

  /** The registered names, in the order of their listing positions. */
  std::vector<std::string>
  geometry_names();

  /** The kind registered as `name`; InputError naming <Geometry/Type>. */
  const GeometryKind &
  geometry_kind(const std::string &name);

  /** The geometry <Geometry/Type> names, built from the parameters. */
  template <int dim>
  std::unique_ptr<Geometry<dim>>
  create_geometry(const Parameters                  &parameters,
                  const std::function<void(double)> &before_building = {});

  /**
   * The number of boundary ids of the geometry, 0 to n - 1, or
   * numbers::invalid_unsigned_int where its mesh says which (a mesh file:
   * checked once it is read).
   */
  unsigned int
  n_geometry_boundary_ids(const GeometryParameters &geometry);

  /**
   * Checks a curved boundary of radius `radius` about `center`, given by
   * <entry>, against what deal.II's manifolds take (radius from 1e-6, in
   * 3D a centre within 100 radii of the origin); InputError otherwise.
   */
  void
  check_curved_boundary(double                     radius,
                        const std::vector<double> &center,
                        const std::string         &entry,
                        unsigned int               dim);

  /**
   * Each quadrilateral of `mesh` into 8 triangles (hexahedron into 24
   * tetrahedra), the new vertices on the faces with the ids of `curves`
   * put onto their curve.
   */
  template <int dim>
  void
  convert_to_simplices(Triangulation<dim>                  &mesh,
                       const std::vector<BoundaryManifold> &curves);
} // namespace dualcontact

#endif
