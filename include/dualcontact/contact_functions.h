// The pure pieces of the contact solver: functions of numbers and small
// tensors only, with no mesh, no MPI and no state, so that each can be read
// against its formula in doc/theory.md and tested on its own.
#ifndef dualcontact_contact_functions_h
#define dualcontact_contact_functions_h

#include <deal.II/base/tensor.h>

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /** x^+ = max(x, 0). */
  inline double
  positive_part(const double x)
  {
    return x > 0. ? x : 0.;
  }

  /**
   * |difference| / |reference| for the stopping tests, with 0/0 = 0 and
   * x/0 = 1 (a change from nothing to something is a full change).
   */
  inline double
  relative_change(const double difference, const double reference)
  {
    if (reference > 0.)
      return difference / reference;
    return difference > 0. ? 1. : 0.;
  }

  /**
   * The projection onto the disc of radius g (an interval [-g, g] in 2D,
   * where the tangent space has one dimension): the tangential multiplier
   * update l2 <- proj_g(l2 + r v_t) and the derivative of Phi
   * (doc/theory.md §2).
   */
  template <int n>
  Tensor<1, n>
  project_onto_disc(const Tensor<1, n> &y, const double g)
  {
    const double norm = y.norm();
    return norm <= g ? y : (g / norm) * y;
  }

  /**
   * What a contact node does, as the multiplier update decides it
   * (doc/theory.md §3.2), from the new pressure l1 = (z)^+ and the trial
   * traction y = l2 + r_t v_t that the update projects onto the disc of
   * radius g: separated where l1 = 0; in contact where l1 > 0, and then,
   * with friction, sticking where y lies inside the disc (l2 = y, no slip)
   * and slipping where it does not (l2 = g y/|y|). Without friction a node
   * in contact counts as sticking. The values are those of the status
   * column of the contact CSV (0, 1, 2).
   */
  enum NodeStatus : unsigned char
  {
    separated = 0,
    stick     = 1,
    slip      = 2
  };

  /** Whether the trial traction y lies inside the disc of radius g. */
  template <int n>
  bool
  sticks(const Tensor<1, n> &y, const double g)
  {
    return y.norm() < g;
  }

  template <int n>
  NodeStatus
  node_status(const double        l1,
              const Tensor<1, n> &y,
              const double        g,
              const bool          friction)
  {
    if (!(l1 > 0.))
      return separated;
    return (!friction || sticks(y, g)) ? stick : slip;
  }

  /**
   * psi_g(y) = |y|^2/2 for |y| <= g, g|y| - g^2/2 beyond: the C^1, convex,
   * Huber-like function whose gradient is project_onto_disc(y, g). The
   * friction part of the merit function of a Uzawa step is
   * sum_s m_s/r psi_g(l2_s + r v_t(s)) (doc/theory.md §2, §3.3).
   */
  template <int n>
  double
  huber(const Tensor<1, n> &y, const double g)
  {
    const double norm = y.norm();
    return norm <= g ? 0.5 * norm * norm : g * norm - 0.5 * g * g;
  }

  /**
   * D(y) d, D the derivative of project_onto_disc(., g) at y: the identity
   * when sticking (|y| < g), (g/|y|)(I - y y^T/|y|^2) when slipping (the
   * generalised Hessian of psi_g, doc/theory.md §3.3). Symmetric.
   */
  template <int n>
  Tensor<1, n>
  projection_derivative(const Tensor<1, n> &y,
                        const double        g,
                        const Tensor<1, n> &d)
  {
    const double norm = y.norm();
    if (norm < g)
      return d;
    if (norm == 0.)
      return Tensor<1, n>();
    const Tensor<1, n> y_hat = y / norm;
    return g / norm * (d - (d * y_hat) * y_hat);
  }

  /** d . D(y) d: the curvature of psi_g at y along d. */
  template <int n>
  double
  huber_curvature(const Tensor<1, n> &y, const double g, const Tensor<1, n> &d)
  {
    return d * projection_derivative(y, g, d);
  }

  /**
   * The minimiser along a direction, for the line search of the Newton
   * iteration when the full step fails Armijo's test (doc/theory.md §3.3).
   * Along a descent direction the merit function phi(a) = M_k(v + a d) is a
   * convex, C^1, piecewise quadratic; `derivatives(a)` returns (phi'(a),
   * phi''(a)) (the second from the right). phi'(0) < 0. Returns the
   * minimiser of phi on a > 0: the root of the increasing, piecewise linear
   * phi', bracketed by doubling steps of 4, then found by Newton steps on
   * phi' kept inside the bracket (bisection when they leave it). Ends when
   * |phi'| <= 1e-12 |phi'(0)| or the bracket is 1e-12 wide (relative); at
   * most 50 steps, and the bracket stops growing at a = 1e6.
   */
  double
  exact_line_search(
    const std::function<std::pair<double, double>(double)> &derivatives);

  /**
   * The half-widths of a 2D contact zone from the pressure at the contact
   * nodes, (position along the tangent, l1) sorted by position:
   * - `nodes`: half the distance between the outermost nodes with l1 > 0;
   * - `extrapolated`: the same with each edge extrapolated: near the edge
   *   of a smooth contact the pressure vanishes like sqrt(distance), so l1^2
   *   is linear there; it is extrapolated to zero from the two outermost
   *   active nodes on each side, staying before the first separated node.
   *   Where the zone reaches the end of the list there is no such edge and
   *   the outermost node is kept.
   * Both are 0 without any active node.
   */
  struct ContactZoneWidth
  {
    double nodes        = 0.;
    double extrapolated = 0.;
  };

  ContactZoneWidth
  contact_zone_half_width(
    const std::vector<std::pair<double, double>> &sorted_pressures);

  /**
   * One contact node as the zone measures see it: its coordinates in the
   * mean tangent plane of Gamma_C (the second is 0 in 2D), its weight m_s,
   * its initial gap g0, its pressure l1 and its status (ContactSet::status:
   * 0 separated, 1 in contact and sticking, 2 slipping).
   */
  struct ZoneNode
  {
    std::array<double, 2> t{};
    double                weight = 0.;
    double                gap0   = 0.;
    double                l1     = 0.;
    unsigned int          status = 0;

    // for Utilities::MPI::all_gather
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &t &weight &gap0 &l1 &status;
    }
  };

  /**
   * The size of a contact zone and of its stick zone from the nodes (all
   * ranks), in the tangent plane of Gamma_C.
   * - The centre is where the contact begins: among the active nodes with
   *   the smallest initial gap g0, the one nearest their pressure-weighted
   *   centroid (on a flat face all gaps are equal and it is the node
   *   nearest the centroid of the zone).
   * - 2D: the nodes form one line; 3D: two lines go through the centre
   *   along the tangent axes, made of the nodes within `band` of them (a
   *   quarter of the smallest contact face is right for a mesh whose node
   *   lines are straight there). Each line is measured as
   *   contact_zone_half_width does, and the radius is the mean of the two
   *   lines' half-widths: exact for a circular zone centred on a node line,
   *   the mean extent otherwise.
   * - A line with nodes on one side of the centre only is a model cut by a
   *   plane of symmetry through the centre (a half or quarter model of a
   *   ball): it is completed by its mirror image, `mirrored` counts these
   *   lines, and the area is the whole zone's (the model's times 2 per cut).
   *   A zone cut anywhere else is measured as it is in the model.
   * - The area (sum of m_s over the active nodes) and the extent (the
   *   largest distance of an active node from the centre) describe a zone
   *   that is not a disc.
   * The stick half-width (radius) is half the extent of the longest run of
   * sticking nodes on each line, each end half-way to the next node, averaged
   * over the lines; 0 without friction or without a sticking node.
   */
  struct ContactZoneShape
  {
    ContactZoneWidth      width; // half-width (2D) or radius (3D)
    double                stick_width = 0.;
    double                area        = 0.; // of the whole zone (see above)
    double                extent      = 0.;
    std::array<double, 2> centre{};
    unsigned int          mirrored = 0; // lines completed by symmetry
  };

  ContactZoneShape
  contact_zone_shape(const std::vector<ZoneNode> &nodes,
                     const unsigned int           tangent_dimensions,
                     const double                 band);

  /**
   * The net loads on a body that only the contact may hold, for the
   * equilibrium check before a solve (doc/theory.md §8).
   */
  struct LoadBalance
  {
    double resultant = 0.; // |net load| (for the round-off scale)
    // the translation along the foundation normal m is free (only the
    // contact can stop it), and the net load along m (> 0 pulls the body
    // off the foundation)
    bool   normal_free = false;
    double load_away   = 0.;
    // each free tangential translation's net load; friction must resist
    // their vector sum, whose length is what is checked
    std::vector<double> tangential_loads;
  };

  /**
   * The vertices of the convex hull of `points` in counter-clockwise order
   * (Andrew's monotone chain); `dims` = 1: the points lie on a line (their
   * second coordinates are ignored) and the hull is its two ends.
   */
  std::vector<std::array<double, 2>>
  convex_hull(std::vector<std::array<double, 2>> points, unsigned int dims);

  /**
   * How far `point` lies outside the convex hull `hull` (as convex_hull()
   * gives it): 0 inside or on it, else the distance to its nearest point.
   * `dims` as for convex_hull(). An empty hull is infinitely far.
   */
  double
  distance_outside_hull(const std::vector<std::array<double, 2>> &hull,
                        const std::array<double, 2>              &point,
                        unsigned int                              dims);

  /**
   * Check the necessary conditions of equilibrium: a free normal
   * translation must be pushed toward the foundation, and a free tangential
   * load must not exceed `capacity`, what friction can resist at most
   * (< 0: not known from the loads alone; no check). Throws InputError
   * (exit status 7) with a message that names the loads otherwise.
   * `capacity_text` says where the capacity comes from.
   */
  void
  check_equilibrium(const LoadBalance &balance,
                    const double       capacity,
                    const std::string &capacity_text);
} // namespace dualcontact

#endif
