#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <dualcontact/cell_shapes.h>
#include <dualcontact/discretization.h>
#include <dualcontact/gmsh_scan.h>
#include <dualcontact/input_error.h>
#include <dualcontact/mesh_file.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace dualcontact
{
  namespace
  {
    /** "<Geometry/Mesh file> 'given' (the file path)" for messages. */
    std::string
    name_of(const GeometryParameters &geometry)
    {
      const std::string given = geometry.mesh_file_given.empty() ?
                                  geometry.mesh_file :
                                  geometry.mesh_file_given;
      return "<Geometry/Mesh file> '" + given + "'" +
             (given == geometry.mesh_file ? "" :
                                            " (" + geometry.mesh_file + ")");
    }

    /**
     * The element types a mesh of dimension `dim` may hold, and the
     * advice for the others.
     */
    template <int dim>
    void
    check_elements(const MshContents &contents, const GeometryParameters &g)
    {
      const std::string file = name_of(g);
      const auto        n    = [&contents](const int type) {
        return contents.count(type);
      };
      for (const auto &[type, count] : contents.n_elements)
        if (type != MshContents::point && type != MshContents::line &&
            type != MshContents::triangle && type != MshContents::quad &&
            type != MshContents::tetrahedron &&
            type != MshContents::hexahedron && type != MshContents::prism &&
            type != MshContents::pyramid)
          throw InputError("The mesh " + file + " has " +
                             plural(count, "element") + " of Gmsh type " +
                             std::to_string(type) +
                             " (second order, or another kind): dualcontact "
                             "needs first-order quadrilaterals or triangles "
                             "(2D), hexahedra or tetrahedra (3D); set "
                             "'Mesh.ElementOrder = 1;'.",
                           exit_invalid_value);

      const unsigned long n_3d_cells =
        n(MshContents::tetrahedron) + n(MshContents::hexahedron) +
        n(MshContents::prism) + n(MshContents::pyramid);
      const unsigned long n_2d_cells =
        n(MshContents::triangle) + n(MshContents::quad);
      if (dim == 2 && n_3d_cells > 0)
        throw InputError("The mesh " + file + " is a 3D mesh (it has " +
                           plural(n_3d_cells, "volume element") +
                           "), but <Geometry/Dimension> is 2.",
                         exit_inconsistent);
      if (dim == 3 && n_3d_cells == 0 && n_2d_cells > 0)
        throw InputError("The mesh " + file + " is a 2D mesh (it has " +
                           plural(n_2d_cells, "surface element") +
                           " and no volume elements), but <Geometry/"
                           "Dimension> is 3.",
                         exit_inconsistent);

      // One kind of cell: quadrilaterals or triangles in 2D, hexahedra or
      // tetrahedra in 3D (a mesh of triangles or tetrahedra is read as
      // simplices, doc/simplices.md).
      const int quads = dim == 2 ? MshContents::quad : MshContents::hexahedron;
      const int simplex =
        dim == 2 ? MshContents::triangle : MshContents::tetrahedron;
      const std::string quad_name = dim == 2 ? "quadrilaterals" : "hexahedra";
      const std::string simplex_name = dim == 2 ? "triangles" : "tetrahedra";
      std::string       other;
      if (dim == 3)
        for (const auto &[type, name] :
             std::vector<std::pair<int, std::string>>{
               {MshContents::prism, "prisms"},
               {MshContents::pyramid, "pyramids"}})
          if (n(type) > 0)
            other += (other.empty() ? "" : ", ") + std::to_string(n(type)) +
                     " " + name;
      if (!other.empty())
        throw InputError(
          "The mesh " + file + " has " + other +
            ": dualcontact takes hexahedra or tetrahedra only. In Gmsh, mesh "
            "the volume with tetrahedra alone, or extrude a recombined "
            "surface mesh ('Recombine Surface{:};', then 'Extrude {...} { "
            "Surface{...}; Layers{n}; Recombine; }') for hexahedra "
            "(doc/meshes.md).",
          exit_invalid_value);
      // "1 hexahedron", "2 hexahedra"
      const auto count =
        [&n](const int type, const std::string &one, const std::string &many) {
          return std::to_string(n(type)) + " " + (n(type) == 1 ? one : many);
        };
      if (n(quads) > 0 && n(simplex) > 0)
        throw InputError(
          "The mesh " + file + " mixes " +
            count(quads, dim == 2 ? "quadrilateral" : "hexahedron", quad_name) +
            " with " +
            count(simplex,
                  dim == 2 ? "triangle" : "tetrahedron",
                  simplex_name) +
            ": dualcontact takes one kind of cell. Recombine "
            "every surface in Gmsh ('Recombine Surface{:};' with "
            "'Mesh.Algorithm = 8;') for " +
            quad_name +
            ", or mesh without "
            "'Recombine' for " +
            simplex_name + " (doc/meshes.md).",
          exit_invalid_value);
      if (n(quads) + n(simplex) == 0)
        throw InputError("The mesh " + file + " has no " + quad_name +
                           " and no " + simplex_name +
                           ": Gmsh writes only the elements of physical "
                           "groups; give the domain one ('Physical " +
                           (dim == 2 ? "Surface" : "Volume") +
                           "(1) = {...};') or set 'Mesh.SaveAll = 1;'.",
                         exit_invalid_value);
    }

    /** A point as "(x, y)" for messages. */
    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::ostringstream out;
      out.precision(6);
      out << "(";
      for (unsigned int d = 0; d < dim; ++d)
        out << (d ? ", " : "") << p[d];
      out << ")";
      return out.str();
    }

    /**
     * The radial part of x: from the centre of the manifold's circle or
     * sphere, from the cylinder's axis normal to it.
     */
    template <int dim>
    Tensor<1, dim>
    radial_vector(const BoundaryManifold &manifold, const Point<dim> &x)
    {
      Tensor<1, dim> r = x - to_point<dim>(manifold.center);
      if (manifold.kind == BoundaryManifold::Kind::cylinder)
        {
          Tensor<1, dim> axis;
          for (unsigned int d = 0; d < dim; ++d)
            axis[d] = manifold.axis[d];
          axis /= axis.norm();
          r -= (r * axis) * axis;
        }
      return r;
    }

    /** Distance of x from the manifold's circle, sphere or cylinder axis. */
    template <int dim>
    double
    radial_distance(const BoundaryManifold &manifold, const Point<dim> &x)
    {
      return radial_vector(manifold, x).norm();
    }

    // the manifold id of the transfinite interpolation in the cells: above
    // every boundary id (0..255 in the entries)
    constexpr types::manifold_id interior_manifold_id = 1000;
  } // namespace

  template <int dim>
  void
  read_mesh_file(const GeometryParameters          &geometry,
                 Triangulation<dim>                &mesh,
                 const std::function<void(double)> &before_building)
  {
    const std::string     file = name_of(geometry);
    std::error_code       error;
    std::filesystem::path path(geometry.mesh_file);
    if (std::filesystem::is_directory(path, error))
      throw InputError("The mesh file " + file + " is a directory.",
                       exit_cannot_read_file);
    std::ifstream in(path);
    if (!in)
      throw InputError("Cannot open the mesh file " + file +
                         " (a relative path is taken from the folder of the "
                         ".prm file that sets it).",
                       exit_cannot_read_file);
    std::stringstream text;
    text << in.rdbuf();

    const MshContents contents = scan_msh(text, name_of(geometry));
    check_elements<dim>(contents, geometry);
    if (before_building)
      before_building(static_cast<double>(
        dim == 2 ? contents.count(MshContents::quad) +
                     contents.count(MshContents::triangle) :
                   contents.count(MshContents::hexahedron) +
                     contents.count(MshContents::tetrahedron)));
    // deal.II's reader turns over every cell of negative measure on its
    // own, a folded one as one listed clockwise: the shapes are checked on
    // the file's cells, with their tags and nodes, the same on every rank
    check_cell_shapes(contents, dim, file);

    text.clear();
    text.seekg(0);
    GridIn<dim> grid_in;
    grid_in.attach_triangulation(mesh);
    try
      {
        grid_in.read_msh(text);
      }
    catch (const std::exception &exception)
      {
        throw InputError("The mesh file " + file +
                           " cannot be read by deal.II's GridIn: " +
                           exception_message(exception),
                         exit_cannot_read_file);
      }

    // A boundary face in no physical group gets deal.II's default id 0,
    // which a condition meant for another part would then silently cover:
    // every boundary face must come from an element of the file.
    unsigned int n_boundary_faces = 0;
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary())
        ++n_boundary_faces;
    const unsigned long n_boundary_elements =
      dim == 2 ? contents.count(MshContents::line) :
                 contents.count(MshContents::quad) +
                   contents.count(MshContents::triangle);
    if (n_boundary_elements < n_boundary_faces)
      throw InputError("The mesh " + file + " has " +
                         plural(n_boundary_faces - n_boundary_elements,
                                "boundary face") +
                         " in no physical group (of " +
                         std::to_string(n_boundary_faces) +
                         "): every part of the boundary needs a boundary "
                         "id, e.g. 'Physical " +
                         (dim == 2 ? "Curve" : "Surface") +
                         "(0) = {...};' in the .geo file (doc/meshes.md).",
                       exit_inconsistent);
  }

  template <int dim>
  std::set<types::boundary_id>
  boundary_ids(const Triangulation<dim> &mesh)
  {
    std::set<types::boundary_id> ids;
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary())
        ids.insert(face->boundary_id());
    return ids;
  }

  template <int dim>
  void
  check_mesh_against_parameters(const Parameters         &parameters,
                                const Triangulation<dim> &mesh)
  {
    const GeometryParameters          &geometry = parameters.geometry;
    const std::set<types::boundary_id> ids      = boundary_ids(mesh);
    std::string                        id_list;
    for (const types::boundary_id id : ids)
      id_list += (id_list.empty() ? "" : ", ") + std::to_string(id);
    const auto check = [&](const types::boundary_id id,
                           const std::string       &entry) {
      if (ids.count(id) == 0)
        throw InputError("The entry <" + entry + "> names boundary id " +
                           std::to_string(id) + ", which the mesh " +
                           name_of(geometry) + " does not have (its ids are " +
                           id_list + ").",
                         exit_inconsistent);
    };
    for (const auto &[id, condition] : parameters.boundary.conditions)
      check(id, "Boundary conditions/Conditions");
    for (const BoundaryManifold &manifold : geometry.manifolds)
      check(manifold.id, "Geometry/Manifolds");

    for (const BoundaryManifold &manifold : geometry.manifolds)
      {
        const double tolerance = 1e-5 * manifold.radius;
        for (const auto &face : mesh.active_face_iterators())
          if (face->at_boundary() && face->boundary_id() == manifold.id)
            for (const unsigned int v : face->vertex_indices())
              {
                const double distance =
                  radial_distance(manifold, face->vertex(v));
                if (std::abs(distance - manifold.radius) > tolerance)
                  {
                    std::ostringstream figures;
                    figures.precision(6);
                    figures
                      << distance << " from the "
                      << (manifold.kind == BoundaryManifold::Kind::cylinder ?
                            "axis" :
                            "center")
                      << ", not the radius " << manifold.radius;
                    throw InputError(
                      "The entry <Geometry/Manifolds> puts boundary id " +
                        std::to_string(manifold.id) + " on a " +
                        manifold.kind_name() + " of center " +
                        point_text(to_point<dim>(manifold.center)) +
                        ", but the vertex " + point_text(face->vertex(v)) +
                        " of a face with that id in the mesh " +
                        name_of(geometry) + " is " + figures.str() +
                        ": the center, radius" +
                        (manifold.kind == BoundaryManifold::Kind::cylinder ?
                           ", axis" :
                           "") +
                        " or id does not match the mesh (tolerance 1e-5 R).",
                      exit_inconsistent);
                  }
              }
      }
  }

  template <int dim>
  void
  attach_manifolds(const GeometryParameters &geometry,
                   Triangulation<dim>       &triangulation)
  {
    if (geometry.manifolds.empty())
      return;
    // On simplices only the curved boundary faces follow their manifold:
    // deal.II 9.4's transfinite interpolation takes quadrilaterals and
    // hexahedra alone, so the cells stay flat.
    const bool simplex = cell_kind(triangulation) == CellKind::simplex;
    // The cells next to a curved boundary part follow the transfinite
    // interpolation of their boundary, so that their refined cells stay
    // well shaped; the other cells, the faces they share with those, and
    // the straight parts of the boundary stay flat (as in deal.II's
    // step-65; flat cells also spare the transfinite map's costly
    // pull-backs). The curved ids come last: an edge shared by a flat and a
    // curved boundary face is curved.
    std::set<types::boundary_id> curved;
    for (const BoundaryManifold &manifold : geometry.manifolds)
      curved.insert(manifold.id);
    const auto next_to_curved = [&curved](const auto &cell) {
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && curved.count(face->boundary_id()) > 0)
          return true;
      return false;
    };
    triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (!simplex && next_to_curved(cell))
        cell->set_all_manifold_ids(interior_manifold_id);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (!next_to_curved(cell))
        cell->set_all_manifold_ids(numbers::flat_manifold_id);
    for (const auto &face : triangulation.active_face_iterators())
      if (face->at_boundary())
        face->set_all_manifold_ids(numbers::flat_manifold_id);
    for (const BoundaryManifold &manifold : geometry.manifolds)
      {
        // by hand: set_all_manifold_ids_on_boundary() would also take
        // the edges whose own boundary id is manifold.id, and every edge
        // of a mesh read in 3D has the default boundary id 0
        for (const auto &face : triangulation.active_face_iterators())
          if (face->at_boundary() && face->boundary_id() == manifold.id)
            face->set_all_manifold_ids(manifold.id);
        const Point<dim> center = to_point<dim>(manifold.center);
        if (manifold.kind == BoundaryManifold::Kind::cylinder)
          {
            Tensor<1, dim> axis;
            for (unsigned int d = 0; d < dim; ++d)
              axis[d] = manifold.axis[d];
            // CylindricalManifold exists for dim = 3 only
            if constexpr (dim == 3)
              triangulation.set_manifold(manifold.id,
                                         CylindricalManifold<dim>(axis,
                                                                  center));
          }
        else
          triangulation.set_manifold(manifold.id,
                                     SphericalManifold<dim>(center));
      }
    if (simplex)
      return;
    TransfiniteInterpolationManifold<dim> interior;
    interior.initialize(triangulation);
    triangulation.set_manifold(interior_manifold_id, interior);
  }

  template <int dim>
  void
  snap_to_manifolds(const std::vector<BoundaryManifold> &manifolds,
                    Triangulation<dim>                  &triangulation)
  {
    for (const BoundaryManifold &manifold : manifolds)
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == manifold.id)
          for (const unsigned int v : face->vertex_indices())
            {
              // along the radius, away from the centre or the axis
              Point<dim>          &x        = face->vertex(v);
              const Tensor<1, dim> r        = radial_vector(manifold, x);
              const double         distance = r.norm();
              if (distance > 0.)
                x += (manifold.radius / distance - 1.) * r;
            }
  }

  template void
  read_mesh_file(const GeometryParameters &,
                 Triangulation<2> &,
                 const std::function<void(double)> &);
  template void
  read_mesh_file(const GeometryParameters &,
                 Triangulation<3> &,
                 const std::function<void(double)> &);
  template std::set<types::boundary_id>
  boundary_ids(const Triangulation<2> &);
  template std::set<types::boundary_id>
  boundary_ids(const Triangulation<3> &);
  template void
  check_mesh_against_parameters(const Parameters &, const Triangulation<2> &);
  template void
  check_mesh_against_parameters(const Parameters &, const Triangulation<3> &);
  template void
  snap_to_manifolds(const std::vector<BoundaryManifold> &, Triangulation<2> &);
  template void
  snap_to_manifolds(const std::vector<BoundaryManifold> &, Triangulation<3> &);
  template void
  attach_manifolds(const GeometryParameters &, Triangulation<2> &);
  template void
  attach_manifolds(const GeometryParameters &, Triangulation<3> &);
} // namespace dualcontact
