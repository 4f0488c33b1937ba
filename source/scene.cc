#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <dualcontact/discretization.h>
#include <dualcontact/input_error.h>
#include <dualcontact/mesh_file.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/scene.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    /**
     * A FunctionParser of `expression` in `variables` (the time t last if
     * `of_time`), or nullptr if muparser refuses it. deal.II prints
     * muparser's diagnostics on std::cerr before it throws; the user gets
     * our one-line message instead.
     */
    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    try_parse(const std::string                   &expression,
              const unsigned int                   n_components,
              const std::string                   &variables,
              const std::map<std::string, double> &constants,
              const bool                           of_time,
              const double                         length)
    {
      // Gradients (for H1 errors) by fourth-order differences with a step
      // relative to the body's size.
      auto function =
        std::make_unique<FunctionParser<dim>>(n_components, 0., 1e-4 * length);
      function->set_formula(AutoDerivativeFunction<dim>::FourthOrder);
      std::ostringstream    muparser_diagnostics;
      std::streambuf *const cerr_buffer =
        std::cerr.rdbuf(muparser_diagnostics.rdbuf());
      try
        {
          function->initialize(variables, expression, constants, of_time);
          // muparser may defer some errors to the first evaluation
          Vector<double> values(n_components);
          function->vector_value(Point<dim>(), values);
        }
      catch (const std::exception &)
        {
          function.reset();
        }
      std::cerr.rdbuf(cerr_buffer);
      return function;
    }

    /**
     * <Obstacle/Displacement>, "U_x; U_y" (U_z), as dim functions of the
     * one variable t (evaluated at the point t); checked finite at the
     * steps' times.
     */
    template <int dim>
    std::unique_ptr<FunctionParser<1>>
    make_path(const std::string         &expression,
              const std::vector<double> &times,
              const double               length)
    {
      auto path = try_parse<1>(
        expression, dim, "t", {{"pi", numbers::PI}}, false, length);
      if (path == nullptr)
        throw InputError("The entry <Obstacle/Displacement> is not a valid "
                         "expression in t: '" +
                           expression + "'.",
                         exit_invalid_value);
      for (const double t : times)
        for (unsigned int c = 0; c < dim; ++c)
          if (!std::isfinite(path->value(Point<1>(t), c)))
            throw InputError("The entry <Obstacle/Displacement> is not a "
                             "finite number (NaN or infinity) at t = " +
                               number_text(t) + ": '" + expression + "'.",
                             exit_invalid_value);
      return path;
    }
  } // namespace

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_function(const std::string         &expression,
                const unsigned int         n_components,
                const MaterialParameters  &material,
                const std::string         &entry,
                const double               length,
                const std::vector<double> &times)
  {
    const std::map<std::string, double> constants = {
      {"pi", numbers::PI},
      {"E", material.youngs_modulus},
      {"nu", material.poissons_ratio},
      {"lambda", material.lambda()},
      {"mu", material.mu()}};
    const bool        of_time   = !times.empty();
    const std::string space     = dim == 2 ? "x,y" : "x,y,z";
    const std::string variables = space + (of_time ? ",t" : "");

    // the count is checked whatever the values: '0' or '0; 0' for a 3D
    // vector is as wrong as '1; 2' (a 3D scene's default body force is
    // '0; 0; 0', Parameters::use)
    const auto n_given = Utilities::split_string_list(expression, ';').size();
    if (n_given != n_components)
      throw InputError("The entry <" + entry + "> needs " +
                         std::to_string(n_components) +
                         " expression(s) separated by ';', not " +
                         std::to_string(n_given) + ": '" + expression + "'.",
                       exit_invalid_value);

    auto function = try_parse<dim>(
      expression, n_components, variables, constants, of_time, length);
    if (function == nullptr)
      {
        if (!of_time && try_parse<dim>(expression,
                                       n_components,
                                       space + ",t",
                                       constants,
                                       true,
                                       length) != nullptr)
          throw InputError(
            "The entry <" + entry + "> may not depend on the time t: '" +
              expression +
              "'. Only the loads (<Boundary conditions/Tractions>, <Boundary "
              "conditions/Displacements>, <Loads/Body force>) and "
              "<Obstacle/Displacement> follow the load path.",
            exit_invalid_value);
        throw InputError("The entry <" + entry +
                           "> is not a valid expression in " + variables +
                           ": '" + expression + "'.",
                         exit_invalid_value);
      }
    // An expression without x, y, z is one number at each time: NaN or
    // infinity (0/0, 1/0) is refused here. One that depends on the position
    // is checked where it is used (loads, friction at the contact nodes,
    // errors).
    const bool follows_path = of_time && uses_time(expression);
    if (!uses_coordinates(expression, dim))
      for (const double t : follows_path ? times : std::vector<double>{0.})
        {
          function->set_time(t);
          Vector<double> values(n_components);
          function->vector_value(Point<dim>(), values);
          for (const double value : values)
            if (!std::isfinite(value))
              throw InputError("The entry <" + entry +
                                 "> is not a finite number (NaN or infinity)" +
                                 (follows_path ? " at t = " + number_text(t) :
                                                 std::string()) +
                                 ": '" + expression + "'.",
                               exit_invalid_value);
        }
    return function;
  }


  namespace
  {
    /**
     * The Gram matrix G_ij = int_{fixed} m_i.m_j + int_{normal fixed}
     * (m_i.n)(m_j.n) of displacement modes m_i(x) (mode(i, x, cell), on the
     * cell at x) over the constrained part of the boundary, summed over the
     * ranks; `measure` gets that part's length (area). A mode is left free
     * by the constraints iff G m = 0.
     */
    template <int dim, typename Mode>
    FullMatrix<double>
    constrained_gram(const Triangulation<dim>           &triangulation,
                     const std::set<types::boundary_id> &fixed,
                     const std::set<types::boundary_id> &slider,
                     const unsigned int                  n_modes,
                     const Mode                         &mode,
                     double                             &measure)
    {
      // the cells' straight-sided map: the boundary as its vertices'
      // polygon (or polyhedron) is exact enough for the question asked
      const CellKind                      kind = cell_kind(triangulation);
      const FE_Nothing<dim>               fe(kind == CellKind::simplex ?
                                 ReferenceCells::get_simplex<dim>() :
                                 ReferenceCells::get_hypercube<dim>());
      const std::unique_ptr<Mapping<dim>> mapping = make_mapping<dim>(kind, 1);
      const Quadrature<dim - 1>           quadrature = face_quadrature(fe, 2);
      FEFaceValues<dim>                   fe_face(*mapping,
                                fe,
                                quadrature,
                                update_quadrature_points |
                                  update_normal_vectors | update_JxW_values);
      FullMatrix<double>                  gram(n_modes, n_modes);
      measure = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && (fixed.count(face->boundary_id()) ||
                                        slider.count(face->boundary_id())))
              {
                const bool all = fixed.count(face->boundary_id()) > 0;
                fe_face.reinit(cell, face);
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  {
                    const Point<dim>     &x = fe_face.quadrature_point(q);
                    const Tensor<1, dim> &n = fe_face.normal_vector(q);
                    measure += fe_face.JxW(q);
                    for (unsigned int i = 0; i < n_modes; ++i)
                      for (unsigned int j = 0; j < n_modes; ++j)
                        gram(i, j) +=
                          fe_face.JxW(q) *
                          (all ?
                             mode(i, x, cell) * mode(j, x, cell) :
                             (mode(i, x, cell) * n) * (mode(j, x, cell) * n));
                  }
              }
      const MPI_Comm comm = triangulation.get_communicator();
      for (unsigned int i = 0; i < n_modes; ++i)
        for (unsigned int j = 0; j < n_modes; ++j)
          gram(i, j) = Utilities::MPI::sum(gram(i, j), comm);
      measure = Utilities::MPI::sum(measure, comm);
      return gram;
    }
  } // namespace

  namespace
  {
    /**
     * The half disc (3D: half ball) below its flat top through `center`,
     * normal +e_{dim-1}, or in 2D with `quarter` its lower right quarter; no
     * manifolds, ids 0. In 2D both are made of deal.II's quarter ball (the
     * quadrant x, y >= 0) turned by -90 degrees (lower right quarter) and,
     * for the half disc, by 180 degrees (lower left quarter): the quarter
     * ball is symmetric about its diagonal, so the half disc's mesh is
     * symmetric about the line x = x_c, which is a mesh line, and its right
     * half is exactly the quarter disc's mesh. In 3D the half ball x >= 0
     * is turned so that its cut plane is the top.
     */
    template <int dim>
    void
    make_lower_half_disc(Triangulation<dim> &result,
                         const Point<dim>   &center,
                         const double        radius,
                         const bool          quarter)
    {
      const auto turn = [&](const auto &rotation) {
        Triangulation<dim> part;
        if (dim == 2)
          GridGenerator::quarter_hyper_ball(part, Point<dim>(), radius);
        else
          GridGenerator::half_hyper_ball(part, Point<dim>(), radius);
        GridTools::transform(rotation, part);
        return part;
      };
      const auto lower_right = turn([&](const Point<dim> &p) {
        Point<dim> q;
        if (dim == 2)
          q = Point<dim>(p[1], -p[0]);
        else // a proper rotation: (x,y,z) -> (-y, z, -x)
          {
            q[0]       = -p[1];
            q[1]       = p[dim - 1];
            q[dim - 1] = -p[0];
          }
        return q + center;
      });
      if (dim == 2 && !quarter)
        GridGenerator::merge_triangulations(lower_right,
                                            turn([&](const Point<dim> &p) {
                                              return center - p;
                                            }),
                                            result);
      else
        result.copy_triangulation(lower_right);
      result.reset_all_manifolds();
    }

    /**
     * The bodies `parts` in one coarse mesh that shares no vertex between
     * them, not even where they touch (GridGenerator::merge_triangulations
     * would glue those): body i's cells get material id i. Boundary ids
     * are the caller's to set.
     */
    template <int dim>
    void
    join_bodies(const std::vector<const Triangulation<dim> *> &parts,
                Triangulation<dim>                            &result)
    {
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      for (unsigned int body = 0; body < parts.size(); ++body)
        {
          const unsigned int offset = vertices.size();
          vertices.insert(vertices.end(),
                          parts[body]->get_vertices().begin(),
                          parts[body]->get_vertices().end());
          for (const auto &cell : parts[body]->active_cell_iterators())
            {
              CellData<dim> data(cell->n_vertices());
              for (const unsigned int v : cell->vertex_indices())
                data.vertices[v] = offset + cell->vertex_index(v);
              data.material_id = body;
              cells.push_back(data);
            }
        }
      result.create_triangulation(vertices, cells, SubCellData());
    }

    /**
     * Two half discs (3D: half balls) that touch at `contact`: the upper
     * one (radius R1, material id 1) below its flat top, the lower one
     * (radius R2, material id 0) above its flat bottom, the mesh of a lower
     * half disc turned by 180 degrees (about the x axis in 3D), a proper
     * rotation. Boundary ids: 0 on the upper body's curved part, 1 on its
     * top, 2 on the lower body's curved part, 3 on its bottom. The caller
     * attaches the manifolds: the circles (spheres) 0 and 2 and a
     * transfinite interpolation inside.
     */
    template <int dim>
    void
    make_two_half_discs(Triangulation<dim> &result,
                        const Point<dim>   &contact,
                        const double        upper_radius,
                        const double        lower_radius)
    {
      Point<dim> upper_center(contact), lower_center(contact);
      upper_center[dim - 1] += upper_radius;
      lower_center[dim - 1] -= lower_radius;
      Triangulation<dim> upper, lower;
      make_lower_half_disc(upper, upper_center, upper_radius, false);
      make_lower_half_disc(lower, Point<dim>(), lower_radius, false);
      GridTools::transform(
        [&](const Point<dim> &p) {
          Point<dim> q = -p;
          if (dim == 3)
            q[0] = p[0];
          return q + lower_center;
        },
        lower);
      join_bodies<dim>({&lower, &upper}, result);
      // The ids of the faces and, in 3D, of their edges: the manifolds
      // follow the edges' ids, and a new mesh has 0 on every boundary edge.
      // The flat faces first, then the curved ones: a rim edge lies on the
      // sphere (and in the flat side through its centre) and takes the
      // sphere's id.
      for (const bool flat_pass : {true, false})
        for (const auto &cell : result.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const bool   on_upper = cell->material_id() == 1;
                const double radius   = on_upper ? upper_radius : lower_radius;
                // the flat sides pass through the discs' centres
                const double flat =
                  on_upper ? upper_center[dim - 1] : lower_center[dim - 1];
                const bool is_flat =
                  std::abs(face->center()[dim - 1] - flat) < 1e-8 * radius;
                if (is_flat == flat_pass)
                  face->set_all_boundary_ids((on_upper ? 0 : 2) +
                                             (is_flat ? 1 : 0));
              }
    }

    /**
     * The pre-refinement band of a scene whose contact is between bodies:
     * the vertices of the pairs' surfaces (slave and master ids) of all
     * ranks with their bodies, binned in squares (cubes) of the band's
     * width, so that a vertex finds those within the width in the 3^dim
     * bins around it.
     */
    template <int dim>
    class PairBand
    {
    public:
      PairBand() = default;

      PairBand(const Triangulation<dim> &triangulation,
               const std::map<types::boundary_id, types::boundary_id> &pairs,
               const double                                            width)
          : width(std::max(width, std::numeric_limits<double>::min()))
          , bodies(bodies_of_coarse_cells(triangulation))
      {
        std::set<types::boundary_id> ids;
        for (const auto &[slave, master] : pairs)
          {
            ids.insert(slave);
            ids.insert(master);
          }
        std::vector<double> local;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() && ids.count(face->boundary_id()))
                for (const unsigned int v : face->vertex_indices())
                  {
                    for (unsigned int d = 0; d < dim; ++d)
                      local.push_back(face->vertex(v)[d]);
                    local.push_back(body_of<dim>(cell, bodies));
                  }
        for (const auto &part :
             Utilities::MPI::all_gather(triangulation.get_communicator(),
                                        local))
          for (std::size_t i = 0; i + dim < part.size(); i += dim + 1)
            {
              Point<dim> x;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = part[i + d];
              bins[bin_of(x)].emplace_back(
                x, static_cast<unsigned int>(part[i + dim]));
            }
      }

      /** Whether vertex v of `cell` lies within the width of another body's
       * paired surface. */
      template <typename Iterator>
      bool
      near(const Iterator &cell, const unsigned int v) const
      {
        const Point<dim>   x    = cell->vertex(v);
        const unsigned int body = body_of<dim>(cell, bodies);
        const auto         home = bin_of(x);
        for (unsigned int k = 0; k < std::pow(3, dim); ++k)
          {
            auto         key  = home;
            unsigned int rest = k;
            for (unsigned int d = 0; d < dim; ++d, rest /= 3)
              key[d] += static_cast<long>(rest % 3) - 1;
            const auto it = bins.find(key);
            if (it != bins.end())
              for (const auto &[p, other] : it->second)
                if (other != body && x.distance(p) <= width)
                  return true;
          }
        return false;
      }

    private:
      std::array<long, dim>
      bin_of(const Point<dim> &x) const
      {
        std::array<long, dim> key;
        for (unsigned int d = 0; d < dim; ++d)
          key[d] = static_cast<long>(std::floor(x[d] / width));
        return key;
      }

      double                    width = 0.;
      std::vector<unsigned int> bodies;
      std::map<std::array<long, dim>,
               std::vector<std::pair<Point<dim>, unsigned int>>>
        bins;
    };

    /**
     * Two boxes [lower, cut_low] and [cut_high, upper] that touch on the cut
     * x_{dim-1} = cut, each subdivided on its own, in one coarse mesh whose
     * vertices on the cut are not shared: two bodies. Boundary ids as a
     * box's (2 d on each block's lower, 2 d + 1 on its upper side along
     * x_d), and
     * on the cut 2 dim for the lower block's top and 2 dim + 1 for the upper
     * block's bottom; material id 0 for the lower and 1 for the upper block.
     */
    template <int dim>
    void
    make_two_blocks(Triangulation<dim>              &result,
                    const std::vector<unsigned int> &lower_subdivisions,
                    const std::vector<unsigned int> &upper_subdivisions,
                    const Point<dim>                &lower,
                    const Point<dim>                &cut_low,
                    const Point<dim>                &cut_high,
                    const Point<dim>                &upper,
                    const bool                       simplex)
    {
      std::array<Triangulation<dim>, 2> blocks;
      for (const unsigned int block : {0u, 1u})
        {
          const auto &n = block == 0 ? lower_subdivisions : upper_subdivisions;
          const Point<dim> &a = block == 0 ? lower : cut_high;
          const Point<dim> &b = block == 0 ? cut_low : upper;
          if (simplex)
            GridGenerator::subdivided_hyper_rectangle_with_simplices(
              blocks[block], n, a, b);
          else
            GridGenerator::subdivided_hyper_rectangle(blocks[block], n, a, b);
        }
      join_bodies<dim>({&blocks[0], &blocks[1]}, result);
      const double cut = cut_low[dim - 1];
      for (const auto &cell : result.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> x = face->center();
              // the corners of the face's block
              const bool        lower_block = cell->material_id() == 0;
              const Point<dim> &a           = lower_block ? lower : cut_high;
              const Point<dim> &b           = lower_block ? cut_low : upper;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const double tolerance = 1e-10 * (b[d] - a[d]);
                  if (d == dim - 1 && std::abs(x[d] - cut) < tolerance)
                    face->set_boundary_id(2 * dim + cell->material_id());
                  else if (std::abs(x[d] - a[d]) < tolerance)
                    face->set_boundary_id(2 * d);
                  else if (std::abs(x[d] - b[d]) < tolerance)
                    face->set_boundary_id(2 * d + 1);
                }
            }
    }
  } // namespace

  template <int dim>
  std::vector<unsigned int>
  bodies_of_coarse_cells(const Triangulation<dim> &triangulation)
  {
    const unsigned int        n_cells = triangulation.n_cells(0);
    std::vector<unsigned int> parent(n_cells);
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&parent](unsigned int i) {
      while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    };
    std::map<unsigned int, unsigned int> first_cell_at_vertex;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int v : cell->vertex_indices())
        {
          const auto [it, inserted] =
            first_cell_at_vertex.emplace(cell->vertex_index(v), cell->index());
          if (!inserted)
            {
              const unsigned int a = root(it->second), b = root(cell->index());
              parent[std::max(a, b)] = std::min(a, b);
            }
        }
    // 0, 1, ... in the order of each body's first coarse cell
    std::vector<unsigned int>            body(n_cells);
    std::map<unsigned int, unsigned int> number;
    for (unsigned int i = 0; i < n_cells; ++i)
      body[i] = number.emplace(root(i), number.size()).first->second;
    return body;
  }

  template std::vector<unsigned int>
  bodies_of_coarse_cells(const Triangulation<2> &);
  template std::vector<unsigned int>
  bodies_of_coarse_cells(const Triangulation<3> &);

  std::string
  Effects::describe() const
  {
    std::ostringstream out;
    out << "  contact with the obstacle   : "
        << (obstacle_contact ? "yes: Uzawa on the modified Lagrangian" :
            contact          ? "no" :
                               "no: one linear elasticity solve per mesh")
        << '\n';
    if (obstacle_contact)
      out << "  obstacle                    : " << obstacle << '\n';
    if (!pairs.empty())
      out << "  contact between bodies      : slave on master " << pairs << ": "
          << pair_coupling << ", Uzawa on the modified Lagrangian\n";
    out << "  friction                    : "
        << (!contact      ? "no (no contact)" :
            zero_friction ? "no: the coefficient/threshold is zero, the "
                            "frictionless path runs" :
                            friction->description())
        << '\n'
        << "  body force                  : "
        << (body_force ? "yes" : "no (not assembled)") << '\n'
        << "  boundary tractions          : "
        << (tractions ? "yes" : "no (not assembled)") << '\n';
    return out.str();
  }

  template <int dim>
  Scene<dim>::Scene(const Parameters                  &parameters,
                    const std::function<void(double)> &before_building)
      : parameters(parameters)
  {
    AssertThrow(parameters.geometry.dimension == dim,
                ExcMessage("Scene<dim> built for the wrong dimension."));

    // The coarse mesh of a mesh file is read first, on every rank (it is
    // small): its size is the scene's length, and its boundary ids are
    // what the conditions must name.
    if (parameters.geometry.type == GeometryType::mesh_file)
      {
        // the file's cells, times 2^dim per initial global refinement
        const double refined =
          std::pow(std::pow(2., dim),
                   parameters.refinement.initial_global_refinement);
        read_mesh_file(parameters.geometry,
                       coarse_mesh,
                       [&before_building, refined](const double n_cells) {
                         if (before_building)
                           before_building(n_cells * refined);
                       });
        check_mesh_against_parameters(parameters, coarse_mesh);
        if (dualcontact::cell_kind(coarse_mesh) == CellKind::simplex)
          GeometryParameters::check_simplices(
            parameters, std::string("the cells of <Geometry/Mesh file>"));
        else if (parameters.geometry.cell_kind == CellKind::simplex)
          {
            // each quadrilateral into 8 triangles (hexahedron into 24
            // tetrahedra), the new vertices of curved faces onto their curve
            Triangulation<dim> simplices;
            GridGenerator::convert_hypercube_to_simplex_mesh(coarse_mesh,
                                                             simplices);
            snap_to_manifolds(parameters.geometry.manifolds, simplices);
            coarse_mesh.clear();
            coarse_mesh.copy_triangulation(simplices);
          }
        const auto box   = GridTools::compute_bounding_box(coarse_mesh);
        mesh_lower_left  = box.get_boundary_points().first;
        mesh_upper_right = box.get_boundary_points().second;
      }

    kind_ = parameters.geometry.type == GeometryType::mesh_file ?
              dualcontact::cell_kind(coarse_mesh) :
              parameters.geometry.cell_kind;

    const MaterialParameters &material = parameters.material;
    const BoundaryParameters &boundary = parameters.boundary;
    const double              length   = characteristic_length();
    // the loads follow the load path (doc/theory.md §11)
    const std::vector<double> times = parameters.load_path.step_times();

    // A load or a prescribed displacement: its function, or none where it
    // is zero (nothing to assemble or to interpolate), with the count of
    // its components checked in either case.
    const auto load = [&](const std::string &expression,
                          const std::string &entry) {
      auto function =
        make_function<dim>(expression, dim, material, entry, length, times);
      return is_zero_expression(expression) ? nullptr : std::move(function);
    };
    for (const types::boundary_id id : ids_with(BoundaryCondition::fixed))
      {
        const auto it = boundary.displacements.find(id);
        if (it != boundary.displacements.end())
          if (auto function =
                load(it->second, "Boundary conditions/Displacements"))
            displacements[id] = std::move(function);
      }
    for (const types::boundary_id id : ids_with(BoundaryCondition::traction))
      if (auto function =
            load(boundary.tractions.at(id), "Boundary conditions/Tractions"))
        tractions[id] = std::move(function);
    body_force_ = load(parameters.loads.body_force, "Loads/Body force");
    if (!parameters.exact.displacement.empty())
      exact_ = make_function<dim>(parameters.exact.displacement,
                                  dim,
                                  material,
                                  "Exact solution/Displacement",
                                  length);

    if (!parameters.exact.contact_pressure.empty())
      exact_pressure_ = make_function<dim>(parameters.exact.contact_pressure,
                                           1,
                                           material,
                                           "Exact solution/Contact pressure",
                                           length);

    // the obstacle is needed only with contact, but a plane is always
    // there (its entries have defaults), so that gaps are defined; its
    // translation U(t) is a function of the time alone
    std::string path;
    for (const std::string &component :
         parameters.obstacle.displacement_components())
      path += (path.empty() ? "" : "; ") + component;
    if (!path.empty())
      obstacle_path = make_path<dim>(path, times, length);
    obstacle_ =
      std::make_unique<PlacedObstacle<dim>>(create_obstacle<dim>(parameters,
                                                                 length),
                                            Tensor<1, dim>(),
                                            obstacle_entries_text(parameters));
    set_time(times.front());

    effects_.contact =
      !ids_with(BoundaryCondition::contact).empty() || !contact_pairs().empty();
    effects_.obstacle_contact = !ids_with(BoundaryCondition::contact).empty();
    for (const auto &[slave, master] : contact_pairs())
      effects_.pairs += (effects_.pairs.empty() ? "" : ", ") +
                        std::to_string(slave) + " on " + std::to_string(master);
    effects_.pair_coupling = parameters.boundary.node_to_segment ?
                               "node to segment (one pass)" :
                               "dual mortar";
    effects_.obstacle      = (*obstacle_)->description();
    obstacle_moves_        = obstacle_->displacement().norm() > 0;
    if (obstacle_path != nullptr && times.size() > 1 && uses_time(path))
      {
        obstacle_moves_ = true;
        effects_.obstacle += ", moved by U(t) = (" + path + ")";
      }
    else if (obstacle_->displacement().norm() > 0)
      {
        std::ostringstream moved;
        moved << ", moved by (" << obstacle_->displacement() << ")";
        effects_.obstacle += moved.str();
      }
    effects_.friction           = create_friction_law(parameters.friction.law);
    const std::string parameter = effects_.friction->parameter_entry();
    if (effects_.contact && !parameter.empty())
      {
        const std::string &expression = parameters.friction.parameter;
        const std::string  entry      = "Friction/" + parameter;
        friction_ = make_function<dim>(expression, 1, material, entry, length);
        if (is_zero_expression(expression))
          {
            effects_.zero_friction = true;
            effects_.friction      = create_friction_law("none");
            friction_.reset();
          }
        else if (friction_->value(center()) < 0. &&
                 expression.find_first_of("xyz") == std::string::npos)
          throw InputError("The entry <" + entry + "> must not be negative.",
                           exit_invalid_value);
      }
    effects_.body_force = body_force_ != nullptr;
    effects_.tractions  = !tractions.empty();
  }

  template <int dim>
  void
  Scene<dim>::set_time(const double t)
  {
    time_ = t;
    for (auto &[id, function] : displacements)
      function->set_time(t);
    for (auto &[id, function] : tractions)
      function->set_time(t);
    if (body_force_ != nullptr)
      body_force_->set_time(t);
    Tensor<1, dim> U;
    if (obstacle_path != nullptr)
      {
        for (unsigned int c = 0; c < dim; ++c)
          U[c] = obstacle_path->value(Point<1>(t), c);
      }
    obstacle_->move_to(U);
  }

  template <int dim>
  std::set<types::boundary_id>
  Scene<dim>::ids_with(const BoundaryCondition condition) const
  {
    const auto ids = parameters.boundary.ids_with(condition);
    return {ids.begin(), ids.end()};
  }

  template <int dim>
  const Function<dim> &
  Scene<dim>::displacement(const types::boundary_id id) const
  {
    const auto it = displacements.find(id);
    return it == displacements.end() ?
             static_cast<const Function<dim> &>(zero) :
             *it->second;
  }

  template <int dim>
  const Function<dim> *
  Scene<dim>::traction(const types::boundary_id id) const
  {
    const auto it = tractions.find(id);
    return it == tractions.end() ? nullptr : it->second.get();
  }

  template <int dim>
  double
  Scene<dim>::characteristic_length() const
  {
    const GeometryParameters &g      = parameters.geometry;
    double                    length = 0;
    if (g.type == GeometryType::mesh_file)
      {
        for (unsigned int d = 0; d < dim; ++d)
          length = std::max(length, mesh_upper_right[d] - mesh_lower_left[d]);
        return length;
      }
    if (g.type == GeometryType::two_half_discs)
      return std::max(g.radius, g.lower_radius);
    if (!is_box(g.type))
      return g.radius;
    for (unsigned int d = 0; d < dim; ++d)
      length = std::max(length, g.upper_right[d] - g.lower_left[d]);
    return length;
  }

  template <int dim>
  Point<dim>
  Scene<dim>::center() const
  {
    const GeometryParameters &g = parameters.geometry;
    if (g.type == GeometryType::mesh_file)
      return 0.5 * (mesh_lower_left + mesh_upper_right);
    if (!is_box(g.type))
      return to_point<dim>(g.center);
    return 0.5 * (to_point<dim>(g.lower_left) + to_point<dim>(g.upper_right));
  }

  template <int dim>
  void
  Scene<dim>::create_mesh(
    parallel::TriangulationBase<dim>  &triangulation,
    const std::function<void(double)> &before_refining) const
  {
    create_coarse_mesh(triangulation, before_refining);
    refine_initial_mesh(triangulation, before_refining);
  }

  template <int dim>
  void
  Scene<dim>::create_coarse_mesh(
    parallel::TriangulationBase<dim>  &triangulation,
    const std::function<void(double)> &before_refining) const
  {
    const GeometryParameters &g       = parameters.geometry;
    const bool                simplex = kind_ == CellKind::simplex;
    // each refinement makes 2^dim children of a cell (a triangle 4, a
    // tetrahedron 8)
    const double children = std::pow(2., dim);
    if (g.type == GeometryType::rectangle)
      {
        // The box's cells are known before it is built: the product of the
        // subdivisions, taken in double (three of them overflow an
        // integer long before the memory runs out); 2 triangles or 5
        // tetrahedra per box on simplices.
        if (before_refining)
          {
            double n_cells = simplex ? (dim == 2 ? 2. : 5.) : 1.;
            for (const unsigned int n : g.subdivisions)
              n_cells *= n;
            before_refining(
              n_cells *
              std::pow(children,
                       parameters.refinement.initial_global_refinement));
          }
        std::vector<unsigned int> repetitions(g.subdivisions.begin(),
                                              g.subdivisions.end());
        if (simplex)
          {
            // deal.II 9.4 does not colorize this one: the ids of the
            // quadrilaterals' box, 2 d on the lower and 2 d + 1 on the upper
            // side along x_d, by hand
            Triangulation<dim> serial;
            const Point<dim>   lower = to_point<dim>(g.lower_left);
            const Point<dim>   upper = to_point<dim>(g.upper_right);
            GridGenerator::subdivided_hyper_rectangle_with_simplices(
              serial, repetitions, lower, upper);
            for (const auto &face : serial.active_face_iterators())
              if (face->at_boundary())
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const double tolerance = 1e-10 * (upper[d] - lower[d]);
                    if (std::abs(face->center()[d] - lower[d]) < tolerance)
                      face->set_boundary_id(2 * d);
                    else if (std::abs(face->center()[d] - upper[d]) < tolerance)
                      face->set_boundary_id(2 * d + 1);
                  }
            triangulation.copy_triangulation(serial);
          }
        else
          GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                    repetitions,
                                                    to_point<dim>(g.lower_left),
                                                    to_point<dim>(
                                                      g.upper_right),
                                                    /*colorize=*/true);
      }
    else if (g.type == GeometryType::two_blocks)
      {
        const Point<dim> lower = to_point<dim>(g.lower_left);
        const Point<dim> upper = to_point<dim>(g.upper_right);
        Point<dim>       cut_low(upper), cut_high(lower), top(upper);
        const double     cut = 0.5 * (lower[dim - 1] + upper[dim - 1]);
        cut_low[dim - 1]     = cut;
        cut_high[dim - 1]    = cut;
        // the upper block reaches beyond the lower one across the cut
        for (unsigned int d = 0; d + 1 < dim; ++d)
          {
            cut_high[d] -= g.upper_overhang;
            top[d] += g.upper_overhang;
          }
        if (before_refining)
          {
            double n_lower = simplex ? (dim == 2 ? 2. : 5.) : 1.;
            double n_upper = n_lower;
            for (unsigned int d = 0; d < dim; ++d)
              {
                n_lower *= g.subdivisions[d];
                n_upper *= g.upper_subdivisions[d];
              }
            before_refining(
              (n_lower + n_upper) *
              std::pow(children,
                       parameters.refinement.initial_global_refinement));
          }
        Triangulation<dim> serial;
        make_two_blocks(serial,
                        {g.subdivisions.begin(), g.subdivisions.end()},
                        {g.upper_subdivisions.begin(),
                         g.upper_subdivisions.end()},
                        lower,
                        cut_low,
                        cut_high,
                        top,
                        simplex);
        triangulation.copy_triangulation(serial);
      }
    else if (g.type == GeometryType::two_half_discs)
      {
        Triangulation<dim> serial;
        const Point<dim>   contact = to_point<dim>(g.center);
        make_two_half_discs(serial, contact, g.radius, g.lower_radius);
        triangulation.copy_triangulation(serial);
        // the curved parts follow their circles (spheres), the interior
        // blends toward them (as for the half disc below)
        Point<dim> upper_center(contact), lower_center(contact);
        upper_center[dim - 1] += g.radius;
        lower_center[dim - 1] -= g.lower_radius;
        triangulation.set_all_manifold_ids(1);
        triangulation.set_all_manifold_ids_on_boundary(0, 0);
        triangulation.set_all_manifold_ids_on_boundary(2, 2);
        triangulation.set_manifold(0, SphericalManifold<dim>(upper_center));
        triangulation.set_manifold(2, SphericalManifold<dim>(lower_center));
        TransfiniteInterpolationManifold<dim> inner;
        inner.initialize(triangulation);
        triangulation.set_manifold(1, inner);
      }
    else if (g.type == GeometryType::mesh_file)
      {
        // the file's mesh, read in the constructor; refinement follows the
        // manifolds of <Geometry/Manifolds>
        triangulation.copy_triangulation(coarse_mesh);
        attach_manifolds(g, triangulation);
      }
    else
      {
        // The body lies below its flat top (normal +e_{dim-1}) through the
        // centre. In 2D both discs are made of deal.II's quarter ball (the
        // quadrant x, y >= 0) turned by -90 degrees (lower right quarter)
        // and, for the half disc, by 180 degrees (lower left quarter): the
        // quarter ball is symmetric about its diagonal, so the half disc's
        // mesh is symmetric about the line x = x_c, which is a mesh line, and
        // its right half is exactly the quarter disc's mesh. In 3D the half
        // ball x >= 0 is turned so that its cut plane is the top.
        const Point<dim>   center = to_point<dim>(g.center);
        Triangulation<dim> serial;
        make_lower_half_disc(serial,
                             center,
                             g.radius,
                             g.type == GeometryType::quarter_disc);

        // Boundary ids: 1 on the flat top, 2 on the symmetry line of the
        // quarter disc, 0 on the curved part.
        const double tolerance = 1e-8 * g.radius;
        for (const auto &face : serial.active_face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> x = face->center();
              if (std::abs(x[dim - 1] - center[dim - 1]) < tolerance)
                face->set_boundary_id(1);
              else if (g.type == GeometryType::quarter_disc &&
                       std::abs(x[0] - center[0]) < tolerance)
                face->set_boundary_id(2);
              else
                face->set_boundary_id(0);
            }
        if (simplex)
          {
            // each quadrilateral into 8 triangles (hexahedron into 24
            // tetrahedra); the vertices this puts on the middle of the
            // curved faces' chords go onto the circle (sphere)
            Triangulation<dim> simplices;
            GridGenerator::convert_hypercube_to_simplex_mesh(serial, simplices);
            BoundaryManifold curve;
            curve.id     = 0;
            curve.kind   = dim == 2 ? BoundaryManifold::Kind::circle :
                                      BoundaryManifold::Kind::sphere;
            curve.center = g.center;
            curve.radius = g.radius;
            snap_to_manifolds({curve}, simplices);
            triangulation.copy_triangulation(simplices);
          }
        else
          triangulation.copy_triangulation(serial);

        // The curved boundary follows the circle; on quadrilaterals the
        // interior blends smoothly toward it, so refined cells stay well
        // shaped (deal.II 9.4's transfinite interpolation takes no
        // simplices: their cells stay flat).
        triangulation.set_all_manifold_ids(simplex ? numbers::flat_manifold_id :
                                                     1);
        if (simplex)
          {
            // by hand: deal.II 9.4's set_all_manifold_ids_on_boundary()
            // asks a triangle for a fourth face
            for (const auto &face : triangulation.active_face_iterators())
              if (face->at_boundary() && face->boundary_id() == 0)
                face->set_all_manifold_ids(0);
          }
        else
          triangulation.set_all_manifold_ids_on_boundary(0, 0);
        triangulation.set_manifold(0, SphericalManifold<dim>(center));
        if (!simplex)
          {
            TransfiniteInterpolationManifold<dim> inner;
            inner.initialize(triangulation);
            triangulation.set_manifold(1, inner);
          }
      }
  }

  template <int dim>
  void
  Scene<dim>::refine_initial_mesh(
    parallel::TriangulationBase<dim>  &triangulation,
    const std::function<void(double)> &before_refining) const
  {
    const GeometryParameters &g        = parameters.geometry;
    const bool                simplex  = kind_ == CellKind::simplex;
    const double              children = std::pow(2., dim);
    if (before_refining)
      before_refining(
        triangulation.n_global_active_cells() *
        std::pow(children, parameters.refinement.initial_global_refinement));
    triangulation.refine_global(
      parameters.refinement.initial_global_refinement);

    // A step whose band reaches the vertex farthest from the foundation
    // refines every cell: what the remaining steps make at least is known
    // before they are made.
    double farthest = -std::numeric_limits<double>::max();
    if (before_refining && g.pre_refinement_steps > 0)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              farthest = std::max(farthest, initial_gap(cell->vertex(v)));
        farthest =
          Utilities::MPI::max(farthest, triangulation.get_communicator());
      }

    // In a scene whose contact is between bodies only, the band lies
    // around the pairs' surfaces: a cell is near if one of its vertices
    // lies within the distance of a vertex of another body's paired
    // surface (PairBand).
    const bool toward_pairs =
      !effects_.obstacle_contact && !contact_pairs().empty();
    if (toward_pairs)
      farthest = std::numeric_limits<double>::max();

    double distance = g.pre_refinement_distance;
    for (unsigned int step = 0; step < g.pre_refinement_steps;
         ++step, distance *= g.pre_refinement_grading)
      {
        const PairBand<dim> band =
          toward_pairs ?
            PairBand<dim>(triangulation, contact_pairs(), distance) :
            PairBand<dim>();
        // (a replicated mesh of simplices refines the cells that every
        // rank flags alike: all of them are flagged)
        unsigned int n_flagged = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() || simplex)
            for (const unsigned int v : cell->vertex_indices())
              if (toward_pairs ? band.near(cell, v) :
                                 initial_gap(cell->vertex(v)) <= distance)
                {
                  cell->set_refine_flag();
                  n_flagged += cell->is_locally_owned() ? 1 : 0;
                  break;
                }
        if (before_refining)
          {
            double n_cells =
              triangulation.n_global_active_cells() +
              (children - 1.) *
                Utilities::MPI::sum(n_flagged,
                                    triangulation.get_communicator());
            double later = distance * g.pre_refinement_grading;
            for (unsigned int next = step + 1;
                 next < g.pre_refinement_steps && later >= farthest;
                 ++next, later *= g.pre_refinement_grading)
              n_cells *= children;
            before_refining(n_cells);
          }
        triangulation.execute_coarsening_and_refinement();
      }
  }

  template <int dim>
  bool
  Scene<dim>::translation_is_free(const Tensor<1, dim>     &e,
                                  const Triangulation<dim> &triangulation,
                                  const std::vector<unsigned int> *bodies,
                                  const unsigned int               body) const
  {
    double     measure = 0;
    const auto gram    = constrained_gram(
      triangulation,
      ids_with(BoundaryCondition::fixed),
      ids_with(BoundaryCondition::normal_fixed),
      1,
      [&](const unsigned int, const Point<dim> &, const auto &cell) {
        return bodies == nullptr || body_of<dim>(cell, *bodies) == body ?
                    e :
                    Tensor<1, dim>();
      },
      measure);
    return gram(0, 0) <= 1e-12 * measure;
  }

  template <int dim>
  Tensor<1, dim>
  Scene<dim>::rigid_motion(const unsigned int i, const Point<dim> &x) const
  {
    Tensor<1, dim> m;
    if (i < dim)
      m[i] = 1;
    else
      {
        const Tensor<1, dim> r = (x - center()) / characteristic_length();
        const unsigned int   k = i - dim; // rotation in the plane (a, b)
        const unsigned int   a = (dim == 2) ? 0 : (k == 2 ? 1 : 0);
        const unsigned int   b = (dim == 2) ? 1 : (k == 0 ? 1 : 2);
        m[a]                   = -r[b];
        m[b]                   = r[a];
      }
    return m;
  }

  template <int dim>
  FullMatrix<double>
  Scene<dim>::rigid_motion_gram(const Triangulation<dim>        &triangulation,
                                double                          &measure,
                                const std::vector<unsigned int> *bodies) const
  {
    const unsigned int n_bodies =
      bodies == nullptr ? 1 :
                          1 + *std::max_element(bodies->begin(), bodies->end());
    return constrained_gram(
      triangulation,
      ids_with(BoundaryCondition::fixed),
      ids_with(BoundaryCondition::normal_fixed),
      n_bodies * n_rigid_motions,
      [this,
       bodies](const unsigned int i, const Point<dim> &x, const auto &cell) {
        if (bodies != nullptr &&
            body_of<dim>(cell, *bodies) != i / n_rigid_motions)
          return Tensor<1, dim>();
        return rigid_motion(i % n_rigid_motions, x);
      },
      measure);
  }

  template <int dim>
  void
  Scene<dim>::check_rigid_motions(const Triangulation<dim> &triangulation) const
  {
    if (effects_.contact)
      return; // semi-coercive is allowed: contact holds the body

    const unsigned int       n_modes = n_rigid_motions;
    double                   measure = 0;
    const FullMatrix<double> gram = rigid_motion_gram(triangulation, measure);

    unsigned int n_free = n_modes;
    if (measure > 0)
      {
        LAPACKFullMatrix<double> g(n_modes);
        g = gram;
        g.compute_eigenvalues();
        n_free = 0;
        for (unsigned int i = 0; i < n_modes; ++i)
          if (std::abs(g.eigenvalue(i)) < 1e-10 * measure)
            ++n_free;
      }
    if (n_free > 0)
      throw InputError(
        "The scene leaves " + std::to_string(n_free) +
          " rigid-body motion(s) free and has no contact boundary to hold "
          "them, so the elastic problem has no unique solution. Give more of "
          "the boundary the condition 'fixed' or 'normal fixed' in <Boundary "
          "conditions/Conditions>.",
        exit_inconsistent);
  }

  template std::unique_ptr<Function<2>>
  make_function(const std::string &,
                unsigned int,
                const MaterialParameters &,
                const std::string &,
                double,
                const std::vector<double> &);
  template std::unique_ptr<Function<3>>
  make_function(const std::string &,
                unsigned int,
                const MaterialParameters &,
                const std::string &,
                double,
                const std::vector<double> &);

  template class Scene<2>;
  template class Scene<3>;
} // namespace dualcontact
