#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <dualcontact/discretization.h>
#include <dualcontact/input_error.h>
#include <dualcontact/plausibility.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    // "id 2 ('contact')"
    std::string
    describe(const types::boundary_id id, const BoundaryCondition condition)
    {
      return "boundary id " + std::to_string(id) + " ('" +
             to_string(condition) + "')";
    }

    // x with three significant digits, not in scientific notation: 50.2
    std::string
    plain(const double x)
    {
      std::ostringstream out;
      out << std::setprecision(3) << x;
      return out.str();
    }

    // The entries that place the obstacle, for messages.
    template <int dim>
    std::string
    obstacle_entries(const Scene<dim> &scene)
    {
      std::string entries = scene.obstacle().entries();
      if (scene.obstacle().displacement().norm() > 0)
        entries += ", <Obstacle/Displacement>";
      return entries;
    }
  } // namespace

  template <int dim>
  void
  check_initial_position(const Triangulation<dim> &triangulation,
                         const Scene<dim>         &scene)
  {
    if (!scene.effects().obstacle_contact)
      return;
    const double tolerance = 1e-8 * scene.characteristic_length();
    // the extreme signed distances of all vertices and of the contact
    // boundary's vertices from the obstacle where it starts, before a
    // prescribed displacement moves it into the body (> 0 on the body's
    // side)
    const Obstacle<dim> &obstacle       = *scene.obstacle();
    double               highest        = -std::numeric_limits<double>::max();
    double               lowest_contact = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          for (const unsigned int v : cell->vertex_indices())
            highest = std::max(highest, obstacle.distance(cell->vertex(v)));
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() &&
                scene.parameters.boundary.condition(face->boundary_id()) ==
                  BoundaryCondition::contact)
              for (const unsigned int v : face->vertex_indices())
                lowest_contact =
                  std::min(lowest_contact, obstacle.distance(face->vertex(v)));
        }
    const MPI_Comm comm = triangulation.get_communicator();
    highest             = Utilities::MPI::max(highest, comm);
    lowest_contact      = Utilities::MPI::min(lowest_contact, comm);

    const std::string entries = obstacle_entries(scene);
    if (highest < tolerance && obstacle.is_plane())
      throw InputError(
        "The whole body lies behind the foundation plane: the foundation "
        "normal points away from the body (" +
          entries +
          "). It must point from the foundation into the body; reverse "
          "<Foundation/Normal>.",
        exit_inconsistent);
    if (highest < tolerance)
      throw InputError("The whole body lies inside the obstacle (" + entries +
                         "): it must start outside it, where the distance "
                         "is positive.",
                       exit_inconsistent);
    if (lowest_contact < -tolerance)
      throw InputError(
        "The body starts inside the " +
          std::string(obstacle.is_plane() ? "foundation" : "obstacle") +
          ": part of its contact boundary lies " +
          format_number(-lowest_contact) + " inside it (" + entries +
          "). Place the obstacle at the body's surface or beyond it; to "
          "press it in, prescribe <Obstacle/Displacement>.",
        exit_inconsistent);
  }

  namespace
  {
    /**
     * The support points of the contact boundary (also those a ghost cell
     * sees), by the DoF of their first component, sorted: they are kept
     * out of the foundation by the contact conditions, up to the
     * tolerance, and are not checked again.
     */
    template <int dim>
    std::vector<types::global_dof_index>
    contact_support_points(const DoFHandler<dim> &dof_handler,
                           const Scene<dim>      &scene)
    {
      const FiniteElement<dim>            &fe     = dof_handler.get_fe();
      const FiniteElement<dim>            &scalar = fe.base_element(0);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::vector<types::global_dof_index> contact_points;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  scene.parameters.boundary.condition(
                    cell->face(f)->boundary_id()) == BoundaryCondition::contact)
                for (unsigned int q = 0; q < scalar.n_dofs_per_cell(); ++q)
                  if (support_on_face(scalar, q, f))
                    contact_points.push_back(
                      dofs[fe.component_to_system_index(0, q)]);
          }
      std::sort(contact_points.begin(), contact_points.end());
      return contact_points;
    }

    /** What the support points of this rank's cells show. */
    struct SupportPointScan
    {
      double       max_u          = 0.;
      double       deepest        = 0.;
      double       lowest_contact = std::numeric_limits<double>::max();
      unsigned int deepest_id     = 0;
    };

    /**
     * The largest displacement at the support points of FE_Q(k), all k:
     * the vertices at k = 1, and at k >= 2 the points between them too,
     * where a curved or bent boundary may cross the obstacle while the
     * vertices do not (a support point is known by the DoF of its first
     * component); with contact, the deepest boundary point in the obstacle
     * and its boundary id, and the smallest initial gap of the contact
     * boundary's points.
     */
    template <int dim>
    SupportPointScan
    scan_support_points(const Mapping<dim>                  &mapping,
                        const DoFHandler<dim>               &dof_handler,
                        const TrilinosWrappers::MPI::Vector &solution,
                        const Scene<dim>                    &scene,
                        const bool                           contact)
    {
      SupportPointScan                           scan;
      const FiniteElement<dim>                  &fe     = dof_handler.get_fe();
      const FiniteElement<dim>                  &scalar = fe.base_element(0);
      FEValues<dim>                              at_support_points(mapping,
                                      fe,
                                      Quadrature<dim>(
                                        scalar.get_unit_support_points()),
                                      update_quadrature_points);
      std::vector<types::global_dof_index>       dofs(fe.n_dofs_per_cell());
      const std::vector<types::global_dof_index> contact_points =
        contact_support_points(dof_handler, scene);
      const auto is_contact_point = [&](const types::global_dof_index i) {
        return std::binary_search(contact_points.begin(),
                                  contact_points.end(),
                                  i);
      };
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            at_support_points.reinit(cell);
            const auto u = [&](const unsigned int q) {
              Tensor<1, dim> value;
              for (unsigned int c = 0; c < dim; ++c)
                value[c] = solution[dofs[fe.component_to_system_index(c, q)]];
              return value;
            };
            for (unsigned int q = 0; q < scalar.n_dofs_per_cell(); ++q)
              scan.max_u = std::max(scan.max_u, u(q).norm());
            if (!contact)
              continue;
            for (const unsigned int f : cell->face_indices())
              {
                if (!cell->face(f)->at_boundary())
                  continue;
                const types::boundary_id id = cell->face(f)->boundary_id();
                for (unsigned int q = 0; q < scalar.n_dofs_per_cell(); ++q)
                  {
                    if (!support_on_face(scalar, q, f))
                      continue;
                    const Point<dim> &x = at_support_points.quadrature_point(q);
                    if (is_contact_point(
                          dofs[fe.component_to_system_index(0, q)]))
                      {
                        scan.lowest_contact =
                          std::min(scan.lowest_contact, scene.initial_gap(x));
                        continue;
                      }
                    const double depth = -scene.initial_gap(x + u(q));
                    if (depth > scan.deepest)
                      {
                        scan.deepest    = depth;
                        scan.deepest_id = id;
                      }
                  }
              }
          }
      return scan;
    }

    /**
     * A boundary without contact that passes through the obstacle: more
     * than 0.1 % of the body's size `length` throws, less is a warning.
     */
    template <int dim>
    void
    check_penetration(PositionRecord   &record,
                      const Scene<dim> &scene,
                      const double      length)
    {
      const std::string text =
        describe(record.penetrating_id,
                 scene.parameters.boundary.condition(record.penetrating_id)) +
        " passes through the obstacle by " + format_number(record.penetration) +
        " (" + plain(100. * record.penetration / length) +
        " % of the body's size): only boundaries with the condition "
        "'contact' are kept out of it";
      if (record.penetration > 1e-3 * length)
        throw InputError("The solution is not physical: " + text +
                           ". Give that boundary the condition 'contact' "
                           "(<Boundary conditions/Conditions>), or check "
                           "which face touches the obstacle (" +
                           obstacle_entries(scene) + ").",
                         exit_inconsistent);
      record.warnings.push_back(text + " (less than 0.1 % of its size).");
    }

    /** The warning on displacements beyond 5 % of the body's size. */
    template <int dim>
    std::string
    large_displacement_warning(const PositionRecord &record,
                               const Scene<dim>     &scene,
                               const double          length,
                               const bool            contact)
    {
      std::ostringstream text;
      text << "the displacements reach "
           << format_number(record.max_displacement) << ", "
           << plain(100. * record.max_displacement / length)
           << " % of the body's size " << plain(length)
           << ": the model is linear (small displacements and strains), "
              "so the result is not physical there";
      if (contact && record.min_initial_gap > 0.05 * length)
        text << "; the contact boundary starts "
             << plain(record.min_initial_gap)
             << " from the obstacle, and the body moves that far to "
                "reach it ("
             << obstacle_entries(scene) << ")";
      text << ".";
      return text.str();
    }
  } // namespace

  template <int dim>
  PositionRecord
  check_deformed_position(const Mapping<dim>                  &mapping,
                          const DoFHandler<dim>               &dof_handler,
                          const TrilinosWrappers::MPI::Vector &solution,
                          const Scene<dim>                    &scene)
  {
    PositionRecord         record;
    const double           length  = scene.characteristic_length();
    const bool             contact = scene.effects().obstacle_contact;
    const SupportPointScan scan =
      scan_support_points(mapping, dof_handler, solution, scene, contact);
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    record.max_displacement = Utilities::MPI::max(scan.max_u, comm);
    record.min_initial_gap  = Utilities::MPI::min(scan.lowest_contact, comm);
    // the deepest point and its id, over the ranks
    const double global_deepest = Utilities::MPI::max(scan.deepest, comm);
    record.penetration          = global_deepest;
    record.penetrating_id =
      Utilities::MPI::min(scan.deepest == global_deepest && scan.deepest > 0. ?
                            scan.deepest_id :
                            std::numeric_limits<unsigned int>::max(),
                          comm);

    if (contact && record.penetration > 1e-8 * length)
      check_penetration(record, scene, length);
    if (record.max_displacement > 0.05 * length)
      record.warnings.push_back(
        large_displacement_warning(record, scene, length, contact));
    // gap and normal are taken before deformation: the obstacle's surface
    // must look flat over the distances the body moves
    const double curvature_radius = scene.obstacle()->radius_of_curvature();
    if (contact && record.max_displacement > 0.05 * curvature_radius)
      record.warnings.push_back(
        "the displacements reach " + format_number(record.max_displacement) +
        ", " + plain(100. * record.max_displacement / curvature_radius) +
        " % of the obstacle's radius of curvature " + plain(curvature_radius) +
        ": gaps and normals are taken in the initial configuration, which "
        "is accurate only for displacements small against that radius.");
    return record;
  }

  template void
  check_initial_position<2>(const Triangulation<2> &, const Scene<2> &);
  template void
  check_initial_position<3>(const Triangulation<3> &, const Scene<3> &);
  template PositionRecord
  check_deformed_position<2>(const Mapping<2> &,
                             const DoFHandler<2> &,
                             const TrilinosWrappers::MPI::Vector &,
                             const Scene<2> &);
  template PositionRecord
  check_deformed_position<3>(const Mapping<3> &,
                             const DoFHandler<3> &,
                             const TrilinosWrappers::MPI::Vector &,
                             const Scene<3> &);
} // namespace dualcontact
