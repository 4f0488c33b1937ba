// ContactProblem, the equilibrium checks: before a contact solve, whether
// the obstacle and friction can hold the loads at all (the net load toward
// the obstacle, the tangential load against what friction can resist, the
// moment that would tip the body over); after it, the balance of the loads
// and the reactions. A load that cannot be held is refused with exit status
// 7 instead of being left to the iterations to diverge on.
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_output.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/output_directory.h>
#include <dualcontact/pair_equilibrium.h>
#include <dualcontact/plausibility.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/refinement.h>
#include <dualcontact/refinement_indicator.h>
#include <dualcontact/run_size.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <set>

namespace dualcontact
{
  template <int dim>
  double
  ContactProblem<dim>::net_load(const Tensor<1, dim> &direction) const
  {
    // b . E, E the nodal vector of the rigid translation along `direction`
    TrilinosWrappers::MPI::Vector translation(locally_owned_dofs,
                                              mpi_communicator);
    for (unsigned int c = 0; c < dim; ++c)
      {
        ComponentMask mask(dim, false);
        mask.set(c, true);
        for (const auto i : DoFTools::extract_dofs(dof_handler, mask))
          translation[i] = direction[c];
      }
    translation.compress(VectorOperation::insert);
    return system_rhs * translation;
  }

  template <int dim>
  std::vector<double>
  ContactProblem<dim>::check_equilibrium() const
  {
    // A translation that only the contact can stop must be balanced by
    // contact forces: they push along m (never pull) and their tangential
    // part is at most what the friction law can resist. Necessary
    // conditions, checked before solving so that an impossible load never
    // loops (doc/theory.md §8). The obstacle's checks see the whole mesh
    // (its bodies held together by their pairs) and the obstacle's contact
    // nodes; each body held by a pair alone is checked on its own.
    std::vector<double> held_pressure =
      check_pair_bodies(contact_set, dof_handler, system_rhs, scene);
    const auto on_obstacle = [this](const unsigned int s) {
      return contact_set.nodes[s].masters.empty();
    };
    unsigned int n_obstacle = 0;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      n_obstacle += on_obstacle(s);
    if (Utilities::MPI::sum(n_obstacle, mpi_communicator) == 0)
      return held_pressure;

    const Tensor<1, dim> m = -contact_set.normal; // into the body
    LoadBalance          balance;
    Tensor<1, dim>       resultant;
    for (unsigned int d = 0; d < dim; ++d)
      {
        Tensor<1, dim> e;
        e[d]         = 1.;
        resultant[d] = net_load(e);
      }
    balance.resultant   = resultant.norm();
    balance.normal_free = scene.translation_is_free(m, triangulation);
    balance.load_away   = net_load(m);

    // what the friction law can resist: from sum_s m_s p_s, max_s p_s (p
    // its parameter) and the normal load, over the obstacle's nodes
    double weighted = 0., largest = 0., measure = 0.;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      if (on_obstacle(s))
        {
          weighted +=
            contact_set.nodes[s].weight * contact_set.friction_parameter[s];
          largest = std::max(largest, contact_set.friction_parameter[s]);
          measure += contact_set.nodes[s].weight;
        }
    measure = Utilities::MPI::sum(measure, mpi_communicator);

    // N / |Gamma_C| if only friction holds a tangential load and N is known
    // (on a plane: a curved obstacle also holds tangential loads by its
    // normal pressure)
    double     pressure = 0.;
    const bool plane    = scene.obstacle()->is_plane();
    for (const Tensor<1, dim> &t : contact_set.tangents)
      if (plane && scene.translation_is_free(t, triangulation))
        {
          const double load = std::abs(net_load(t));
          balance.tangential_loads.push_back(load);
          if (balance.normal_free && load > 1e-10 * balance.resultant)
            pressure = -balance.load_away / measure;
        }

    std::string  why;
    const double capacity = scene.effects().friction_law().capacity(
      Utilities::MPI::sum(weighted, mpi_communicator),
      Utilities::MPI::max(largest, mpi_communicator),
      balance.normal_free ? -balance.load_away : -1.,
      why);
    dualcontact::check_equilibrium(balance, capacity, why);
    if (balance.normal_free && plane)
      check_moment(balance);
    if (pressure > 0.)
      {
        held_pressure.resize(contact_set.n_local_nodes(), 0.);
        for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
          if (on_obstacle(s))
            held_pressure[s] = pressure;
      }
    return held_pressure;
  }

  namespace
  {
    /**
     * The error of loads that tip the body over: the line of action of
     * their resultant meets the foundation at `centre`, `outside` outside
     * the hull of the contact nodes. Points of the plane are told as
     * coordinates.
     */
    template <int dim>
    [[noreturn]] void
    throw_tipped_over(const Point<dim>                         &origin,
                      const ContactSet<dim>                    &contact_set,
                      const double                              flat,
                      const double                              N,
                      const std::array<double, 2>              &centre,
                      const double                              outside,
                      const std::vector<std::array<double, 2>> &hull)
    {
      const auto on_plane = [&](const std::array<double, 2> &p) {
        Point<dim> x = origin;
        for (unsigned int k = 0; k < dim - 1; ++k)
          x += p[k] * contact_set.tangents[k];
        std::ostringstream out;
        out << "(";
        for (unsigned int c = 0; c < dim; ++c)
          out << (c > 0 ? ", " : "") << std::setprecision(4)
              << (std::abs(x[c]) < flat ? 0. : x[c]);
        return out.str() + ")";
      };
      std::ostringstream text;
      text << "No equilibrium: the loads tip the body over. Only the contact "
              "holds the body, and it can only push: the loads press it onto "
              "the foundation with "
           << format_number(N)
           << ", but the line of action of their resultant meets the "
              "foundation at "
           << on_plane(centre) << ", " << format_number(outside)
           << " outside the contact boundary's "
           << (dim == 2 ? "extent on it, from " + on_plane(hull.front()) +
                            " to " + on_plane(hull.back()) :
                          std::string("convex hull on it"))
           << ", so no contact pressure balances their moment. Reduce the "
              "tangential loads or their lever arm, or hold the body "
              "(<Boundary conditions/Conditions>).";
      throw InputError(text.str(), exit_no_equilibrium);
    }
  } // namespace

  template <int dim>
  void
  ContactProblem<dim>::check_moment(const LoadBalance &balance) const
  {
    // Where only the contact holds the body (no prescribed displacement
    // holds any rigid motion), the contact forces must also balance the
    // loads' moment. On a plane they push along m at the nodes of Gamma_C;
    // their friction parts lie in the plane, and where the nodes lie on it
    // their moment about a point O of the plane is normal to it. So the
    // loads' moment M about O, normal part aside, is balanced by pressures
    // alone: their centre c = O + (M x m) / N must lie in the convex hull
    // of the nodes, N the load toward the plane. Without friction the
    // nodes may lie anywhere on Gamma_C (only their projections count);
    // with friction off the plane a tangential force has a lever arm, and
    // the check cannot decide (doc/theory.md §8).
    double     measure = 0.;
    const auto gram    = scene.rigid_motion_gram(triangulation, measure);
    if (gram.frobenius_norm() > 1e-12 * std::max(measure, 1e-300))
      return;
    const double N = -balance.load_away;
    if (!(N > 1e-10 * balance.resultant))
      return;
    const double         length = scene.characteristic_length();
    const double         flat   = 1e-8 * length;
    const Tensor<1, dim> m      = -contact_set.normal; // into the body
    // O: the body's centre moved onto the plane along m
    Point<dim> origin = scene.center();
    origin -= scene.initial_gap(origin) * m;
    bool                               off_plane = false;
    std::vector<std::array<double, 2>> points;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        const ContactNode<dim> &node = contact_set.nodes[s];
        // the obstacle's nodes: a pair's are inside the mesh it holds
        if (!node.masters.empty())
          continue;
        off_plane = off_plane || node.gap0 > flat;
        std::array<double, 2> p{};
        for (unsigned int k = 0; k < dim - 1; ++k)
          p[k] = contact_set.tangents[k] * (node.position - origin);
        points.push_back(p);
      }
    if (Utilities::MPI::logical_or(off_plane, mpi_communicator) &&
        contact_set.friction)
      return;
    // each rank's hull, then the hull of theirs
    std::vector<double> local;
    for (const auto &p : convex_hull(points, dim - 1))
      local.insert(local.end(), p.begin(), p.end());
    std::vector<std::array<double, 2>> hull;
    for (const auto &part : Utilities::MPI::all_gather(mpi_communicator, local))
      for (std::size_t i = 0; i + 1 < part.size(); i += 2)
        hull.push_back(std::array<double, 2>{{part[i], part[i + 1]}});
    hull = convex_hull(hull, dim - 1);

    // M about O: b . R_k for the rigid rotations R_k(x) = e_k x (x - O)
    // (in 2D the one about the normal of the plane)
    const unsigned int n_rotations = dim == 2 ? 1 : 3;
    Tensor<1, 3>       moment;
    const IndexSet    &owned = locally_owned_dofs;
    for (unsigned int k = 0; k < n_rotations; ++k)
      {
        TrilinosWrappers::MPI::Vector rotation(owned, mpi_communicator);
        const unsigned int            axis = dim == 2 ? 2 : k;
        interpolate_field<dim>(
          mapping,
          dof_handler,
          [&origin, axis](const Point<dim> &x) {
            const Tensor<1, dim> r   = x - origin;
            const double       r3[3] = {r[0], r[1], dim == 3 ? r[dim - 1] : 0.};
            const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
            Tensor<1, 3>       u; // e_axis x r, r in 3D
            u[a] = -r3[b];
            u[b] = r3[a];
            Tensor<1, dim> value;
            for (unsigned int c = 0; c < dim; ++c)
              value[c] = u[c];
            return value;
          },
          rotation);
        moment[dim == 2 ? 2 : k] = system_rhs * rotation;
      }
    Tensor<1, 3> m3;
    for (unsigned int c = 0; c < dim; ++c)
      m3[c] = m[c];
    const Tensor<1, 3>    offset = cross_product_3d(moment, m3) / N;
    std::array<double, 2> centre{};
    for (unsigned int k = 0; k < dim - 1; ++k)
      for (unsigned int c = 0; c < dim; ++c)
        centre[k] += contact_set.tangents[k][c] * offset[c];
    const double outside = distance_outside_hull(hull, centre, dim - 1);
    if (!(outside > flat))
      return;

    throw_tipped_over(origin, contact_set, flat, N, centre, outside, hull);
  }

  template <int dim>
  void
  ContactProblem<dim>::check_balance(const ReactionRecord &reactions) const
  {
    // The converged solution balances the loads up to the solver
    // tolerances (1e-14 to 1e-10 on the shipped scenes, doc/theory.md §8);
    // a solve that stopped on its tests without balancing them (a proximal
    // weight so large that v never moves, say) is not a solution.
    const double tolerance =
      std::clamp(1e2 * parameters.solver.uzawa_tolerance, 1e-6, 1e-2);
    if (!(reactions.imbalance <= tolerance))
      AssertThrow(
        false,
        ExcMessage("The solution does not balance the loads: contact "
                   "force, reactions and applied loads sum to " +
                   format_number(reactions.imbalance) +
                   " of the largest of them (at most " +
                   format_number(tolerance) + " for <Solver/Uzawa tolerance> " +
                   format_number(parameters.solver.uzawa_tolerance) +
                   "). The solver stopped without a solution: check "
                   "<Solver/Proximal parameter> and <Solver/Augmentation "
                   "parameter> (their defaults suit every scene)."));
  }


  template double
  ContactProblem<2>::net_load(const Tensor<1, 2> &direction) const;
  template double
  ContactProblem<3>::net_load(const Tensor<1, 3> &direction) const;
  template std::vector<double>
  ContactProblem<2>::check_equilibrium() const;
  template std::vector<double>
  ContactProblem<3>::check_equilibrium() const;
  template void
  ContactProblem<2>::check_moment(const LoadBalance &balance) const;
  template void
  ContactProblem<3>::check_moment(const LoadBalance &balance) const;
  template void
  ContactProblem<2>::check_balance(const ReactionRecord &reactions) const;
  template void
  ContactProblem<3>::check_balance(const ReactionRecord &reactions) const;
} // namespace dualcontact
