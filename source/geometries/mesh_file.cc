// <Geometry/Type> 'mesh file': the coarse mesh of a Gmsh file, its boundary
// ids the file's physical groups, its curved parts given by
// <Geometry/Manifolds> (doc/meshes.md); reading and checking the file is
// source/mesh_file.cc's.
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_tools.h>

#include <dualcontact/discretization.h>
#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/mesh_file.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    /**
     * <Geometry/Manifolds>: "id: kind center x, y[, z] radius R [axis a, b,
     * c]; ...". The counts of coordinates are checked against the dimension
     * in GeometryParameters::check().
     */
    std::vector<BoundaryManifold>
    parse_manifolds(const std::string &text)
    {
      const std::string entry = "<Geometry/Manifolds>";
      const std::string form =
        " (expected 'id: circle center x, y radius R', 'id: sphere center x, "
        "y, z radius R' or 'id: cylinder center x, y, z axis a, b, c radius "
        "R', separated by ';')";
      std::vector<BoundaryManifold> result;
      for (const std::string &item : Utilities::split_string_list(text, ';'))
        {
          if (item.empty())
            continue;
          const auto colon = item.find(':');
          const auto bad   = [&](const std::string &what) {
            return InputError("The entry " + entry + " has '" + item +
                                "': " + what + form + ".",
                              exit_invalid_value);
          };
          if (colon == std::string::npos)
            throw bad("no 'id:' in front");
          BoundaryManifold  manifold;
          const std::string id_text = Utilities::trim(item.substr(0, colon));
          if (id_text.empty() ||
              id_text.find_first_not_of("0123456789") != std::string::npos ||
              id_text.size() > 3 || std::stoi(id_text) > 255)
            throw bad("'" + id_text + "' is not a boundary id (0 to 255)");
          manifold.id = static_cast<boundary_id>(std::stoi(id_text));

          std::string words = item.substr(colon + 1);
          std::replace(words.begin(), words.end(), ',', ' ');
          std::istringstream in(words);
          std::string        kind;
          in >> kind;
          if (!manifold_kind_names().has(kind))
            throw bad("'" + kind + "' is not a kind of manifold (" +
                      manifold_kind_names().names(", ") + ")");
          manifold.kind = manifold_kind_names().value(kind);

          // keyword, then its numbers up to the next keyword
          std::map<std::string, std::vector<double>> values;
          std::string                                word, key;
          while (in >> word)
            {
              if (word == "center" || word == "radius" || word == "axis")
                {
                  key = word;
                  if (!values.emplace(key, std::vector<double>()).second)
                    throw bad("'" + key + "' is given twice");
                  continue;
                }
              std::size_t used  = 0;
              double      value = 0.;
              try
                {
                  value = std::stod(word, &used);
                }
              catch (const std::exception &)
                {
                  used = 0;
                }
              if (key.empty() || used != word.size() || !std::isfinite(value))
                throw bad("'" + word +
                          "' is neither a number nor one of "
                          "center, radius, axis");
              values[key].push_back(value);
            }
          if (values.count("center") == 0 || values.count("radius") == 0)
            throw bad("a manifold needs its center and its radius");
          manifold.center = values["center"];
          if (values["radius"].size() != 1 || !(values["radius"][0] > 0.))
            throw bad("the radius must be one positive number");
          manifold.radius = values["radius"][0];
          if (manifold.kind == BoundaryManifold::Kind::cylinder)
            {
              if (values.count("axis") == 0)
                throw bad("a cylinder needs its axis");
              manifold.axis = values["axis"];
            }
          else if (values.count("axis") > 0)
            throw bad("only a cylinder has an axis");
          for (const BoundaryManifold &earlier : result)
            if (earlier.id == manifold.id)
              throw bad("boundary id " + id_text + " is given twice");
          result.push_back(manifold);
        }
      return result;
    }


    template <int dim>
    class MeshFile : public Geometry<dim>
    {
    public:
      /**
       * Reads the file's coarse mesh on every rank (it is small): its size
       * is the scene's length, and its boundary ids are what the conditions
       * must name.
       */
      MeshFile(const Parameters                  &parameters,
               const std::function<void(double)> &before_building)
          : g(parameters.geometry)
      {
        // the file's cells, times 2^dim per initial global refinement
        const double refined =
          std::pow(std::pow(2., dim),
                   parameters.refinement.initial_global_refinement);
        read_mesh_file(g,
                       coarse_mesh,
                       [&before_building, refined](const double n_cells) {
                         if (before_building)
                           before_building(n_cells * refined);
                       });
        check_mesh_against_parameters(parameters, coarse_mesh);
        if (dualcontact::cell_kind(coarse_mesh) == CellKind::simplex)
          GeometryParameters::check_simplices(
            parameters, std::string("the cells of <Geometry/Mesh file>"));
        else if (g.cell_kind == CellKind::simplex)
          convert_to_simplices(coarse_mesh, g.manifolds);
        const auto box = GridTools::compute_bounding_box(coarse_mesh);
        lower_left     = box.get_boundary_points().first;
        upper_right    = box.get_boundary_points().second;
      }

      CellKind
      cell_kind() const override
      {
        return dualcontact::cell_kind(coarse_mesh);
      }

      void
      create_coarse_mesh(Triangulation<dim> &triangulation) const override
      {
        // refinement follows the manifolds of <Geometry/Manifolds>
        triangulation.copy_triangulation(coarse_mesh);
        attach_manifolds(g, triangulation);
      }

      /** The centre of the mesh's bounding box. */
      Point<dim>
      center() const override
      {
        return 0.5 * (lower_left + upper_right);
      }

      /** The longest side of the mesh's bounding box. */
      double
      characteristic_length() const override
      {
        double length = 0;
        for (unsigned int d = 0; d < dim; ++d)
          length = std::max(length, upper_right[d] - lower_left[d]);
        return length;
      }

      /**
       * A mapping of degree k follows the manifolds: without them the
       * boundary stays the polygon of the file's faces.
       */
      std::string
      mapping_warning(const unsigned int degree) const override
      {
        if (degree <= 1 || !g.manifolds.empty())
          return "";
        return "<Geometry/Manifolds> is empty: the boundary of the mesh file "
               "stays the polygon of its faces at <Discretization/Polynomial "
               "degree> " +
               std::to_string(degree) +
               " as at 1; name its curved parts there for the mapping to "
               "follow them.";
      }

    private:
      const GeometryParameters &g;
      Triangulation<dim>        coarse_mesh;
      Point<dim>                lower_left, upper_right;
    };

    template <int dim>
    std::unique_ptr<Geometry<dim>>
    make(const Parameters                  &parameters,
         const std::function<void(double)> &before_building)
    {
      return std::make_unique<MeshFile<dim>>(parameters, before_building);
    }

    void
    declare(EntryDeclarer &declarer)
    {
      declarer.declare_entry(
        "Mesh file",
        "",
        EntryPattern::file_name(),
        "Type 'mesh file': the Gmsh mesh (.msh, ASCII, format 2.2 or 4.1), a "
        "path relative to the folder of the .prm file that sets it (given by "
        "--set: relative to the working directory). It must hold one kind of "
        "cell, quadrilaterals or triangles (2D), hexahedra or tetrahedra (3D): "
        "the coarse mesh that the refinement starts from. Physical groups of curves (2D) or surfaces "
        "(3D) become boundary ids, the numbers of <Boundary conditions/"
        "Conditions>; every boundary face must be in one (Gmsh's 'Physical "
        "Curve(0) = {...};' gives id 0). Coordinates are in [length].");
      declarer.declare_entry(
        "Manifolds",
        "",
        EntryPattern::text(),
        "Type 'mesh file': the curved parts of the boundary, so that refinement "
        "puts new vertices on the curve instead of on the straight line "
        "between old ones. A list separated by ';' of 'id: circle center x, y "
        "radius R' (2D), 'id: sphere center x, y, z radius R' or 'id: cylinder "
        "center x, y, z axis a, b, c radius R' (3D: the cylinder's axis passes "
        "through the center in direction (a, b, c)), e.g. '0: circle center 0, "
        "0 radius 1'. Center and radius in [length]. Every vertex of a "
        "boundary face with that id must lie on the curve (within 1e-5 R). The "
        "interior then follows a transfinite interpolation of the boundary, "
        "so that refined cells stay well shaped. Empty: every face stays "
        "straight.");
    }

    void
    parse(ParameterHandler &prm, GeometryParameters &geometry)
    {
      geometry.mesh_file       = prm.get("Mesh file");
      geometry.mesh_file_given = geometry.mesh_file;
      geometry.manifolds       = parse_manifolds(prm.get("Manifolds"));
    }

    void
    check_magnitudes(const GeometryParameters &geometry)
    {
      for (const BoundaryManifold &manifold : geometry.manifolds)
        check_curved_boundary(manifold.radius,
                              manifold.center,
                              "Geometry/Manifolds",
                              geometry.dimension);
    }

    void
    check(const Parameters &parameters)
    {
      if (parameters.geometry.mesh_file.find_first_not_of(" \t") ==
          std::string::npos)
        throw InputError("The entry <Geometry/Type> is 'mesh file' but "
                         "<Geometry/Mesh file> names no file.",
                         exit_inconsistent);
    }

    std::vector<std::pair<std::string, std::string>>
    size_entries(const GeometryParameters &geometry)
    {
      return {{"Geometry/Mesh file", geometry.mesh_file_given}};
    }

    const bool registered = register_geometry(
      "mesh file",
      {5,
       "'mesh file': the "
       "coarse mesh of <Geometry/Mesh file> (Gmsh: quadrilaterals or "
       "triangles in 2D, hexahedra or tetrahedra in 3D), whose physical "
       "groups are the boundary ids; "
       "<Geometry/Manifolds> makes curved parts stay curved under refinement "
       "(doc/meshes.md).",
       declare,
       parse,
       {"Mesh file", "Manifolds"},
       {{{"Mesh file", "Manifolds"}, "'mesh file'"}},
       {},
       nullptr,
       nullptr,
       check_magnitudes,
       check,
       nullptr,
       size_entries,
       make<2>,
       make<3>});
  } // namespace
} // namespace dualcontact
