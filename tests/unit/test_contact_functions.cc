// The pure pieces of the contact solver (contact_functions.h) and the
// friction laws (friction_law.h), each against its formula in
// doc/theory.md.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/friction_law.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>
#include <vector>

using namespace dualcontact;

namespace
{
  Tensor<1, 2>
  vec(const double a, const double b)
  {
    Tensor<1, 2> t;
    t[0] = a;
    t[1] = b;
    return t;
  }
} // namespace

TEST_CASE("Projection onto the disc: identity inside, radial onto the circle "
          "outside",
          "[functions]")
{
  const double g = 2.;
  CHECK((project_onto_disc(vec(1., 1.), g) - vec(1., 1.)).norm() == 0.);
  const Tensor<1, 2> p = project_onto_disc(vec(3., 4.), g);
  CHECK(p.norm() == Approx(g));
  CHECK(p[0] / p[1] == Approx(3. / 4.));
  // 2D contact: the tangent space is a line, the disc the interval [-g, g]
  Tensor<1, 1> y;
  y[0] = -7.;
  CHECK(project_onto_disc(y, g)[0] == Approx(-g));
  y[0] = 0.5;
  CHECK(project_onto_disc(y, g)[0] == 0.5);
  // g = 0: everything projects to zero (no friction capacity)
  CHECK(project_onto_disc(vec(3., 4.), 0.).norm() == 0.);
}

TEST_CASE("Huber function: C^1, its gradient is the projection, its "
          "curvature the projection's derivative",
          "[functions]")
{
  const double g = 1.5;
  // value: |y|^2/2 inside, g|y| - g^2/2 outside, continuous at |y| = g
  CHECK(huber(vec(1., 0.), g) == Approx(0.5));
  CHECK(huber(vec(3., 4.), g) == Approx(g * 5. - 0.5 * g * g));
  CHECK(huber(vec(g, 0.), g) == Approx(0.5 * g * g));
  // the gradient by central differences, inside, outside and at the kink
  for (const Tensor<1, 2> &y :
       {vec(0.3, -0.4), vec(2., 1.), vec(g * 0.6, g * 0.8)})
    {
      const double h = 1e-6;
      for (unsigned int i = 0; i < 2; ++i)
        {
          Tensor<1, 2> e;
          e[i]                = h;
          const double slope  = (huber(y + e, g) - huber(y - e, g)) / (2 * h);
          const double normal = project_onto_disc(y, g)[i];
          CHECK(slope == Approx(normal).margin(1e-8));
        }
    }
  // the derivative of the projection: I inside, (g/|y|)(I - yy^T/|y|^2)
  // outside; symmetric, zero along y and g/|y| across it
  const Tensor<1, 2> inside = vec(0.5, 0.5), outside = vec(3., 4.);
  const Tensor<1, 2> d1 = vec(1., -2.), d2 = vec(0.7, 0.1);
  CHECK((projection_derivative(inside, g, d1) - d1).norm() == 0.);
  CHECK(projection_derivative(outside, g, outside).norm() ==
        Approx(0.).margin(1e-14));
  const Tensor<1, 2> across = vec(-4., 3.);
  CHECK(
    (projection_derivative(outside, g, across) - (g / 5.) * across).norm() ==
    Approx(0.).margin(1e-14));
  CHECK(d1 * projection_derivative(outside, g, d2) ==
        Approx(d2 * projection_derivative(outside, g, d1)));
  CHECK(huber_curvature(outside, g, across) == Approx(g / 5. * 25.));
  // and it is the derivative: (P(y + h d) - P(y - h d)) / 2h = D(y) d
  const double       h  = 1e-6;
  const Tensor<1, 2> fd = (project_onto_disc(outside + h * d1, g) -
                           project_onto_disc(outside - h * d1, g)) /
                          (2 * h);
  CHECK((fd - projection_derivative(outside, g, d1)).norm() ==
        Approx(0.).margin(1e-8));
}

TEST_CASE("Exact line search: the root of a piecewise linear, increasing "
          "phi'",
          "[functions]")
{
  // phi'(a) = -3 + a + 4 (a - 1)^+ + 2 (a - 2)^+ : kinks at 1 and 2, root
  // where -3 + a + 4(a - 1) = 0 -> a = 7/5 (between the kinks)
  const auto derivatives = [](const double a) {
    const double d1 =
      -3. + a + 4. * std::max(a - 1., 0.) + 2. * std::max(a - 2., 0.);
    const double d2 = 1. + (a >= 1. ? 4. : 0.) + (a >= 2. ? 2. : 0.);
    return std::make_pair(d1, d2);
  };
  CHECK(exact_line_search(derivatives) == Approx(1.4).epsilon(1e-10));

  // a root beyond 1, found after the bracket grows: phi'(a) = a - 37
  const auto far = [](const double a) { return std::make_pair(a - 37., 1.); };
  CHECK(exact_line_search(far) == Approx(37.).epsilon(1e-10));

  // a root below 1 (a step that meets new contact nodes): phi' = 10 a - 1
  const auto near = [](const double a) {
    return std::make_pair(10. * a - 1., 10.);
  };
  CHECK(exact_line_search(near) == Approx(0.1).epsilon(1e-10));
}

TEST_CASE("Contact zone half-width: outermost nodes, and the edges "
          "extrapolated from the square-root pressure",
          "[functions]")
{
  // a Hertz pressure p = sqrt(1 - x^2/a^2) sampled at nodes h apart
  const double                           a = 0.33, h = 0.05;
  std::vector<std::pair<double, double>> nodes;
  for (int i = -20; i <= 20; ++i)
    {
      const double x = i * h;
      nodes.emplace_back(x, std::sqrt(std::max(1. - x * x / (a * a), 0.)));
    }
  const ContactZoneWidth width = contact_zone_half_width(nodes);
  CHECK(width.nodes == Approx(0.3)); // the outermost active nodes, +-0.3
  // l1^2 is exactly linear in x^2, not in x: the extrapolation is within
  // a fraction of h of the true edge, and better than the nodes
  CHECK(std::abs(width.extrapolated - a) < 0.2 * h);
  CHECK(std::abs(width.extrapolated - a) < std::abs(width.nodes - a));
  // never beyond the first separated node
  CHECK(width.extrapolated <= 0.35);

  // a zone that reaches the end of Gamma_C keeps its outermost node there
  std::vector<std::pair<double, double>> flat = {{0., 1.}, {1., 1.}, {2., 1.}};
  CHECK(contact_zone_half_width(flat).extrapolated == Approx(1.));
  // no active node: zero
  std::vector<std::pair<double, double>> none = {{0., 0.}, {1., 0.}};
  CHECK(contact_zone_half_width(none).nodes == 0.);
  CHECK(contact_zone_half_width(none).extrapolated == 0.);
}

namespace
{
  // the contact nodes of a ball on a plane: a grid of spacing h over
  // [i0, 20] x [j0, 20] (i0, j0 = -20 for the whole plane, 0 for a model cut
  // at the ball's axis) with the gap r^2 / 2, the Hertz pressure of radius
  // a and a stick zone of radius c
  std::vector<ZoneNode>
  ball_nodes(const int i0, const int j0, const double h)
  {
    const double          a = 0.33, c = 0.21;
    std::vector<ZoneNode> nodes;
    for (int i = i0; i <= 20; ++i)
      for (int j = j0; j <= 20; ++j)
        {
          ZoneNode     node;
          const double r2 = h * h * (i * i + j * j);
          node.t          = {{i * h, j * h}};
          // a node on a cut owns half a cell there (a quarter at a corner)
          node.weight = h * h * (i == i0 && i0 == 0 ? 0.5 : 1.) *
                        (j == j0 && j0 == 0 ? 0.5 : 1.);
          node.gap0   = 0.5 * r2;
          node.l1     = std::sqrt(std::max(1. - r2 / (a * a), 0.));
          node.status = node.l1 > 0. ? (r2 < c * c ? 1 : 2) : 0;
          nodes.push_back(node);
        }
    return nodes;
  }
} // namespace

TEST_CASE("Contact zone shape in 3D: the same radius, stick radius and area "
          "on the whole plane and on a half or quarter model",
          "[functions]")
{
  const double           h = 0.05, band = 0.25 * h;
  const ContactZoneShape whole =
    contact_zone_shape(ball_nodes(-20, -20, h), 2, band);
  CHECK(whole.mirrored == 0);
  CHECK(whole.centre[0] == Approx(0.).margin(1e-14));
  CHECK(whole.centre[1] == Approx(0.).margin(1e-14));
  CHECK(whole.width.nodes == Approx(0.3)); // nodes at +-0.3 on both lines
  CHECK(std::abs(whole.width.extrapolated - 0.33) < 0.2 * h);
  // stick nodes up to 0.2, the run's ends half-way to the slip nodes
  CHECK(whole.stick_width == Approx(0.225));
  // the active nodes' cells cover the disc to within a cell per node on
  // its edge
  CHECK(std::abs(whole.area - M_PI * 0.33 * 0.33) < 2. * M_PI * 0.33 * h);
  CHECK(whole.extent == Approx(std::hypot(0.25, 0.2))); // r < a nearest a

  for (const auto &[i0, j0, cuts] :
       {std::tuple<int, int, unsigned int>{0, -20, 1}, {-20, 0, 1}, {0, 0, 2}})
    {
      CAPTURE(i0, j0);
      const ContactZoneShape cut =
        contact_zone_shape(ball_nodes(i0, j0, h), 2, band);
      CHECK(cut.mirrored == cuts);
      CHECK(cut.width.nodes == Approx(whole.width.nodes));
      CHECK(cut.width.extrapolated == Approx(whole.width.extrapolated));
      CHECK(cut.stick_width == Approx(whole.stick_width));
      CHECK(cut.area == Approx(whole.area));
      CHECK(cut.extent == Approx(whole.extent));
    }

  // a flat face (all gaps equal): the centre is the node nearest the
  // pressure centroid, and a zone cut off-centre is not mirrored
  std::vector<ZoneNode> flat;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 4; ++j)
      {
        ZoneNode node;
        node.t      = {{i * h, j * h}};
        node.weight = h * h;
        node.l1     = 1.;
        node.status = 1;
        flat.push_back(node);
      }
  const ContactZoneShape block = contact_zone_shape(flat, 2, band);
  CHECK(block.mirrored == 0);
  CHECK(block.centre[0] == Approx(0.25));
  CHECK(block.centre[1] == Approx(0.1));
  CHECK(block.width.nodes == Approx(0.5 * (0.25 + 0.1)));
  CHECK(block.area == Approx(55 * h * h));
}

TEST_CASE("Contact zone shape in 2D: the half-width of a whole line, and of a "
          "line cut at the first contact",
          "[functions]")
{
  const double          a = 0.33, h = 0.05;
  std::vector<ZoneNode> line, half;
  for (int i = -20; i <= 20; ++i)
    {
      ZoneNode node;
      node.t      = {{i * h, 0.}};
      node.weight = h;
      node.gap0   = 0.5 * node.t[0] * node.t[0];
      node.l1 = std::sqrt(std::max(1. - node.t[0] * node.t[0] / (a * a), 0.));
      node.status = node.l1 > 0. ? 1 : 0;
      line.push_back(node);
      if (i >= 0)
        half.push_back(node);
    }
  std::vector<std::pair<double, double>> pressures;
  for (const ZoneNode &node : line)
    pressures.emplace_back(node.t[0], node.l1);
  const ContactZoneWidth width = contact_zone_half_width(pressures);
  const ContactZoneShape shape = contact_zone_shape(line, 1, 0.25 * h);
  CHECK(shape.mirrored == 0);
  CHECK(shape.width.nodes == width.nodes);
  CHECK(shape.width.extrapolated == width.extrapolated);
  const ContactZoneShape cut = contact_zone_shape(half, 1, 0.25 * h);
  CHECK(cut.mirrored == 1);
  CHECK(cut.width.nodes == Approx(width.nodes));
  CHECK(cut.width.extrapolated == Approx(width.extrapolated));
  // no active node: all zero
  for (ZoneNode &node : line)
    node.l1 = 0.;
  CHECK(contact_zone_shape(line, 1, 0.25 * h).width.nodes == 0.);
  CHECK(contact_zone_shape(line, 1, 0.25 * h).area == 0.);
}

TEST_CASE("Equilibrium check: loads that only the contact could hold",
          "[functions]")
{
  LoadBalance balance;
  balance.resultant        = 10.;
  balance.normal_free      = true;
  balance.load_away        = -10.; // pushes toward the foundation
  balance.tangential_loads = {2.};
  // friction can resist 3 > 2: fine; 1 < 2: no equilibrium
  CHECK_NOTHROW(check_equilibrium(balance, 3., "F N"));
  try
    {
      check_equilibrium(balance, 1., "F N");
      FAIL("no exception");
    }
  catch (const InputError &error)
    {
      CHECK(error.code == exit_no_equilibrium);
      CHECK(std::string(error.what()).find("tangential load 2.0") !=
            std::string::npos);
    }
  // capacity unknown (< 0): the tangential load is not checked
  CHECK_NOTHROW(check_equilibrium(balance, -1., ""));
  // pulled off the foundation
  balance.load_away = 1.;
  CHECK_THROWS_AS(check_equilibrium(balance, 3., ""), InputError);
  // ... unless something else holds the body normally
  balance.normal_free = false;
  CHECK_NOTHROW(check_equilibrium(balance, 3., ""));
  // a load at round-off of the resultant counts as zero
  balance.tangential_loads = {1e-12};
  CHECK_NOTHROW(check_equilibrium(balance, 0., "frictionless contact"));
  // 3D: friction resists a disc of tangential forces, so an oblique load
  // (1.2, 1.2) exceeds the capacity 1.6 although each part stays below it
  balance.normal_free      = true;
  balance.load_away        = -10.;
  balance.tangential_loads = {1.2, 1.2};
  CHECK_THROWS_AS(check_equilibrium(balance, 1.6, "F N"), InputError);
  balance.tangential_loads = {1.1, 1.1};
  CHECK_NOTHROW(check_equilibrium(balance, 1.6, "F N"));
}

TEST_CASE("Convex hull of the contact nodes and the distance from it",
          "[functions]")
{
  using P = std::array<double, 2>;
  // 2D: an interval on the foundation line
  const auto interval =
    convex_hull({P{{0.5, 0.}}, P{{-1., 0.}}, P{{2., 0.}}}, 1);
  REQUIRE(interval.size() == 2);
  CHECK(interval.front()[0] == -1.);
  CHECK(interval.back()[0] == 2.);
  CHECK(distance_outside_hull(interval, P{{0., 0.}}, 1) == 0.);
  CHECK(distance_outside_hull(interval, P{{2.5, 0.}}, 1) == Approx(0.5));
  CHECK(distance_outside_hull(interval, P{{-1.25, 0.}}, 1) == Approx(0.25));

  // 3D: the unit square's nodes on a 3 x 3 grid, with interior points
  std::vector<P> grid;
  for (unsigned int i = 0; i <= 2; ++i)
    for (unsigned int j = 0; j <= 2; ++j)
      grid.push_back(P{{0.5 * i, 0.5 * j}});
  const auto square = convex_hull(grid, 2);
  CHECK(square.size() == 4); // collinear edge midpoints dropped
  CHECK(distance_outside_hull(square, P{{0.5, 0.5}}, 2) == 0.);
  CHECK(distance_outside_hull(square, P{{1., 0.3}}, 2) == 0.); // on an edge
  CHECK(distance_outside_hull(square, P{{1.2, 0.5}}, 2) == Approx(0.2));
  CHECK(distance_outside_hull(square, P{{1.3, 1.4}}, 2) == Approx(0.5));
  // a triangle: the point beyond its hypotenuse
  const auto triangle = convex_hull({P{{0., 0.}}, P{{1., 0.}}, P{{0., 1.}}}, 2);
  CHECK(distance_outside_hull(triangle, P{{0.6, 0.6}}, 2) ==
        Approx(0.1 * std::sqrt(2.)));
  CHECK(distance_outside_hull(triangle, P{{0.2, 0.2}}, 2) == 0.);
  // degenerate hulls: a segment and a point; no node at all
  const auto segment = convex_hull({P{{0., 0.}}, P{{1., 0.}}, P{{0.5, 0.}}}, 2);
  CHECK(distance_outside_hull(segment, P{{0.5, 0.3}}, 2) == Approx(0.3));
  CHECK(distance_outside_hull(convex_hull({P{{1., 1.}}}, 2), P{{1., 2.}}, 2) ==
        Approx(1.));
  CHECK(std::isinf(distance_outside_hull({}, P{{0., 0.}}, 2)));
}

TEST_CASE("Friction laws: the threshold from the pressure, written once",
          "[functions][friction]")
{
  const std::vector<std::string> names = friction_law_names();
  for (const std::string name : {"coulomb", "given", "none"})
    CHECK(std::find(names.begin(), names.end(), name) != names.end());

  const auto coulomb = create_friction_law("coulomb");
  CHECK(coulomb->has_friction());
  CHECK(coulomb->depends_on_pressure());
  CHECK(coulomb->parameter_entry() == "Coefficient");
  CHECK(coulomb->threshold(0.3, 10.) == Approx(3.));
  std::string why;
  CHECK(coulomb->capacity(0., 0.3, 20., why) == Approx(6.));
  CHECK(coulomb->capacity(0., 0.3, -1., why) < 0.); // N not known

  const auto given = create_friction_law("given");
  CHECK(given->has_friction());
  CHECK(!given->depends_on_pressure());
  CHECK(given->threshold(2., 0.) == 2.);
  CHECK(given->threshold(2., 100.) == 2.);
  CHECK(given->capacity(5., 2., 20., why) == 5.); // sum m_s g_s

  const auto none = create_friction_law("none");
  CHECK(!none->has_friction());
  CHECK(none->threshold(1., 1.) == 0.);
  CHECK(none->capacity(5., 2., 20., why) == 0.);

  CHECK_THROWS(create_friction_law("no such law"));
}

namespace
{
  // A law from outside the library: a coefficient that falls with the
  // pressure, g = F l1 / (1 + l1 / p_ref) (step-3's extension).
  class PressureDependent : public FrictionLaw
  {
  public:
    std::string
    name() const override
    {
      return "pressure dependent";
    }
    std::string
    description() const override
    {
      return "a coefficient falling with the pressure";
    }
    bool
    depends_on_pressure() const override
    {
      return true;
    }
    std::string
    parameter_entry() const override
    {
      return "Coefficient";
    }
    double
    threshold(const double F, const double l1) const override
    {
      return F * l1 / (1. + l1);
    }
    double
    capacity(const double,
             const double F,
             const double N,
             std::string &why) const override
    {
      why = "at most F N";
      return N < 0. ? -1. : F * N;
    }
  };
} // namespace

TEST_CASE("A friction law registered from outside the library is a choice "
          "of <Friction/Law>",
          "[functions][friction]")
{
  const bool registered = register_friction_law("pressure dependent", [] {
    return std::make_unique<PressureDependent>();
  });
  CHECK(registered);
  Parameters parameters;
  CHECK_NOTHROW(
    parameters.read_string("subsection Boundary conditions\n"
                           "  set Conditions = 2: contact, 3: fixed\n"
                           "end\n"
                           "subsection Friction\n"
                           "  set Law = pressure dependent\n"
                           "  set Coefficient = 0.3\n"
                           "end\n"));
  CHECK(parameters.friction.law == "pressure dependent");
  CHECK(create_friction_law("pressure dependent")->threshold(0.5, 1.) ==
        Approx(0.25));
}
