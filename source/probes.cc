#include <deal.II/base/bounding_box.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>

#include <deal.II/numerics/vector_tools_evaluate.h>

#include <dualcontact/input_error.h>
#include <dualcontact/mixed_bulk.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/probes.h>
#include <dualcontact/report.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    // -0 (a stress component that vanishes) as 0
    inline double
    tidy(const double x)
    {
      return x + 0.;
    }

    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::ostringstream text;
      text << '(';
      for (unsigned int d = 0; d < dim; ++d)
        text << (d > 0 ? ", " : "") << p[d];
      text << ')';
      return text.str();
    }

    // a length in a message: 3 significant digits
    std::string
    length_text(const double x)
    {
      std::ostringstream text;
      text << std::setprecision(3) << x;
      return text.str();
    }

    /**
     * Where a probe point is evaluated on a mesh: the point itself if a cell
     * holds it, else the nearest point of the body, how far that is and how
     * far a point may lie outside the body there and count as on its
     * boundary.
     */
    template <int dim>
    struct Location
    {
      bool       inside = true;
      Point<dim> where;
      double     distance  = 0.;
      double     tolerance = 0.;
    };

    /**
     * How far a point may lie outside the boundary face f of `cell` and
     * count as on the boundary: the distance of the face's centre on the
     * mesh (the mapped face, a chord of a curved boundary) from its centre
     * on the boundary's manifold (the curve), where the chord is farthest
     * from the curve, plus 1e-6 of the face's size, the tolerance within
     * which RemotePointEvaluation finds a point in a cell anyway.
     */
    template <int dim>
    double
    face_tolerance(const Mapping<dim>                               &mapping,
                   const typename Triangulation<dim>::cell_iterator &cell,
                   const unsigned int                                f)
    {
      // a simplex's face centre on the mesh is the mean of the face's
      // vertices at degree 1 and on the curve at degree 2
      // (SimplexMapping): the chord's distance bounds both
      Point<dim> on_mesh = cell->face(f)->center();
      if (cell->reference_cell().is_hyper_cube())
        {
          Point<dim> unit_centre;
          for (unsigned int d = 0; d < dim; ++d)
            unit_centre[d] = 0.5;
          unit_centre[f / 2] = f % 2;
          on_mesh = mapping.transform_unit_to_real_cell(cell, unit_centre);
        }
      return on_mesh.distance(cell->face(f)->center(true)) +
             1e-6 * cell->face(f)->diameter();
    }

    /**
     * The nearest point of the body to `p`, which no cell holds: over the
     * locally owned cells at the boundary, p's reference coordinates
     * clamped to the unit cell and mapped back (a point of the face p lies
     * beyond, the nearest one if the cell is a rectangle), or the cell's
     * nearest vertex where the mapping cannot invert p; then the nearest
     * over all ranks (the lowest rank's on a draw), the same on every rank.
     * Collective.
     */
    template <int dim>
    Location<dim>
    nearest_point(const Point<dim>         &p,
                  const Mapping<dim>       &mapping,
                  const Triangulation<dim> &triangulation,
                  const MPI_Comm            comm)
    {
      double     distance  = std::numeric_limits<double>::infinity();
      double     tolerance = 0.;
      Point<dim> nearest;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && cell->at_boundary())
          {
            // the box of the vertices holds a Q1 cell: a lower bound
            const BoundingBox<dim> box   = cell->bounding_box();
            double                 below = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double outside = std::max(
                  {box.lower_bound(d) - p[d], p[d] - box.upper_bound(d), 0.});
                below += outside * outside;
              }
            if (std::sqrt(below) >= distance)
              continue;

            Point<dim> candidate;
            double     candidate_tolerance = 0.;
            try
              {
                const Point<dim> unit =
                  mapping.transform_real_to_unit_cell(cell, p);
                if (cell->reference_cell().is_hyper_cube())
                  {
                    const Point<dim> clamped =
                      GeometryInfo<dim>::project_to_unit_cell(unit);
                    candidate =
                      mapping.transform_unit_to_real_cell(cell, clamped);
                    // the boundary faces the clamping moved the point onto
                    for (unsigned int d = 0; d < dim; ++d)
                      for (unsigned int side = 0; side < 2; ++side)
                        if ((side == 0 ? unit[d] < 0. : unit[d] > 1.) &&
                            cell->face(2 * d + side)->at_boundary())
                          candidate_tolerance = std::max(
                            candidate_tolerance,
                            face_tolerance(mapping, cell, 2 * d + side));
                  }
                else
                  {
                    // onto the reference simplex: no negative coordinate,
                    // their sum at most 1; the tolerance of every boundary
                    // face of the cell
                    Point<dim> clamped;
                    double     sum = 0.;
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        clamped[d] = std::max(unit[d], 0.);
                        sum += clamped[d];
                      }
                    if (sum > 1.)
                      clamped /= sum;
                    candidate =
                      mapping.transform_unit_to_real_cell(cell, clamped);
                    for (const unsigned int f : cell->face_indices())
                      if (cell->face(f)->at_boundary())
                        candidate_tolerance =
                          std::max(candidate_tolerance,
                                   face_tolerance(mapping, cell, f));
                  }
              }
            catch (const typename Mapping<dim>::ExcTransformationFailed &)
              {
                candidate = cell->vertex(0);
                for (const unsigned int v : cell->vertex_indices())
                  if (p.distance(cell->vertex(v)) < p.distance(candidate))
                    candidate = cell->vertex(v);
                for (const unsigned int f : cell->face_indices())
                  if (cell->face(f)->at_boundary())
                    candidate_tolerance =
                      std::max(candidate_tolerance,
                               face_tolerance(mapping, cell, f));
              }
            if (p.distance(candidate) < distance)
              {
                distance  = p.distance(candidate);
                nearest   = candidate;
                tolerance = candidate_tolerance;
              }
          }

      std::vector<double> mine = {distance, tolerance};
      for (unsigned int d = 0; d < dim; ++d)
        mine.push_back(nearest[d]);
      Location<dim> location;
      location.inside   = false;
      location.distance = std::numeric_limits<double>::infinity();
      for (const std::vector<double> &other :
           Utilities::MPI::all_gather(comm, mine))
        if (other[0] < location.distance)
          {
            location.distance  = other[0];
            location.tolerance = other[1];
            for (unsigned int d = 0; d < dim; ++d)
              location.where[d] = other[2 + d];
          }
      return location;
    }

    /**
     * Where each of `points` is evaluated on the mesh of `triangulation`.
     * Collective.
     */
    template <int dim>
    std::vector<Location<dim>>
    locate(const std::vector<Point<dim>> &points,
           const Mapping<dim>            &mapping,
           const Triangulation<dim>      &triangulation)
    {
      // every rank asks for every point: all ranks find the same
      Utilities::MPI::RemotePointEvaluation<dim> cache;
      cache.reinit(points, triangulation, mapping);
      std::vector<Location<dim>> locations(points.size());
      for (unsigned int i = 0; i < points.size(); ++i)
        if (cache.point_found(i))
          locations[i].where = points[i];
        else
          locations[i] = nearest_point(points[i],
                                       mapping,
                                       triangulation,
                                       triangulation.get_communicator());
      return locations;
    }
  } // namespace

  template <int dim>
  Probes<dim>::Probes(const std::vector<std::vector<double>> &coordinates,
                      const bool                              with_pressure)
      : with_pressure(with_pressure)
  {
    // the number of coordinates is checked with the other entries
    // (Parameters::check_consistency)
    for (const std::vector<double> &c : coordinates)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim && d < c.size(); ++d)
          p[d] = c[d];
        points.push_back(p);
      }
  }

  template <int dim>
  void
  Probes<dim>::check_inside(const Mapping<dim>       &mapping,
                            const Triangulation<dim> &triangulation) const
  {
    if (points.empty())
      return;
    const std::vector<Location<dim>> locations =
      locate(points, mapping, triangulation);
    for (unsigned int i = 0; i < points.size(); ++i)
      if (!locations[i].inside &&
          !(locations[i].distance <= locations[i].tolerance))
        throw InputError("The point " + point_text(points[i]) + " (probe " +
                           std::to_string(i + 1) +
                           ") of <Output/Probe points> lies " +
                           length_text(locations[i].distance) +
                           " outside the body (the tolerance there is " +
                           length_text(locations[i].tolerance) + ").",
                         exit_inconsistent);
  }

  template <int dim>
  std::vector<typename Probes<dim>::Value>
  Probes<dim>::measure(const Mapping<dim>                  &mapping,
                       const DoFHandler<dim>               &dof_handler,
                       const TrilinosWrappers::MPI::Vector &solution,
                       const MaterialParameters            &material,
                       const MixedBulk<dim>                *mixed) const
  {
    Assert(with_pressure == (mixed != nullptr),
           ExcMessage("The probes of the mixed formulation read its "
                      "pressure field, and only they."));
    // a point outside the body within the tolerance is evaluated at the
    // nearest point of the body; one farther outside is not found
    const std::vector<Location<dim>> locations =
      locate(points, mapping, dof_handler.get_triangulation());
    std::vector<Point<dim>> where = points;
    for (unsigned int i = 0; i < points.size(); ++i)
      if (locations[i].distance <= locations[i].tolerance)
        where[i] = locations[i].where;
    // every rank asks for every point: the values come back to all ranks
    Utilities::MPI::RemotePointEvaluation<dim> cache;
    const auto u = VectorTools::point_values<dim>(
      mapping, dof_handler, solution, where, cache);
    const auto grad =
      VectorTools::point_gradients<dim>(cache, dof_handler, solution);
    // the mixed formulation's p, on its own DoFs of the same mesh
    const std::vector<double> pressure =
      mixed ? VectorTools::point_values<1>(cache,
                                           mixed->dofs(),
                                           mixed->ghosted_pressure()) :
              std::vector<double>(points.size(), 0.);
    // the material id of (the first of) the cells that hold each point
    std::vector<double>       ids, buffer;
    const Triangulation<dim> &triangulation = dof_handler.get_triangulation();
    cache.template evaluate_and_process<double>(
      ids,
      buffer,
      [&](const ArrayView<double> &values,
          const typename Utilities::MPI::RemotePointEvaluation<dim>::CellData
            &cell_data) {
        for (unsigned int c = 0; c < cell_data.cells.size(); ++c)
          {
            const typename Triangulation<dim>::active_cell_iterator cell(
              &triangulation,
              cell_data.cells[c].first,
              cell_data.cells[c].second);
            for (unsigned int q = cell_data.reference_point_ptrs[c];
                 q < cell_data.reference_point_ptrs[c + 1];
                 ++q)
              values[q] = cell->material_id();
          }
      });
    const std::vector<unsigned int> &first = cache.get_point_ptrs();
    std::vector<Value>               values(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        Value &value = values[i];
        value.probe  = i;
        value.point  = points[i];
        if (cache.point_found(i))
          {
            const MaterialParameters here =
              material.of(static_cast<types::material_id>(ids[first[i]]));
            const double lambda = here.block_lambda(), mu = here.mu();
            value.displacement = u[i];
            value.pressure     = pressure[i];
            value.stress =
              stress_from_gradient(grad[i], lambda, mu, value.pressure);
            value.stress_zz =
              out_of_plane_stress(grad[i], lambda, value.pressure);
            value.von_mises = von_mises_stress(value.stress, value.stress_zz);
          }
        else // a later mesh lost the point (a concave curved boundary)
          {
            const double nan      = std::numeric_limits<double>::quiet_NaN();
            value.displacement[0] = nan;
            value.stress[0][0]    = nan;
            value.stress_zz       = nan;
            value.von_mises       = nan;
            value.pressure        = nan;
          }
      }
    return values;
  }

  template <int dim>
  void
  Probes<dim>::evaluate(const unsigned int                   cycle,
                        const Mapping<dim>                  &mapping,
                        const DoFHandler<dim>               &dof_handler,
                        const TrilinosWrappers::MPI::Vector &solution,
                        const MaterialParameters            &material,
                        const MixedBulk<dim>                *mixed)
  {
    if (points.empty())
      return;
    for (Value &value :
         measure(mapping, dof_handler, solution, material, mixed))
      {
        value.cycle = cycle;
        all_values.push_back(value);
      }
  }

  template <int dim>
  void
  Probes<dim>::evaluate_step(const unsigned int                   step,
                             const double                         time,
                             const Mapping<dim>                  &mapping,
                             const DoFHandler<dim>               &dof_handler,
                             const TrilinosWrappers::MPI::Vector &solution,
                             const MaterialParameters            &material,
                             const MixedBulk<dim>                *mixed)
  {
    if (points.empty())
      return;
    for (Value &value :
         measure(mapping, dof_handler, solution, material, mixed))
      {
        value.step = step;
        value.time = time;
        all_step_values.push_back(value);
      }
  }

  template <int dim>
  void
  Probes<dim>::write_header(std::ostream &csv) const
  {
    static const char axis[] = "xyz";
    csv << "probe";
    for (unsigned int d = 0; d < dim; ++d)
      csv << ',' << axis[d];
    for (unsigned int d = 0; d < dim; ++d)
      csv << ",u_" << axis[d];
    // the diagonal, then the upper triangle; in 2D sigma_zz of plane strain
    for (unsigned int d = 0; d < 3; ++d)
      csv << ",sigma_" << axis[d] << axis[d];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i + 1; j < dim; ++j)
        csv << ",sigma_" << axis[i] << axis[j];
    csv << ",von_mises" << (with_pressure ? ",pressure" : "") << '\n';
  }

  template <int dim>
  void
  Probes<dim>::write_row(std::ostream &csv, const Value &v) const
  {
    csv << v.probe + 1;
    for (unsigned int d = 0; d < dim; ++d)
      csv << ',' << tidy(v.point[d]);
    for (unsigned int d = 0; d < dim; ++d)
      csv << ',' << tidy(v.displacement[d]);
    for (unsigned int d = 0; d < dim; ++d)
      csv << ',' << tidy(v.stress[d][d]);
    if (dim == 2)
      csv << ',' << tidy(v.stress_zz);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i + 1; j < dim; ++j)
        csv << ',' << tidy(v.stress[i][j]);
    csv << ',' << tidy(v.von_mises);
    if (with_pressure)
      csv << ',' << tidy(v.pressure);
    csv << '\n';
  }

  template <int dim>
  void
  Probes<dim>::write_csv(const std::string &filename) const
  {
    std::ofstream csv(filename);
    csv << "cycle,";
    write_header(csv);
    csv << std::setprecision(12);
    for (const Value &v : all_values)
      {
        csv << v.cycle << ',';
        write_row(csv, v);
      }
  }

  template <int dim>
  void
  Probes<dim>::append_step_csv(const std::string &filename)
  {
    std::ofstream csv;
    if (!step_csv_started)
      {
        step_csv_started = true;
        csv.open(filename, std::ios::trunc);
        csv << "step,time,";
        write_header(csv);
      }
    else
      csv.open(filename, std::ios::app);
    csv << std::setprecision(12);
    for (; step_values_written < all_step_values.size(); ++step_values_written)
      {
        const Value &v = all_step_values[step_values_written];
        csv << v.step << ',' << v.time << ',';
        write_row(csv, v);
      }
  }

  template <int dim>
  void
  Probes<dim>::resume_step_csv(const std::string &filename,
                               const unsigned int last_step)
  {
    keep_rows_up_to(filename, "step", last_step);
    step_csv_started = true;
  }

  template class Probes<2>;
  template class Probes<3>;
} // namespace dualcontact
