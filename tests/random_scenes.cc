// random_scenes: the deterministic generator of the test random_inputs
// (tests/check_random_inputs.sh).
//
//   random_scenes <source dir> <output dir> [seed]
//
// writes into <output dir>, which must not exist (the seed defaults to the
// test's; another one makes other inputs, to explore):
//   valid_NN.prm    small scenes that are valid by construction: boxes on the
//                   foundation plane (2D and 3D, pressed by a traction, held
//                   sideways by friction, a slider or a clamped side), half
//                   discs and half balls and quarter discs pressed onto it,
//                   indenters (a cylinder, a sphere or a flat punch given by
//                   its distance, moved into a box with a fixed base), and
//                   the half disc of prm/meshes/half_disc.msh. E from 1e-3 to
//                   1e9, nu from 0 to 0.45, friction none, given or coulomb
//                   (F from 0.1 to 1), refinement global, kelly or contact,
//                   1 or 2 cycles, each a few hundred to a few thousand DoFs.
//                   The loads are ones the contact can hold: toward the
//                   obstacle and, when only the contact holds the body along
//                   it, a tangential load at most 0.3 times what friction
//                   could hold and whose moment keeps the centre of pressure
//                   within 0.3 of the half-width of the base (no tipping).
//                   Then two bodies in contact (a contact pair, the pair
//                   written either way, doc/two_bodies.md), most on one
//                   cycle: 'two blocks' (2D and 3D, quadrilaterals or
//                   simplices, meshes that do not match across the cut, the
//                   upper block sometimes of another material) with the
//                   lower block clamped or on the plane and sliders ('normal
//                   fixed') on one side or both, stacks of two blocks on the
//                   plane, an upper block that reaches beyond the lower one
//                   (<Geometry/Upper overhang>), load paths that press and
//                   unload to zero (the last step without load), Gmsh files
//                   of two blocks of triangles that the generator writes
//                   (format 2.2 or 4.1, nodes of their own on each side of
//                   the cut, the upper block narrower or wider), and Hertz's
//                   two half discs of one radius or two. The upper body is
//                   pressed onto the lower one; where its pair alone holds
//                   it, its tangential load is at most 0.3 of what friction
//                   holds (none without friction) and 0.3 of the tipping
//                   limit; pulled off, it must be refused (exit 7) whether
//                   nothing or sliders hold it sideways.
//   mutated_NN.prm  inputs derived from the shipped scenes prm/*.prm (made
//                   cheap first: one cycle, at most 2 global refinements in
//                   2D and 1 in 3D, few pre-refinement steps, no vtu) and
//                   from the valid ones, by one mutation each (the table
//                   `kinds` below: the kind, what it does, the exit
//                   statuses it allows; of the scenes of two bodies also a
//                   pair id that does not exist, both ids on one body, an id
//                   in two pairs, and the pair turned round).
//   meshes/         prm/meshes/half_disc.msh and half_disc_v22.msh, the
//                   meshes of the shipped scenes, the Gmsh files of two
//                   blocks (two_blocks_N.msh), and the garbled copies the
//                   mutations make
//   manifest.txt    one line per input: name, MPI ranks, the allowed exit
//                   statuses (comma-separated), a description; tab-separated
//
// Determinism: the numbers come from std::mt19937 with a fixed seed, whose
// raw 32-bit output the C++ standard fixes; they are mapped to integers and
// reals by the functions below (not by std::uniform_*_distribution, whose
// algorithm each standard library chooses), and only through +, -, *, / (no
// libm function, whose last bit may differ), so that every platform writes
// the same files. Each statement draws at most one random number: the
// order in which a call's arguments are evaluated is unspecified. The
// shipped scenes are read in sorted order: a new scene changes the mutated
// inputs, which stay reproducible from the files written (the driver keeps
// those of a failing run).

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
  // ------------------------------------------------------------ numbers
  std::mt19937 rng(20250601u);

  std::uint32_t
  raw()
  {
    return static_cast<std::uint32_t>(rng());
  }

  // an integer in [0, n): the high 32 bits of raw * n (bias below 2^-32 n)
  unsigned int
  below(const unsigned int n)
  {
    return static_cast<unsigned int>((std::uint64_t(raw()) * n) >> 32);
  }

  // a real in [a, b)
  double
  uniform(const double a, const double b)
  {
    return a + (b - a) * (raw() / 4294967296.0);
  }

  bool
  chance(const unsigned int percent)
  {
    return below(100) < percent;
  }

  template <typename T>
  const T &
  pick(const std::vector<T> &v)
  {
    return v[below(v.size())];
  }

  // 10^k by products, exact up to the rounding of each product
  double
  power_of_ten(int k)
  {
    double x = 1;
    for (; k > 0; --k)
      x *= 10;
    for (; k < 0; ++k)
      x /= 10;
    return x;
  }

  // a number as the scene writes it: 6 significant digits (printf rounds
  // correctly), and the value read back, so that what the generator
  // computes with is what the file says
  std::string
  text(const double x, const int digits = 6)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x + 0.); // no -0
    return buffer;
  }

  double
  rounded(const double x, const int digits = 4)
  {
    return std::strtod(text(x, digits).c_str(), nullptr);
  }

  std::string
  join(const std::vector<double> &v, const std::string &separator)
  {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i)
      s += (i ? separator : "") + text(v[i]);
    return s;
  }

  std::string
  vec(const std::vector<double> &v)
  {
    return join(v, ", ");
  }

  // ------------------------------------------------------------ scenes
  // A parameter file as lines, with what a mutation needs to know about
  // the scene it describes.
  struct Scene
  {
    std::string              name;  // where it came from
    std::vector<std::string> lines; // without the header comment
    unsigned int             dim = 2;
    std::string              geometry; // rectangle, half disc, ...
    std::string              obstacle; // plane, cylinder, sphere, distance
    std::string              law;      // none, given, coulomb
    unsigned int             ranks = 1;
    // a Tractions value that reverses the normal load (the body is then
    // pulled off the foundation), and the exit statuses it allows: 7 if
    // nothing but the contact holds the body along the normal, 0 if a
    // clamped side does
    std::string pull_off;
    std::string pull_off_exits;
    // a Tractions value with a tangential load 1.5 times what friction can
    // hold (only friction holds the body along the foundation): exit 7
    std::string overload;
    // of a scene of two bodies: its <Boundary conditions/Contact pairs>,
    // and a pair of two ids on one body that are free or loaded (the
    // second one not in the scene's pair)
    std::string pair;
    std::string one_body_pair;
    // whether the pair holds when turned round (a generated scene whose
    // pair was drawn either way)
    bool pair_turns = false;
  };

  struct Line
  {
    enum Kind
    {
      blank,
      comment,
      subsection,
      end,
      set,
      other
    } kind = blank;
    std::string section; // of a set line: the enclosing subsection
    std::string name;    // entry or subsection name
    std::string value;
  };

  std::string
  trim(const std::string &s)
  {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos)
      return "";
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
  }

  std::vector<Line>
  parse(const std::vector<std::string> &lines)
  {
    std::vector<Line> result;
    std::string       section;
    for (const std::string &raw_line : lines)
      {
        Line        line;
        std::string s = raw_line.substr(0, raw_line.find('#'));
        s             = trim(s);
        if (trim(raw_line).empty())
          line.kind = Line::blank;
        else if (s.empty())
          line.kind = Line::comment;
        else if (s.rfind("subsection ", 0) == 0)
          {
            line.kind = Line::subsection;
            line.name = trim(s.substr(11));
            section   = line.name;
          }
        else if (s == "end")
          {
            line.kind = Line::end;
            section.clear();
          }
        else if (s.rfind("set ", 0) == 0 && s.find('=') != std::string::npos)
          {
            line.kind    = Line::set;
            line.section = section;
            line.name    = trim(s.substr(4, s.find('=') - 4));
            line.value   = trim(s.substr(s.find('=') + 1));
          }
        else
          line.kind = Line::other;
        result.push_back(line);
      }
    return result;
  }

  // the index of the line setting section/entry, or -1
  int
  find(const Scene &scene, const std::string &section, const std::string &entry)
  {
    const std::vector<Line> lines = parse(scene.lines);
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].kind == Line::set && lines[i].section == section &&
          lines[i].name == entry)
        return static_cast<int>(i);
    return -1;
  }

  std::optional<std::string>
  get(const Scene &scene, const std::string &section, const std::string &entry)
  {
    const int i = find(scene, section, entry);
    if (i < 0)
      return std::nullopt;
    return parse(scene.lines)[i].value;
  }

  // sets an entry: replaces the value of its line, or adds the line to the
  // end of its subsection, or a new subsection at the end of the file
  void
  put(Scene             &scene,
      const std::string &section,
      const std::string &entry,
      const std::string &value)
  {
    const std::string line = "  set " + entry + " = " + value;
    const int         i    = find(scene, section, entry);
    if (i >= 0)
      {
        scene.lines[i] = line;
        return;
      }
    const std::vector<Line> lines = parse(scene.lines);
    for (std::size_t k = 0; k < lines.size(); ++k)
      if (lines[k].kind == Line::subsection && lines[k].name == section)
        for (std::size_t e = k + 1; e < lines.size(); ++e)
          if (lines[e].kind == Line::end)
            {
              scene.lines.insert(scene.lines.begin() + e, line);
              return;
            }
    scene.lines.push_back("subsection " + section);
    scene.lines.push_back(line);
    scene.lines.push_back("end");
  }

  std::vector<std::string>
  split(const std::string &s, const char separator)
  {
    std::vector<std::string> parts;
    std::string              part;
    std::istringstream       in(s);
    while (std::getline(in, part, separator))
      parts.push_back(part);
    if (!s.empty() && s.back() == separator)
      parts.emplace_back();
    return parts;
  }

  // the ids of <Boundary conditions/Conditions> with the given condition
  std::vector<std::string>
  ids_with(const Scene &scene, const std::string &condition)
  {
    std::vector<std::string> ids;
    const auto conditions = get(scene, "Boundary conditions", "Conditions");
    if (!conditions)
      return ids;
    for (const std::string &item : split(*conditions, ','))
      {
        const auto colon = item.find(':');
        if (colon != std::string::npos &&
            trim(item.substr(colon + 1)) == condition)
          ids.push_back(trim(item.substr(0, colon)));
      }
    return ids;
  }

  // ------------------------------------------------------------ valid scenes
  struct Builder
  {
    Scene scene;

    void
    set(const std::string &section,
        const std::string &entry,
        const std::string &value)
    {
      put(scene, section, entry, value);
    }
  };

  // E = m 10^k, m in [1, 10) with one decimal, k in [-3, 8]: 1e-3 to 9.9e8,
  // and sometimes exactly 1e9
  double
  random_modulus()
  {
    if (chance(8))
      return 1e9;
    const double m = 1 + below(90) / 10.;
    return rounded(m * power_of_ten(static_cast<int>(below(12)) - 3), 2);
  }

  // the scene's material, a strain of 1e-4 to 2e-3 that sets its loads (the
  // pressure p = E strain), and the common entries
  struct Common
  {
    double E, nu, strain;
  };

  Common
  material(Builder &b)
  {
    Common c;
    c.E      = random_modulus();
    c.nu     = below(10) * 0.05;
    c.strain = rounded(uniform(1e-4, 2e-3), 2);
    b.set("Material", "Young's modulus", text(c.E));
    b.set("Material", "Poisson's ratio", text(c.nu, 2));
    return c;
  }

  // friction: the law and, for the box families, the largest tangential
  // traction it holds per unit normal pressure (F for coulomb, g/p for
  // given, 0 for none)
  // the laws take turns, so that each has a third of the valid scenes
  unsigned int law_turn = 0;

  double
  friction(Builder &b, const double pressure, const bool coulomb = true)
  {
    unsigned int law = law_turn++ % 3;
    if (law == 1 && !coulomb)
      law = law_turn++ % 3;
    if (law == 0)
      {
        b.scene.law = "none";
        return 0;
      }
    if (law == 1)
      {
        b.scene.law    = "coulomb";
        const double F = (1 + below(10)) / 10.;
        b.set("Friction", "Law", "coulomb");
        b.set("Friction", "Coefficient", text(F, 2));
        if (chance(30))
          b.set("Friction", "Threshold iteration", "nested");
        if (chance(30))
          b.set("Friction", "Initial threshold", "frictionless");
        return F;
      }
    b.scene.law           = "given";
    const double fraction = (1 + below(10)) / 10.;
    const double g        = rounded(fraction * pressure);
    b.set("Friction", "Law", "given");
    b.set("Friction", "Threshold", text(g));
    return g / pressure;
  }

  // refinement: the strategy and 1 or 2 cycles; returns the factor by which
  // the cells grow over the cycles (an estimate for kelly/contact)
  double
  refinement(Builder &b, const unsigned int dim, const bool allow_two = true)
  {
    const unsigned int cycles = allow_two ? 1 + below(2) : 1;
    b.set("Refinement", "Number of cycles", std::to_string(cycles));
    // one cycle: no refinement, and the entries of one would have no effect
    if (cycles == 1)
      return 1;
    const unsigned int strategy = below(3);
    const char        *names[]  = {"global", "kelly", "contact"};
    b.set("Refinement", "Strategy", names[strategy]);
    if (strategy != 0)
      b.set("Refinement", "Refine fraction", text(0.2 + below(3) / 10., 2));
    if (strategy == 0)
      return dim == 2 ? 4 : 8;
    return dim == 2 ? 2 : 3;
  }

  void
  output(Builder &b)
  {
    b.set("Output", "Write vtu", "false");
    b.set("Output", "Print timing", "false");
    b.set("Output", "Verbosity", chance(50) ? "quiet" : "normal");
  }

  std::string
  tractions(const std::string &id, const std::vector<double> &t)
  {
    return id + ": " + join(t, "; ");
  }

  // A box on the foundation plane, the contact on one of its faces, a
  // pressure p (and a shear q) on the opposite face. Held along the
  // foundation by friction alone, by a slider on a side ('normal fixed') or
  // by a clamped side ('fixed').
  Scene
  box_on_plane(const unsigned int dim)
  {
    Builder b;
    b.scene.dim      = dim;
    b.scene.geometry = "rectangle";
    b.scene.obstacle = "plane";
    b.set("Geometry", "Dimension", std::to_string(dim));
    b.set("Geometry", "Type", "rectangle");
    const Common c = material(b);

    std::vector<double> lower(dim), size(dim), upper(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = rounded(uniform(-2, 2), 3);
        size[d]  = rounded(uniform(0.5, dim == 2 ? 3 : 2), 3);
        upper[d] = rounded(lower[d] + size[d], 6);
        size[d]  = upper[d] - lower[d];
      }
    b.set("Geometry", "Lower left corner", vec(lower));
    b.set("Geometry", "Upper right corner", vec(upper));

    // the contact face: axis a, at its lower (side 0) or upper end
    const unsigned int  a       = below(dim);
    const unsigned int  side    = below(2);
    const unsigned int  contact = 2 * a + side;
    const unsigned int  loaded  = 2 * a + 1 - side;
    std::vector<double> normal(dim, 0.), point = lower;
    normal[a] = side == 0 ? 1 : -1;
    point[a]  = side == 0 ? lower[a] : upper[a];
    b.set("Foundation", "Point", vec(point));
    b.set("Foundation", "Normal", vec(normal));

    // cells about square, 2 to 4 across the smallest side
    const double        smallest = *std::min_element(size.begin(), size.end());
    const double        h        = smallest / (2 + below(3));
    std::vector<double> subdivisions(dim);
    double              cells = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        subdivisions[d] = std::max(1., double(int(size[d] / h + 0.5)));
        cells *= subdivisions[d];
      }
    b.set("Geometry", "Subdivisions", vec(subdivisions));

    const double p     = rounded(c.E * c.strain);
    const double ratio = friction(b, p); // tangential capacity per unit p

    // support along the foundation, in turns: 0 friction alone, 1 slider,
    // 2 clamp
    static unsigned int support_turn = 0;
    const unsigned int  support      = support_turn++ % 3;
    // a side perpendicular to the contact, for each tangential axis
    std::string conditions = std::to_string(contact) + ": contact, " +
                             std::to_string(loaded) + ": traction";
    for (unsigned int t = 0; t < dim; ++t)
      if (t != a && support > 0)
        conditions += ", " + std::to_string(2 * t + below(2)) + ": " +
                      (support == 1 ? "normal fixed" : "fixed");
    b.set("Boundary conditions", "Conditions", conditions);

    // the shear: with friction alone at most 0.3 of its capacity and 0.3 of
    // the tipping limit (half the base over the height); otherwise up to p/2
    double shear_fraction;
    if (support == 0)
      shear_fraction =
        0.3 * std::min(ratio, smallest / (2 * size[a])) * uniform(0, 1);
    else
      shear_fraction = 0.5 * uniform(0, 1);
    const double        q = rounded(shear_fraction * p);
    std::vector<double> traction(dim, 0.);
    traction[a] = -p * normal[a];
    // the shear along the first tangential axis, or split over both in 3D
    const unsigned int t1 = (a + 1) % dim;
    if (dim == 2 || chance(50))
      traction[t1] = chance(50) ? q : -q;
    else
      {
        const unsigned int t2 = (a + 2) % dim;
        traction[t1]          = rounded(0.6 * q);
        traction[t2]          = rounded(-0.8 * q);
      }
    b.set("Boundary conditions",
          "Tractions",
          tractions(std::to_string(loaded), traction));

    // a body force toward the foundation, sometimes: up to the pressure's
    // load again
    double body_load = 0; // per unit area of the contact face
    if (chance(25))
      {
        std::vector<double> f(dim, 0.);
        const double        magnitude = rounded(p / size[a] * uniform(0.1, 1));
        f[a]                          = -normal[a] * magnitude;
        body_load                     = magnitude * size[a];
        b.set("Loads", "Body force", join(f, "; "));
      }

    std::vector<double> pulled = traction;
    pulled[a]                  = -pulled[a] * (body_load > 0 ? 3 : 1);
    b.scene.pull_off           = tractions(std::to_string(loaded), pulled);
    b.scene.pull_off_exits     = support == 2 ? "0" : "7";
    if (support == 0)
      {
        // along t1: 1.5 times what friction holds (coulomb: F times the
        // normal load; given: g times the area), p/2 without friction
        std::vector<double> over(dim, 0.);
        over[a] = traction[a];
        over[t1] =
          rounded(b.scene.law == "coulomb" ? 1.5 * ratio * (p + body_load) :
                  b.scene.law == "given"   ? 1.5 * ratio * p :
                                             0.5 * p);
        b.scene.overload = tractions(std::to_string(loaded), over);
      }

    // at most ~1200 cells (2D) or ~500 (3D) on the last cycle
    const double growth = refinement(b, dim);
    const double limit  = dim == 2 ? 1200 : 500;
    unsigned int global = 0;
    const double per    = dim == 2 ? 4 : 8;
    while (global < 3 && cells * per * growth <= limit)
      {
        cells *= per;
        ++global;
      }
    b.set("Refinement", "Initial global refinement", std::to_string(global));
    output(b);

    b.scene.name = std::string(dim == 2 ? "2D" : "3D") +
                   " box on the plane, contact on id " +
                   std::to_string(contact) + ", pressed by " + text(p) +
                   " on id " + std::to_string(loaded) + ", shear " + text(q) +
                   ", held along it by " +
                   (support == 0 ? "friction alone" :
                    support == 1 ? "a slider" :
                                   "a clamped side") +
                   ", friction " + b.scene.law;
    return b.scene;
  }

  // A half disc (2D) or half ball (3D), or a quarter disc (2D), pressed onto
  // the plane below it by a pressure on its flat top. Nothing but the
  // contact holds it along the plane (the quarter disc: its symmetry line is
  // a slider), so there is no tangential load.
  Scene
  disc_on_plane(const unsigned int dim,
                const bool         quarter,
                const bool         mesh_file)
  {
    Builder b;
    b.scene.dim      = dim;
    b.scene.geometry = mesh_file ? "mesh file" :
                       quarter   ? "quarter disc" :
                                   "half disc";
    b.scene.obstacle = "plane";
    b.set("Geometry", "Dimension", std::to_string(dim));
    b.set("Geometry", "Type", b.scene.geometry);
    const Common c = material(b);

    double              R = 1;
    std::vector<double> centre(dim, 0.);
    if (mesh_file)
      {
        b.set("Geometry", "Mesh file", "meshes/half_disc.msh");
        b.set("Geometry", "Manifolds", "0: circle center 0, 0 radius 1");
      }
    else
      {
        R = rounded(uniform(0.5, 2), 3);
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = rounded(uniform(-1, 1), 3);
        b.set("Geometry", "Center", vec(centre));
        b.set("Geometry", "Radius", text(R));
      }
    std::vector<double> point = centre, normal(dim, 0.);
    point[dim - 1] -= R;
    normal[dim - 1] = 1;
    b.set("Foundation", "Point", vec(point));
    b.set("Foundation", "Normal", vec(normal));

    // the contact zone a/R ~ sqrt(q/E): resolved by pre-refinement
    const double q = rounded(c.E * c.strain * 2);
    friction(b, q);
    const std::string top = "1";
    b.set("Boundary conditions",
          "Conditions",
          std::string("0: contact, 1: traction") +
            (quarter ? ", 2: normal fixed" : ""));
    std::vector<double> traction(dim, 0.);
    traction[dim - 1] = -q;
    b.set("Boundary conditions", "Tractions", tractions(top, traction));
    std::vector<double> pulled(dim, 0.);
    pulled[dim - 1]        = q;
    b.scene.pull_off       = tractions(top, pulled);
    b.scene.pull_off_exits = "7";

    const double growth = refinement(b, dim, dim == 2);
    b.set("Refinement",
          "Initial global refinement",
          dim == 2 ? (growth > 2 ? "2" : "3") : "1");
    b.set("Geometry", "Pre-refinement steps", dim == 2 ? "3" : "2");
    b.set("Geometry", "Pre-refinement distance", text(rounded(0.15 * R)));
    b.set("Geometry", "Pre-refinement grading", "0.6");
    output(b);

    b.scene.name = std::string(mesh_file ? "the half disc of half_disc.msh" :
                               quarter   ? "2D quarter disc" :
                               dim == 2  ? "2D half disc" :
                                           "3D half ball") +
                   " of radius " + text(R) + " pressed by " + text(q) +
                   ", friction " + b.scene.law;
    return b.scene;
  }

  // An indenter moved into a box with a fixed base by <Obstacle/
  // Displacement>: a cylinder (2D), a sphere (3D) or a flat punch (2D, a
  // signed distance), touching the top face at one point (a segment for the
  // punch) at the start; half or quarter models use sliders on the
  // symmetry planes.
  Scene
  indenter(const unsigned int dim, const bool punch)
  {
    Builder b;
    b.scene.dim      = dim;
    b.scene.geometry = "rectangle";
    b.scene.obstacle = punch ? "distance" : dim == 2 ? "cylinder" : "sphere";
    b.set("Geometry", "Dimension", std::to_string(dim));
    b.set("Geometry", "Type", "rectangle");
    material(b);

    const double        W         = rounded(uniform(1.5, 4), 3);
    const double        H         = rounded(uniform(1, 3), 3);
    const bool          symmetric = chance(50);
    std::vector<double> lower(dim, 0.), upper(dim, W), subdivisions(dim, 1.);
    lower[dim - 1] = -H;
    upper[dim - 1] = 0;
    if (dim == 2)
      subdivisions = {2, 1};
    b.set("Geometry", "Lower left corner", vec(lower));
    b.set("Geometry", "Upper right corner", vec(upper));
    b.set("Geometry", "Subdivisions", vec(subdivisions));

    const std::string top        = std::to_string(2 * dim - 1);
    const std::string bottom     = std::to_string(2 * dim - 2);
    std::string       conditions = bottom + ": fixed, " + top + ": contact";
    if (symmetric)
      {
        conditions += ", 0: normal fixed";
        if (dim == 3)
          conditions += ", 2: normal fixed";
      }
    b.set("Boundary conditions", "Conditions", conditions);

    // the point of first contact: the corner of the symmetric model, else
    // near the middle of the top
    const double        x0 = symmetric ? 0 : rounded(W * uniform(0.4, 0.6), 3);
    const double        R  = rounded(uniform(0.5, 2), 3);
    const double        depth = rounded(R * uniform(0.002, 0.01), 3);
    std::vector<double> displacement(dim, 0.);
    displacement[dim - 1] = -depth;
    if (punch)
      {
        // the punch |x - x0| <= half, y >= 0: d = max(-y, |x - x0| - half)
        const double half = rounded(W * 0.2137, 4);
        b.set("Obstacle", "Type", "distance");
        b.set("Obstacle",
              "Distance",
              "max(-y, abs(x - " + text(x0) + ") - " + text(half) + ")");
      }
    else
      {
        std::vector<double> centre(dim, x0);
        centre[dim - 1] = R;
        b.set("Obstacle", "Type", dim == 2 ? "cylinder" : "sphere");
        b.set("Obstacle", "Center", vec(centre));
        b.set("Obstacle", "Radius", text(R));
      }
    b.set("Obstacle", "Displacement", vec(displacement));
    // friction: the tangential loads are what the indentation causes
    friction(b, 1);
    if (b.scene.law == "given")
      {
        // a threshold of the order of the pressures: E depth / R
        const double E =
          std::strtod(get(b.scene, "Material", "Young's modulus")->c_str(),
                      nullptr);
        put(b.scene,
            "Friction",
            "Threshold",
            text(rounded(E * depth / R * uniform(0.05, 0.5))));
      }

    refinement(b, dim, dim == 2);
    b.set("Refinement", "Initial global refinement", dim == 2 ? "2" : "1");
    b.set("Geometry", "Pre-refinement steps", dim == 2 ? "3" : "2");
    b.set("Geometry", "Pre-refinement distance", text(rounded(0.1 * W)));
    b.set("Geometry", "Pre-refinement grading", "0.6");
    output(b);

    b.scene.name = std::string(punch    ? "2D flat punch" :
                               dim == 2 ? "2D cylinder" :
                                          "3D sphere") +
                   " indenter moved by " + text(depth) + " into a " +
                   (symmetric ? "symmetric " : "") +
                   "box with a fixed base, friction " + b.scene.law;
    return b.scene;
  }

  // ------------------------------------------------------------ two bodies
  // Two blocks, one on the other, as 'two blocks' numbers their boundary:
  // the lower block's bottom and top, the upper block's bottom and top, the
  // sides with the rectangle's ids on both blocks. The Gmsh blocks below
  // take the same ids.
  struct BlockIds
  {
    unsigned int lower_bottom, upper_top, lower_top, upper_bottom;
  };

  BlockIds
  block_ids(const unsigned int dim)
  {
    if (dim == 2)
      return {2, 3, 4, 5};
    return {4, 5, 6, 7};
  }

  // the pair across the cut, written either way: the upper block's bottom
  // the slave ('5: 4'), or the lower block's top ('4: 5'); the latter only
  // if not both ways
  void
  cut_pair(Builder &b, const BlockIds &ids, const bool both_ways = true)
  {
    b.scene.pair_turns            = both_ways;
    const bool        upper_slave = both_ways && chance(50);
    const std::string upper       = std::to_string(ids.upper_bottom);
    const std::string lower       = std::to_string(ids.lower_top);
    b.scene.pair = upper_slave ? upper + ": " + lower : lower + ": " + upper;
    b.scene.one_body_pair = upper + ": " + std::to_string(ids.upper_top);
    b.set("Boundary conditions", "Contact pairs", b.scene.pair);
  }

  // the upper body's own material (id 1), sometimes: E from half to three
  // times the lower body's
  std::string
  upper_material(Builder &b, const Common &c)
  {
    if (!chance(40))
      return "";
    const double factor = 0.5 + below(6) * 0.5;
    const double E      = rounded(c.E * factor, 3);
    const double nu     = below(9) * 0.05;
    b.set("Material", "Materials by id", "1: " + text(E) + ", " + text(nu, 2));
    return ", the upper body E = " + text(E);
  }

  // The Gmsh file of two blocks of triangles (2D), the lower one
  // [x0, x0 + w_l] x [y0, y0 + h_l], the upper one [xu, xu + w_u] x
  // [y0 + h_l, y0 + h_l + h_u] on it with nodes of its own on the cut: each
  // block nx x ny rectangles, each cut into two triangles along one of its
  // diagonals (the same in a block), listed counterclockwise from a random
  // corner, so that a triangle's edge on the cut is any of its three. The
  // edges of each side are a curve of
  // their own whose physical group is the side's boundary id (as BlockIds
  // numbers them, the sides 0 and 1 on both blocks); the triangles of the
  // lower block are in the physical surface 0, those of the upper block in
  // 1 (their material ids). Format 2.2, or 4.1 with its $Entities.
  struct TriangleBlock
  {
    double                             x0 = 0, y0 = 0, w = 1, h = 1;
    unsigned int                       nx = 1, ny = 1;
    bool                               other_diagonal = false;
    std::array<unsigned int, 4>        ids = {}; // left, right, bottom, top
    unsigned int                       material   = 0;
    unsigned int                       first_node = 1;
    std::vector<std::array<double, 2>> nodes;
    std::vector<std::array<unsigned int, 3>>                triangles;
    std::array<std::vector<std::array<unsigned int, 2>>, 4> sides;

    void
    build()
    {
      const auto tag = [this](const unsigned int i, const unsigned int j) {
        return first_node + j * (nx + 1) + i;
      };
      for (unsigned int j = 0; j <= ny; ++j)
        for (unsigned int i = 0; i <= nx; ++i)
          nodes.push_back(
            {{rounded(x0 + w * i / nx, 6), rounded(y0 + h * j / ny, 6)}});
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const unsigned int a = tag(i, j), b = tag(i + 1, j),
                               c = tag(i + 1, j + 1), d = tag(i, j + 1);
            if (other_diagonal)
              {
                triangles.push_back({{a, b, d}});
                triangles.push_back({{b, c, d}});
              }
            else
              {
                triangles.push_back({{a, b, c}});
                triangles.push_back({{a, c, d}});
              }
          }
      // each triangle from a random corner
      for (auto &t : triangles)
        {
          const unsigned int                shift = below(3);
          const std::array<unsigned int, 3> was   = t;
          for (unsigned int i = 0; i < 3; ++i)
            t[i] = was[(i + shift) % 3];
        }
      for (unsigned int j = 0; j < ny; ++j)
        {
          sides[0].push_back({{tag(0, j + 1), tag(0, j)}});
          sides[1].push_back({{tag(nx, j), tag(nx, j + 1)}});
        }
      for (unsigned int i = 0; i < nx; ++i)
        {
          sides[2].push_back({{tag(i, 0), tag(i + 1, 0)}});
          sides[3].push_back({{tag(i + 1, ny), tag(i, ny)}});
        }
    }
  };

  void
  write_triangle_blocks(const fs::path                   &file,
                        const std::vector<TriangleBlock> &blocks,
                        const bool                        format_41)
  {
    std::ofstream out(file, std::ios::binary);
    std::size_t   n_nodes = 0, n_elements = 0;
    for (const TriangleBlock &block : blocks)
      {
        n_nodes += block.nodes.size();
        n_elements += block.triangles.size();
        for (const auto &side : block.sides)
          n_elements += side.size();
      }
    const auto point = [](const std::array<double, 2> &x) {
      return text(x[0], 8) + ' ' + text(x[1], 8) + " 0";
    };
    std::size_t element = 0;
    if (!format_41)
      {
        out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
            << n_nodes << '\n';
        for (const TriangleBlock &block : blocks)
          for (std::size_t v = 0; v < block.nodes.size(); ++v)
            out << block.first_node + v << ' ' << point(block.nodes[v]) << '\n';
        out << "$EndNodes\n$Elements\n" << n_elements << '\n';
        // the curves are the elementary entities 1 to 8, the surfaces 1, 2
        for (std::size_t k = 0; k < blocks.size(); ++k)
          {
            const TriangleBlock &block = blocks[k];
            for (unsigned int s = 0; s < 4; ++s)
              for (const auto &edge : block.sides[s])
                out << ++element << " 1 2 " << block.ids[s] << ' '
                    << 4 * k + s + 1 << ' ' << edge[0] << ' ' << edge[1]
                    << '\n';
            for (const auto &t : block.triangles)
              out << ++element << " 2 2 " << block.material << ' ' << k + 1
                  << ' ' << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
          }
        out << "$EndElements\n";
        return;
      }
    // 4.1: no points; each side a curve, each block a surface bounded by
    // its four sides
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 "
        << 4 * blocks.size() << ' ' << blocks.size() << " 0\n";
    for (std::size_t k = 0; k < blocks.size(); ++k)
      {
        const TriangleBlock &block = blocks[k];
        const double         x1    = block.nodes.back()[0];
        const double         y1    = block.nodes.back()[1];
        const double         x0    = block.nodes.front()[0];
        const double         y0    = block.nodes.front()[1];
        // left, right, bottom, top: their boxes
        const std::array<std::array<double, 4>, 4> boxes = {
          {{{x0, y0, x0, y1}},
           {{x1, y0, x1, y1}},
           {{x0, y0, x1, y0}},
           {{x0, y1, x1, y1}}}};
        for (unsigned int s = 0; s < 4; ++s)
          out << 4 * k + s + 1 << ' ' << text(boxes[s][0], 8) << ' '
              << text(boxes[s][1], 8) << " 0 " << text(boxes[s][2], 8) << ' '
              << text(boxes[s][3], 8) << " 0 1 " << block.ids[s] << " 0\n";
      }
    for (std::size_t k = 0; k < blocks.size(); ++k)
      {
        const TriangleBlock &block = blocks[k];
        out << k + 1 << ' ' << point(block.nodes.front()) << ' '
            << point(block.nodes.back()) << " 1 " << block.material << " 4 "
            << 4 * k + 3 << ' ' << 4 * k + 2 << ' ' << -int(4 * k + 4) << ' '
            << -int(4 * k + 1) << '\n';
      }
    out << "$EndEntities\n$Nodes\n"
        << blocks.size() << ' ' << n_nodes << " 1 " << n_nodes << '\n';
    for (std::size_t k = 0; k < blocks.size(); ++k)
      {
        const TriangleBlock &block = blocks[k];
        out << "2 " << k + 1 << " 0 " << block.nodes.size() << '\n';
        for (std::size_t v = 0; v < block.nodes.size(); ++v)
          out << block.first_node + v << '\n';
        for (const auto &x : block.nodes)
          out << point(x) << '\n';
      }
    out << "$EndNodes\n$Elements\n"
        << 5 * blocks.size() << ' ' << n_elements << " 1 " << n_elements
        << '\n';
    for (std::size_t k = 0; k < blocks.size(); ++k)
      {
        const TriangleBlock &block = blocks[k];
        for (unsigned int s = 0; s < 4; ++s)
          {
            out << "1 " << 4 * k + s + 1 << " 1 " << block.sides[s].size()
                << '\n';
            for (const auto &edge : block.sides[s])
              out << ++element << ' ' << edge[0] << ' ' << edge[1] << '\n';
          }
      }
    for (std::size_t k = 0; k < blocks.size(); ++k)
      {
        const TriangleBlock &block = blocks[k];
        out << "2 " << k + 1 << " 2 " << block.triangles.size() << '\n';
        for (const auto &t : block.triangles)
          out << ++element << ' ' << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
      }
    out << "$EndElements\n";
  }

  // Two blocks, the upper one pressed onto the lower one by a traction on
  // its top (dim - 1 the vertical axis):
  //   slider     'two blocks', the lower block clamped or on the plane, a
  //              slider ('normal fixed') on one side or both of each
  //              tangential axis;
  //   stack      'two blocks' on the plane (the lower block's bottom
  //              'contact'), nothing else holds them;
  //   overhang   'two blocks' whose upper block reaches beyond the lower
  //              one (<Geometry/Upper overhang>), sometimes sliders;
  //   unloading  'two blocks', a load path of 2 or 4 steps up to t = 1 and
  //              back to zero at t = 2;
  //   mesh file  a Gmsh file of two blocks of triangles (2D) that the
  //              generator writes, the upper block narrower or wider than
  //              the lower one, format 2.2 or 4.1.
  // The pair is written either way; the meshes do not match across the
  // cut. The upper block's tangential load: up to p/2 where sliders hold
  // it, else at most 0.3 of what friction holds (none without friction)
  // and 0.3 of the tipping limit, half the contact's width over the lever
  // (the upper block's height on a clamped lower block, both blocks' on the
  // plane).
  enum class Blocks
  {
    slider,
    stack,
    overhang,
    unloading,
    mesh_file
  };

  Scene
  two_blocks(const fs::path &out, const unsigned int dim, const Blocks kind)
  {
    Builder b;
    b.scene.dim            = dim;
    const bool mesh        = kind == Blocks::mesh_file;
    b.scene.geometry       = mesh ? "mesh file" : "two blocks";
    const BlockIds     ids = block_ids(dim);
    const unsigned int v   = dim - 1; // the vertical axis
    b.set("Geometry", "Dimension", std::to_string(dim));
    b.set("Geometry", "Type", b.scene.geometry);
    const Common      c     = material(b);
    const std::string upper = upper_material(b, c);

    // the lower block on the plane or clamped, sliders on the sides
    const bool on_plane =
      kind == Blocks::stack ||
      (kind != Blocks::overhang && chance(kind == Blocks::slider ? 50 : 30));
    const bool sliders =
      kind == Blocks::slider ||
      (kind != Blocks::stack && chance(kind == Blocks::unloading ? 30 : 40));

    // the lower block's corner, its widths along the tangential axes and
    // the blocks' heights; the upper block's widths and the contact's
    std::vector<double> corner(dim), lower_width(dim - 1), upper_width(dim - 1),
      contact_width(dim - 1);
    for (unsigned int d = 0; d < dim; ++d)
      corner[d] = rounded(uniform(-2, 2), 3);
    for (unsigned int t = 0; t < dim - 1; ++t)
      lower_width[t] = rounded(uniform(1, dim == 2 ? 3 : 2), 3);
    const double height_factor = uniform(0.25, 0.5);
    const double lower_height  = rounded(height_factor * lower_width[0], 3);
    double       upper_height  = lower_height;
    double       cells         = 0; // of the coarse mesh
    bool         simplex       = false;
    std::string  shape;
    if (mesh)
      {
        b.scene.obstacle = "";
        upper_height     = rounded(lower_height * uniform(0.6, 1.6), 3);
        // the upper block 0.5 to 1.5 times as wide, narrower ones shifted
        // across the lower block's top, wider ones centred on it
        upper_width[0]     = rounded(lower_width[0] * uniform(0.5, 1.5), 3);
        contact_width[0]   = std::min(lower_width[0], upper_width[0]);
        const double room  = lower_width[0] - upper_width[0];
        const double shift = room > 0 ? rounded(room * uniform(0, 1), 3) : 0;
        const double x_upper =
          rounded(room > 0 ? corner[0] + shift : corner[0] + room / 2, 6);
        TriangleBlock lower_block;
        lower_block.x0             = corner[0];
        lower_block.y0             = corner[1];
        lower_block.w              = lower_width[0];
        lower_block.h              = lower_height;
        lower_block.ids            = {{0, 1, ids.lower_bottom, ids.lower_top}};
        lower_block.material       = 0;
        lower_block.nx             = 2 + below(4);
        lower_block.ny             = 1 + below(2);
        lower_block.other_diagonal = chance(50);
        lower_block.build();
        TriangleBlock upper_block;
        upper_block.x0             = x_upper;
        upper_block.y0             = rounded(corner[1] + lower_height, 6);
        upper_block.w              = upper_width[0];
        upper_block.h              = upper_height;
        upper_block.ids            = {{0, 1, ids.upper_bottom, ids.upper_top}};
        upper_block.material       = 1;
        const unsigned int nx      = 2 + below(4);
        upper_block.nx             = nx == lower_block.nx ? nx + 1 : nx;
        upper_block.ny             = 1 + below(2);
        upper_block.other_diagonal = chance(50);
        upper_block.first_node =
          static_cast<unsigned int>(lower_block.nodes.size()) + 1;
        upper_block.build();
        const bool          format_41 = chance(50);
        static unsigned int serial    = 0;
        const std::string   name =
          "meshes/two_blocks_" + std::to_string(serial++) + ".msh";
        write_triangle_blocks(out / name,
                              {lower_block, upper_block},
                              format_41);
        b.set("Geometry", "Mesh file", name);
        cells =
          double(lower_block.triangles.size() + upper_block.triangles.size());
        simplex = true;
        shape   = std::string("Gmsh ") + (format_41 ? "4.1" : "2.2") +
                " two blocks of triangles (" + std::to_string(lower_block.nx) +
                " x " + std::to_string(lower_block.ny) + " and " +
                std::to_string(upper_block.nx) + " x " +
                std::to_string(upper_block.ny) + " rectangles), the upper " +
                text(upper_width[0]) + " wide on the lower " +
                text(lower_width[0]);
      }
    else
      {
        // each block half the box's height, the upper one reaching beyond
        // the lower one by the overhang on each side
        double overhang = 0;
        if (kind == Blocks::overhang)
          overhang = rounded(lower_width[0] * uniform(0.05, 0.25), 3);
        std::vector<double> upper_corner = corner;
        for (unsigned int t = 0; t < dim - 1; ++t)
          {
            upper_corner[t]  = rounded(corner[t] + lower_width[t], 6);
            lower_width[t]   = upper_corner[t] - corner[t];
            upper_width[t]   = lower_width[t] + 2 * overhang;
            contact_width[t] = lower_width[t];
          }
        upper_corner[v] = rounded(corner[v] + 2 * lower_height, 6);
        b.set("Geometry", "Lower left corner", vec(corner));
        b.set("Geometry", "Upper right corner", vec(upper_corner));
        if (overhang > 0)
          b.set("Geometry", "Upper overhang", text(overhang));
        // the lower block 2-5 cells across (3D: 1-3), the upper block 1 or
        // 2 more or fewer; 1 or 2 cells high
        std::vector<double> lower_cells(dim), upper_cells(dim);
        for (unsigned int t = 0; t < dim - 1; ++t)
          {
            lower_cells[t] = (dim == 2 ? 2 : 1) + below(dim == 2 ? 4 : 3);
            const unsigned int step = 1 + below(2);
            upper_cells[t]          = chance(50) && lower_cells[t] > step ?
                                        lower_cells[t] - step :
                                        lower_cells[t] + step;
            // an upper block that reaches beyond: 3 cells or more, so that
            // its bottom has slave nodes across the lower block's top (with
            // one node or a line of them it would tip: exit 1)
            if (overhang > 0)
              upper_cells[t] = std::max(upper_cells[t], 3.);
          }
        lower_cells[v] = 1 + below(2);
        upper_cells[v] = 1 + below(2);
        b.set("Geometry", "Subdivisions", vec(lower_cells));
        b.set("Geometry", "Upper subdivisions", vec(upper_cells));
        double lower_n = 1, upper_n = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower_n *= lower_cells[d];
            upper_n *= upper_cells[d];
          }
        cells = lower_n + upper_n;
        // on triangles (tetrahedra), sometimes
        simplex = chance(25);
        if (simplex)
          {
            b.set("Geometry", "Cell type", "simplex");
            cells *= dim == 2 ? 2 : 5;
          }
        shape = std::string(dim == 2 ? "2D" : "3D") + " two blocks" +
                (simplex ? " of simplices" : "") + " (" + vec(lower_cells) +
                " and " + vec(upper_cells) + " cells)" +
                (overhang > 0 ? ", the upper one reaching " + text(overhang) +
                                  " beyond the lower one" :
                                "");
      }

    // sliders on the sides
    std::string conditions = std::to_string(ids.lower_bottom) +
                             (on_plane ? ": contact, " : ": fixed, ") +
                             std::to_string(ids.upper_top) + ": traction";
    std::string slider_names;
    if (sliders)
      for (unsigned int t = 0; t < dim - 1; ++t)
        {
          // one side or both
          const unsigned int which = below(3);
          for (unsigned int side = 0; side < 2; ++side)
            if (which == 2 || which == side)
              {
                conditions +=
                  ", " + std::to_string(2 * t + side) + ": normal fixed";
                slider_names += (slider_names.empty() ? "" : ", ") +
                                std::to_string(2 * t + side);
              }
        }
    b.set("Boundary conditions", "Conditions", conditions);
    cut_pair(b, ids);
    if (on_plane)
      {
        b.scene.obstacle = "plane";
        std::vector<double> normal(dim, 0.);
        normal[v] = 1;
        b.set("Foundation", "Point", vec(corner));
        b.set("Foundation", "Normal", vec(normal));
      }

    // the loads: the pressure p on the upper block's top and a shear q
    const double p        = rounded(c.E * c.strain);
    const double ratio    = friction(b, p);
    double       top_area = 1, contact_area = 1, narrowest = contact_width[0];
    for (unsigned int t = 0; t < dim - 1; ++t)
      {
        top_area *= upper_width[t];
        contact_area *= contact_width[t];
        narrowest = std::min(narrowest, contact_width[t]);
      }
    // what friction holds per unit pressure on the top: F, or g over p on
    // the contact's area
    const double holds =
      b.scene.law == "given" ? ratio * contact_area / top_area : ratio;
    const double lever = on_plane ? lower_height + upper_height : upper_height;
    const double shear_fraction =
      sliders ? 0.5 * uniform(0, 1) :
                0.3 * std::min(holds, narrowest / (2 * lever)) * uniform(0, 1);
    const double        q = rounded(shear_fraction * p);
    std::vector<double> traction(dim, 0.);
    traction[v] = -p;
    if (dim == 2 || chance(50))
      traction[0] = chance(50) ? q : -q;
    else
      {
        traction[0] = rounded(0.6 * q);
        traction[1] = rounded(-0.8 * q);
      }
    const std::string top = std::to_string(ids.upper_top);
    if (kind == Blocks::unloading)
      {
        // up to the full load at t = 1, back to none at t = 2
        std::string value = top + ":";
        for (unsigned int d = 0; d < dim; ++d)
          value +=
            std::string(d ? "; " : " ") +
            (traction[d] == 0 ? "0" :
                                text(traction[d]) + " * if(t <= 1, t, 2 - t)");
        b.set("Boundary conditions", "Tractions", value);
        const unsigned int steps = 2 + 2 * below(2);
        b.set("Load path", "Number of steps", std::to_string(steps));
        b.set("Load path", "End time", "2");
      }
    else
      b.set("Boundary conditions", "Tractions", tractions(top, traction));

    // a body force toward the lower block, sometimes (not on a path that
    // unloads): up to the pressure's load again
    double body_load = 0; // on the upper block per unit area of its top
    if (kind != Blocks::unloading && chance(20))
      {
        std::vector<double> f(dim, 0.);
        const double        magnitude =
          rounded(p / (lower_height + upper_height) * uniform(0.1, 1));
        f[v]      = -magnitude;
        body_load = magnitude * upper_height;
        b.set("Loads", "Body force", join(f, "; "));
      }

    // pulled off the lower block: exit 7, where nothing but the pair holds
    // the upper block upward (sliders hold it sideways only), or nothing
    // but the plane the two
    {
      std::vector<double> pulled = traction;
      pulled[v]                  = p * (body_load > 0 ? 3 : 1);
      b.scene.pull_off           = tractions(top, pulled);
      b.scene.pull_off_exits     = "7";
    }
    if (!sliders)
      {
        // along the first axis: 1.5 times what friction holds (coulomb: F
        // times the normal load; given: g times the contact's area), p/2
        // without friction
        std::vector<double> over(dim, 0.);
        over[v] = traction[v];
        over[0] =
          rounded(b.scene.law == "coulomb" ? 1.5 * ratio * (p + body_load) :
                  b.scene.law == "given"   ? 1.5 * holds * p :
                                             0.5 * p);
        b.scene.overload = tractions(top, over);
      }

    // a few hundred cells: about 2000 DoFs (3D: 1500) on the last cycle,
    // one cycle on simplices and on paths
    const double growth =
      refinement(b, dim, dim == 2 && !simplex && kind != Blocks::unloading);
    const double limit =
      dim == 2 ? (simplex ? 1200 : 600) : (simplex ? 1200 : 300);
    unsigned int global = 0;
    const double per    = dim == 2 ? 4 : 8;
    while (global < 3 && cells * per * growth <= limit)
      {
        cells *= per;
        ++global;
      }
    b.set("Refinement", "Initial global refinement", std::to_string(global));
    output(b);

    b.scene.name =
      shape + upper + ", the lower one " +
      (on_plane ? "on the plane" : "clamped") + ", the upper pressed by " +
      text(p) + ", shear " + text(q) +
      (sliders ? ", sliders on " + slider_names : ", held by the pair alone") +
      ", pair " + b.scene.pair + ", friction " + b.scene.law +
      (kind == Blocks::unloading ?
         ", loaded to t = 1 and unloaded to zero at t = 2 in " +
           *get(b.scene, "Load path", "Number of steps") + " steps" :
         "");
    return b.scene;
  }

  // Hertz's two cylinders ('two half discs'): the upper body pressed onto
  // the lower one, whose flat bottom is clamped, by a pressure on its flat
  // top; nothing else holds the upper body, the curved pair holds it
  // sideways, and there is no tangential load. The pair written either way;
  // the mesh graded toward the other body.
  Scene
  two_half_discs()
  {
    Builder b;
    b.scene.dim      = 2;
    b.scene.geometry = "two half discs";
    b.scene.obstacle = "";
    b.set("Geometry", "Type", "two half discs");
    const Common      c     = material(b);
    const std::string upper = upper_material(b, c);
    // the lower one's radius R2 from 0.3 R to 3 R, or R
    const double        R  = rounded(uniform(0.5, 2), 3);
    const double        R2 = chance(50) ? R : rounded(R * uniform(0.3, 3), 3);
    std::vector<double> centre(2);
    for (unsigned int d = 0; d < 2; ++d)
      centre[d] = rounded(uniform(-1, 1), 3);
    b.set("Geometry", "Center", vec(centre));
    b.set("Geometry", "Radius", text(R));
    b.set("Geometry", "Lower radius", text(R2));

    const double q = rounded(c.E * c.strain * 2);
    friction(b, q);
    b.set("Boundary conditions", "Conditions", "1: traction, 3: fixed");
    b.set("Boundary conditions", "Tractions", "1: 0; " + text(-q));
    b.scene.pair          = chance(50) ? "2: 0" : "0: 2";
    b.scene.pair_turns    = true;
    b.scene.one_body_pair = "0: 1";
    b.set("Boundary conditions", "Contact pairs", b.scene.pair);
    b.scene.pull_off       = "1: 0; " + text(q);
    b.scene.pull_off_exits = "7";

    const double growth = refinement(b, 2);
    b.set("Refinement", "Initial global refinement", growth > 2 ? "1" : "2");
    b.set("Geometry", "Pre-refinement steps", "3");
    b.set("Geometry", "Pre-refinement distance", text(rounded(0.15 * R)));
    b.set("Geometry", "Pre-refinement grading", "0.6");
    output(b);

    b.scene.name = "2D two half discs of radii " + text(R) + " (upper) and " +
                   text(R2) + upper + ", pressed by " + text(q) + ", pair " +
                   b.scene.pair + ", friction " + b.scene.law;
    return b.scene;
  }

  // ------------------------------------------------------------ shipped scenes
  Scene
  read_scene(const fs::path &file)
  {
    Scene         scene;
    std::ifstream in(file);
    std::string   line;
    bool          header = true;
    while (std::getline(in, line))
      {
        // the leading comment is the scene's, not the mutant's
        if (header && (line.empty() || line[0] == '#'))
          continue;
        header = false;
        scene.lines.push_back(line);
      }
    scene.name = "prm/" + file.filename().string();
    scene.dim =
      get(scene, "Geometry", "Dimension").value_or("2") == "3" ? 3 : 2;
    scene.geometry = get(scene, "Geometry", "Type").value_or("rectangle");
    // a scene whose contact is between bodies alone has no obstacle: its
    // entries are defaults that nothing reads
    const bool obstacle = get(scene, "Boundary conditions", "Conditions")
                            .value_or("")
                            .find("contact") != std::string::npos;
    scene.obstacle =
      obstacle ? get(scene, "Obstacle", "Type").value_or("plane") : "";
    scene.law = get(scene, "Friction", "Law").value_or("none");
    scene.pair =
      get(scene, "Boundary conditions", "Contact pairs").value_or("");
    if (!scene.pair.empty())
      scene.one_body_pair =
        scene.geometry == "two half discs" ? "0: 1" :
        scene.geometry == "two blocks" ? (scene.dim == 2 ? "5: 3" : "7: 5") :
                                         "";
    return scene;
  }

  // the shipped scene made cheap: one cycle, few refinements, no vtu
  Scene
  cheap(Scene scene)
  {
    auto at_most = [&scene](const std::string &section,
                            const std::string &entry,
                            const int          limit) {
      const auto value = get(scene, section, entry);
      if (value && std::atoi(value->c_str()) > limit)
        put(scene, section, entry, std::to_string(limit));
    };
    put(scene, "Refinement", "Number of cycles", "1");
    at_most("Refinement", "Initial global refinement", scene.dim == 2 ? 2 : 1);
    at_most("Geometry", "Pre-refinement steps", scene.dim == 2 ? 3 : 2);
    if (const auto s = get(scene, "Geometry", "Subdivisions"))
      {
        std::vector<double> n;
        double              cells = 1;
        for (const std::string &part : split(*s, ','))
          {
            n.push_back(std::atoi(part.c_str()));
            cells *= n.back();
          }
        if (cells > (scene.dim == 2 ? 256 : 64))
          {
            for (double &x : n)
              x = std::max(1., double(int(x / 2)));
            put(scene, "Geometry", "Subdivisions", vec(n));
          }
      }
    put(scene, "Output", "Write vtu", "false");
    put(scene, "Output", "Print timing", "false");
    put(scene, "Output", "Verbosity", "quiet");
    scene.name += " (made cheap)";
    return scene;
  }

  // ------------------------------------------------------------ mutations
  struct Mutant
  {
    std::vector<std::string> lines;
    std::string              exits;       // allowed exit statuses
    std::string              description; // what was done
    unsigned int             ranks          = 1;
    bool                     newline_at_end = true;
  };

  using Mutation = std::function<std::optional<Mutant>(const Scene &)>;

  struct Kind
  {
    std::string name;
    Mutation    mutate;
  };

  // the indices of the lines of a kind (set lines: optionally of one
  // subsection and of the given entries)
  std::vector<int>
  lines_of(const Scene &scene, const Line::Kind kind)
  {
    std::vector<int>        result;
    const std::vector<Line> lines = parse(scene.lines);
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].kind == kind)
        result.push_back(static_cast<int>(i));
    return result;
  }

  struct Target
  {
    std::string section, entry;
  };

  // the first of the candidates (in random order) that the scene sets
  std::optional<Target>
  some_entry(const Scene &scene, std::vector<Target> candidates)
  {
    std::vector<Target> present;
    for (const Target &t : candidates)
      if (get(scene, t.section, t.entry))
        present.push_back(t);
    if (present.empty())
      return std::nullopt;
    return pick(present);
  }

  Mutant
  with(const Scene       &scene,
       const std::string &exits,
       const std::string &description)
  {
    Mutant m;
    m.lines       = scene.lines;
    m.exits       = exits;
    m.description = description;
    return m;
  }

  Mutant
  with_value(const Scene       &scene,
             const Target      &t,
             const std::string &value,
             const std::string &exits,
             const std::string &what)
  {
    Scene changed = scene;
    put(changed, t.section, t.entry, value);
    const auto was = get(scene, t.section, t.entry);
    return with(changed,
                exits,
                what + ": <" + t.section + "/" + t.entry + "> = '" + value +
                  "' (" + (was ? "was '" + *was + "'" : "unset before") + ")");
  }

  bool
  letter(const char c)
  {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
  }

  // a name with one letter dropped, doubled or swapped with the next one
  // (letters only: a doubled space could be read as the same name)
  std::string
  misspelt(const std::string &name)
  {
    for (;;)
      {
        std::string  s = name;
        const size_t i = below(s.size());
        if (!letter(s[i]))
          continue;
        switch (below(3))
          {
            case 0:
              s.erase(i, 1);
              break;
            case 1:
              s.insert(i, 1, s[i]);
              break;
            default:
              if (i + 1 < s.size() && letter(s[i + 1]))
                std::swap(s[i], s[i + 1]);
          }
        if (s != name)
          return s;
      }
  }

  // a control character, shown escaped in the description
  std::pair<std::string, std::string>
  control_character()
  {
    static const std::vector<std::pair<std::string, std::string>> choices = {
      {std::string(1, '\0'), "\\0"},
      {"\x01", "\\x01"},
      {"\x08", "\\b"},
      {"\r", "\\r"},
      {"\x1b", "\\e"},
      {"\x7f", "\\x7f"}};
    return pick(choices);
  }

  const std::vector<Target> number_entries = {
    {"Material", "Young's modulus"},
    {"Material", "Poisson's ratio"},
    {"Geometry", "Radius"},
    {"Geometry", "Pre-refinement distance"},
    {"Geometry", "Pre-refinement grading"},
    {"Obstacle", "Radius"}};
  const std::vector<Target> integer_entries = {
    {"Refinement", "Number of cycles"},
    {"Refinement", "Initial global refinement"},
    {"Geometry", "Pre-refinement steps"},
    {"Geometry", "Dimension"}};

  std::vector<Kind>
  kinds(const fs::path &out)
  {
    std::vector<Kind> k;

    // ---- the syntax of the file: exit 4
    k.push_back({"misspelt entry", [](const Scene &s) -> std::optional<Mutant> {
                   const std::vector<int> sets  = lines_of(s, Line::set);
                   const int              i     = pick(sets);
                   const Line             line  = parse(s.lines)[i];
                   const std::string      wrong = misspelt(line.name);
                   Scene                  c     = s;
                   c.lines[i] = "  set " + wrong + " = " + line.value;
                   return with(c,
                               "4",
                               "the entry <" + line.section + "/" + line.name +
                                 "> misspelt as <" + wrong + ">");
                 }});
    k.push_back(
      {"misspelt subsection", [](const Scene &s) -> std::optional<Mutant> {
         const int         i     = pick(lines_of(s, Line::subsection));
         const Line        line  = parse(s.lines)[i];
         const std::string wrong = misspelt(line.name);
         Scene             c     = s;
         c.lines[i]              = "subsection " + wrong;
         return with(c,
                     "4",
                     "the subsection <" + line.name + "> misspelt as <" +
                       wrong + ">");
       }});
    k.push_back(
      {"set without '='", [](const Scene &s) -> std::optional<Mutant> {
         const int    i = pick(lines_of(s, Line::set));
         Scene        c = s;
         std::string &l = c.lines[i];
         l.erase(l.find('='), 1);
         return with(c, "4", "the '=' removed from '" + trim(s.lines[i]) + "'");
       }});
    k.push_back(
      {"subsection not closed", [](const Scene &s) -> std::optional<Mutant> {
         const std::vector<int> ends = lines_of(s, Line::end);
         const int              i    = chance(50) ? ends.back() : pick(ends);
         Scene                  c    = s;
         c.lines.erase(c.lines.begin() + i);
         return with(c,
                     "4",
                     "the 'end' of line " + std::to_string(i + 1) +
                       " (of the scene's text) removed");
       }});
    k.push_back({"end too many", [](const Scene &s) -> std::optional<Mutant> {
                   Scene     c = s;
                   const int i = below(c.lines.size() + 1);
                   c.lines.insert(c.lines.begin() + i, "end");
                   return with(c,
                               "4",
                               "an 'end' inserted before line " +
                                 std::to_string(i + 1));
                 }});
    k.push_back(
      {"control character in a name",
       [](const Scene &s) -> std::optional<Mutant> {
         const bool entry = chance(60);
         const int  i = pick(lines_of(s, entry ? Line::set : Line::subsection));
         const Line line               = parse(s.lines)[i];
         const auto [character, shown] = control_character();
         const size_t at               = 1 + below(line.name.size() - 1);
         std::string  name             = line.name;
         name.insert(at, character);
         Scene c = s;
         c.lines[i] =
           entry ? "  set " + name + " = " + line.value : "subsection " + name;
         std::string escaped = line.name;
         escaped.insert(at, shown);
         return with(c,
                     "4",
                     "a control character in the name <" + escaped + ">");
       }});
    k.push_back(
      {"line not understood", [](const Scene &s) -> std::optional<Mutant> {
         static const std::string letters =
           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
           "=:;,.!?$%&()[]{}<>/\\|+-*^~_'\" ";
         std::string        junk(1, letters[below(52)]);
         const unsigned int length = 3 + below(20);
         while (junk.size() < length)
           junk += letters[below(letters.size())];
         Scene     c = s;
         const int i = below(c.lines.size() + 1);
         c.lines.insert(c.lines.begin() + i, junk);
         return with(c,
                     "4",
                     "the line '" + junk + "' inserted before line " +
                       std::to_string(i + 1));
       }});
    k.push_back({"wrong type", [](const Scene &s) -> std::optional<Mutant> {
                   const bool integer = chance(40);
                   const auto t =
                     some_entry(s, integer ? integer_entries : number_entries);
                   if (!t)
                     return std::nullopt;
                   static const std::vector<std::string> words        = {"abc",
                                                                         "two",
                                                                         "1.5.2",
                                                                         "1e",
                                                                         "--1",
                                                                         "0x",
                                                                         "1,5",
                                                                         "true",
                                                                         "[1]",
                                                                         "",
                                                                         "1 2",
                                                                         "1e+"};
                   static const std::vector<std::string> non_integers = {
                     "2.5", "1e1", "two", "", "0x2"};
                   return with_value(s,
                                     *t,
                                     pick(integer ? non_integers : words),
                                     "5",
                                     "a value of the wrong type");
                 }});
    k.push_back(
      {"out of range", [](const Scene &s) -> std::optional<Mutant> {
         static const std::map<std::string, std::vector<std::string>> ranges = {
           {"Material/Young's modulus",
            {"0", "-1", "-1e-3", "1e-300", "1e300"}},
           {"Material/Poisson's ratio",
            {"0.5", "0.5000001", "0.7", "-1", "-1.2", "1e308"}},
           {"Refinement/Number of cycles", {"0", "31", "-2"}},
           {"Refinement/Initial global refinement", {"-1"}},
           {"Geometry/Dimension", {"1", "4", "0"}},
           {"Geometry/Pre-refinement grading", {"0", "1.5", "-0.5"}},
           {"Solver/Uzawa tolerance", {"10", "0"}}};
         std::vector<Target> candidates = {{"Material", "Young's modulus"},
                                           {"Material", "Poisson's ratio"},
                                           {"Refinement", "Number of cycles"},
                                           {"Refinement",
                                            "Initial global refinement"},
                                           {"Geometry", "Dimension"},
                                           {"Solver", "Uzawa tolerance"}};
         // the grading's range is checked where it has an effect: with
         // pre-refinement steps (without, it draws a warning)
         if (std::atoi(get(s, "Geometry", "Pre-refinement steps")
                         .value_or("0")
                         .c_str()) > 0)
           candidates.push_back({"Geometry", "Pre-refinement grading"});
         const Target t = pick(candidates);
         return with_value(s,
                           t,
                           pick(ranges.at(t.section + "/" + t.entry)),
                           "5,6",
                           "a number out of range");
       }});
    k.push_back(
      {"radius not positive", [](const Scene &s) -> std::optional<Mutant> {
         // the body's curved boundary must be 1e-6 or more; an
         // obstacle of radius 1e-9 is merely one that the body
         // does not reach
         if (s.geometry == "half disc" || s.geometry == "quarter disc")
           return with_value(s,
                             {"Geometry", "Radius"},
                             pick(std::vector<std::string>{"0", "-1", "1e-9"}),
                             "5,6",
                             "a radius not positive or too small");
         if (s.geometry == "two half discs")
           {
             const std::string entry = chance(50) ? "Radius" : "Lower radius";
             return with_value(s,
                               {"Geometry", entry},
                               pick(
                                 std::vector<std::string>{"0", "-1", "1e-9"}),
                               "5,6",
                               "a radius not positive or too small");
           }
         if (s.obstacle == "cylinder" || s.obstacle == "sphere")
           return with_value(s,
                             {"Obstacle", "Radius"},
                             pick(std::vector<std::string>{"0", "-1", "-1e-9"}),
                             "5,6",
                             "a radius not positive");
         return std::nullopt;
       }});
    k.push_back(
      {"subnormal number", [](const Scene &s) -> std::optional<Mutant> {
         static const std::vector<std::string> tiny = {"1e-320",
                                                       "4.9e-324",
                                                       "-2e-310"};
         const std::string                     x    = pick(tiny);
         if (chance(50))
           {
             const auto t = some_entry(s, number_entries);
             if (!t)
               return std::nullopt;
             return with_value(s, *t, x, "5", "a subnormal number");
           }
         // one component of a vector
         const auto t = some_entry(s,
                                   {{"Foundation", "Point"},
                                    {"Geometry", "Lower left corner"},
                                    {"Geometry", "Upper right corner"},
                                    {"Geometry", "Center"},
                                    {"Obstacle", "Center"}});
         if (!t)
           return std::nullopt;
         std::vector<std::string> parts =
           split(*get(s, t->section, t->entry), ',');
         parts[below(parts.size())] = x;
         std::string v;
         for (std::size_t i = 0; i < parts.size(); ++i)
           v += (i ? ", " : "") + trim(parts[i]);
         return with_value(s, *t, v, "5", "a subnormal component");
       }});
    k.push_back(
      {"not a finite number", [](const Scene &s) -> std::optional<Mutant> {
         static const std::vector<std::string> bad = {
           "0/0", "1/0", "-1/0", "sqrt(-1)", "log(0)", "1e308*10", "acos(2)"};
         const std::string x = pick(bad);
         // an expression entry that is in effect
         std::vector<std::function<std::optional<Mutant>()>> options;
         for (const std::string &id : ids_with(s, "traction"))
           options.push_back([&s, id, x]() -> std::optional<Mutant> {
             const std::string all =
               *get(s, "Boundary conditions", "Tractions");
             std::vector<std::string> items = split(all, ',');
             for (std::string &item : items)
               if (trim(item.substr(0, item.find(':'))) == id)
                 {
                   std::vector<std::string> c =
                     split(item.substr(item.find(':') + 1), ';');
                   c[below(c.size())] = " " + x;
                   item               = " " + id + ":";
                   for (std::size_t i = 0; i < c.size(); ++i)
                     item += (i ? "; " : " ") + trim(c[i]);
                 }
             std::string v;
             for (std::size_t i = 0; i < items.size(); ++i)
               v += (i ? ", " : "") + trim(items[i]);
             return with_value(s,
                               {"Boundary conditions", "Tractions"},
                               v,
                               "5",
                               "a traction that is not finite");
           });
         options.push_back([&s, x]() -> std::optional<Mutant> {
           std::vector<std::string> f(s.dim, "0");
           f[below(s.dim)] = x;
           std::string v;
           for (std::size_t i = 0; i < f.size(); ++i)
             v += (i ? "; " : "") + f[i];
           return with_value(s,
                             {"Loads", "Body force"},
                             v,
                             "5",
                             "a body force that is not finite");
         });
         if (s.law == "coulomb")
           options.push_back([&s, x]() -> std::optional<Mutant> {
             return with_value(s,
                               {"Friction", "Coefficient"},
                               x,
                               "5",
                               "a friction coefficient that is not finite");
           });
         if (s.law == "given")
           options.push_back([&s, x]() -> std::optional<Mutant> {
             return with_value(s,
                               {"Friction", "Threshold"},
                               x,
                               "5",
                               "a friction threshold that is not finite");
           });
         options.push_back([&s, x]() -> std::optional<Mutant> {
           return with_value(s,
                             {"Material", "Young's modulus"},
                             x,
                             "5",
                             "Young's modulus not a finite number");
         });
         return pick(options)();
       }});
    k.push_back(
      {"wrong number of components",
       [](const Scene &s) -> std::optional<Mutant> {
         // 3 values in a 2D scene, 2 in a 3D one, in an entry in effect
         std::vector<Target> candidates = {{"Loads", "Body force"}};
         if (s.obstacle == "plane")
           candidates.push_back({"Foundation", "Point"}),
             candidates.push_back({"Foundation", "Normal"});
         if (s.geometry == "rectangle" || s.geometry == "two blocks")
           candidates.push_back({"Geometry", "Lower left corner"}),
             candidates.push_back({"Geometry", "Upper right corner"}),
             candidates.push_back({"Geometry", "Subdivisions"});
         if (s.geometry == "two blocks")
           candidates.push_back({"Geometry", "Upper subdivisions"});
         if (s.geometry == "half disc" || s.geometry == "quarter disc" ||
             s.geometry == "two half discs")
           candidates.push_back({"Geometry", "Center"});
         if (s.obstacle == "cylinder" || s.obstacle == "sphere")
           candidates.push_back({"Obstacle", "Center"});
         if (get(s, "Obstacle", "Displacement"))
           candidates.push_back({"Obstacle", "Displacement"});
         const Target             t         = pick(candidates);
         const bool               body      = t.entry == "Body force";
         const char               separator = body ? ';' : ',';
         std::vector<std::string> parts =
           split(get(s, t.section, t.entry)
                   .value_or(body ? (s.dim == 2 ? "0; -1" : "0; 0; -1") :
                                    (s.dim == 2 ? "1, 1" : "1, 1, 1")),
                 separator);
         if (s.dim == 2)
           parts.push_back("1");
         else
           parts.pop_back();
         // not all zero: a zero body force of any length is no
         // body force (accepted)
         bool zero = true;
         for (const std::string &part : parts)
           zero = zero && trim(part) == "0";
         if (zero)
           parts.back() = "1";
         std::string value;
         for (std::size_t i = 0; i < parts.size(); ++i)
           value += (i ? std::string(1, separator) + " " : "") + trim(parts[i]);
         return with_value(s,
                           t,
                           value,
                           "5,6",
                           s.dim == 2 ? "3 values in a 2D scene" :
                                        "2 values in a 3D scene");
       }});
    k.push_back(
      {"2D default in a 3D scene", [](const Scene &s) -> std::optional<Mutant> {
         if (s.dim != 3)
           return std::nullopt;
         std::vector<std::pair<Target, std::string>> candidates;
         if (s.obstacle == "plane")
           candidates.push_back({{"Foundation", "Point"}, "0, 0"}),
             candidates.push_back({{"Foundation", "Normal"}, "0, 1"});
         if (s.geometry == "rectangle" || s.geometry == "two blocks")
           candidates.push_back({{"Geometry", "Lower left corner"}, "0, 0"}),
             candidates.push_back({{"Geometry", "Upper right corner"}, "1, 1"}),
             candidates.push_back({{"Geometry", "Subdivisions"}, "1, 1"});
         if (s.geometry == "half disc" || s.geometry == "two half discs")
           candidates.push_back({{"Geometry", "Center"}, "0, 0"});
         if (s.obstacle == "sphere")
           candidates.push_back({{"Obstacle", "Center"}, "0, 0"});
         if (candidates.empty())
           return std::nullopt;
         const auto &[t, value] = pick(candidates);
         return with_value(
           s, t, value, "5,6", "the 2D default written out in a 3D scene");
       }});
    k.push_back(
      {"huge subdivisions", [](const Scene &s) -> std::optional<Mutant> {
         if (s.geometry != "rectangle" && s.geometry != "two blocks")
           return std::nullopt;
         return with_value(s,
                           {"Geometry",
                            s.geometry == "two blocks" && chance(50) ?
                              "Upper subdivisions" :
                              "Subdivisions"},
                           s.dim == 2 ? "60000, 60000" : "60000, 60000, 60000",
                           "6",
                           "a mesh too large for the memory");
       }});
    k.push_back(
      {"refinement too deep", [](const Scene &s) -> std::optional<Mutant> {
         if (chance(50))
           return with_value(s,
                             {"Refinement", "Initial global refinement"},
                             pick(std::vector<std::string>{"25", "40", "1000"}),
                             "5,6",
                             "too many global refinements");
         Scene c = s;
         put(c, "Geometry", "Pre-refinement distance", "1e3");
         return with_value(c,
                           {"Geometry", "Pre-refinement steps"},
                           pick(std::vector<std::string>{"30", "60"}),
                           "5,6",
                           "too many pre-refinement steps (distance 1e3)");
       }});
    k.push_back(
      {"no such choice", [](const Scene &s) -> std::optional<Mutant> {
         static const std::vector<std::pair<Target, std::vector<std::string>>>
           choices = {
             {{"Friction", "Law"}, {"tresca", "Coulomb", "", "coulomb given"}},
             {{"Geometry", "Type"}, {"circle", "half-disc", "Rectangle"}},
             {{"Refinement", "Strategy"}, {"adaptive", "kelly,contact"}},
             {{"Obstacle", "Type"}, {"cone", "planes"}},
             {{"Output", "Verbosity"}, {"loud", "2"}},
             {{"Output", "Write vtu"}, {"maybe", "2", "truefalse"}},
             {{"Refinement", "Nested iteration"}, {"maybe", "nope"}},
             {{"Friction", "Initial threshold"}, {"one", "F"}}};
         const auto &[t, words] = pick(choices);
         return with_value(s, t, pick(words), "5", "a choice not offered");
       }});
    k.push_back(
      {"bad boundary conditions", [](const Scene &s) -> std::optional<Mutant> {
         const std::string conditions =
           *get(s, "Boundary conditions", "Conditions");
         switch (below(3))
           {
               case 0: {
                 std::vector<std::string> items = split(conditions, ',');
                 std::string             &item  = items[below(items.size())];
                 item = item.substr(0, item.find(':')) + ": " +
                        pick(std::vector<std::string>{
                          "slider", "clamped", "contactt", ""});
                 std::string v;
                 for (std::size_t i = 0; i < items.size(); ++i)
                   v += (i ? ", " : "") + trim(items[i]);
                 return with_value(s,
                                   {"Boundary conditions", "Conditions"},
                                   v,
                                   "5",
                                   "a condition that does not exist");
               }
             case 1:
               return with_value(s,
                                 {"Boundary conditions", "Conditions"},
                                 conditions + ", 9: fixed",
                                 "6",
                                 "a boundary id the geometry does not have");
               default: {
                 const std::string first =
                   trim(conditions.substr(0, conditions.find(':')));
                 return with_value(s,
                                   {"Boundary conditions", "Conditions"},
                                   conditions + ", " + first + ": free",
                                   "6",
                                   "a boundary id named twice");
               }
           }
       }});

    // ---- contact pairs that cannot be one: exit 6; turned round: exit 0
    const auto pair_sides = [](const Scene &s) {
      const auto colon = s.pair.find(':');
      return std::make_pair(trim(s.pair.substr(0, colon)),
                            trim(s.pair.substr(colon + 1)));
    };
    k.push_back({"pair id missing",
                 [pair_sides](const Scene &s) -> std::optional<Mutant> {
                   // no geometry of two bodies has the id 9
                   if (s.pair.empty())
                     return std::nullopt;
                   const auto [slave, master] = pair_sides(s);
                   return with_value(s,
                                     {"Boundary conditions", "Contact pairs"},
                                     chance(50) ? "9: " + master :
                                                  slave + ": 9",
                                     "6",
                                     "a pair id the geometry does not have");
                 }});
    k.push_back(
      {"pair on one body", [](const Scene &s) -> std::optional<Mutant> {
         if (s.one_body_pair.empty())
           return std::nullopt;
         return with_value(s,
                           {"Boundary conditions", "Contact pairs"},
                           s.one_body_pair,
                           "6",
                           "both ids of the pair on one body");
       }});
    k.push_back(
      {"pair id twice", [pair_sides](const Scene &s) -> std::optional<Mutant> {
         // the master in a second pair, with a free or loaded id
         // of the slave's body
         if (s.one_body_pair.empty())
           return std::nullopt;
         const std::string other =
           trim(s.one_body_pair.substr(s.one_body_pair.find(':') + 1));
         const auto [slave, master] = pair_sides(s);
         return with_value(s,
                           {"Boundary conditions", "Contact pairs"},
                           s.pair + ", " + other + ": " + master,
                           "6",
                           "an id in two pairs");
       }});
    k.push_back({"pair turned round",
                 [pair_sides](const Scene &s) -> std::optional<Mutant> {
                   // the generated scenes whose pair was drawn either way
                   // (a shipped path would cost its steps again)
                   if (!s.pair_turns)
                     return std::nullopt;
                   const auto [slave, master] = pair_sides(s);
                   return with_value(s,
                                     {"Boundary conditions", "Contact pairs"},
                                     master + ": " + slave,
                                     "0",
                                     "the pair's slave and master swapped");
                 }});

    // ---- mesh files: exit 3 (unreadable)
    k.push_back(
      {"mesh file missing", [](const Scene &s) -> std::optional<Mutant> {
         if (s.geometry != "mesh file")
           return std::nullopt;
         return with_value(
           s,
           {"Geometry", "Mesh file"},
           pick(std::vector<std::string>{"meshes/no_such.msh",
                                         "meshes",
                                         "meshes/half_disc.msh/x"}),
           "3",
           "a mesh file that cannot be read");
       }});
    k.push_back(
      {"mesh file garbled", [out](const Scene &s) -> std::optional<Mutant> {
         if (s.geometry != "mesh file" || s.dim != 2)
           return std::nullopt;
         std::vector<std::string> mesh;
         {
           std::ifstream in(out / "meshes" / "half_disc.msh");
           for (std::string l; std::getline(in, l);)
             mesh.push_back(l);
         }
         static unsigned int serial = 0;
         const std::string   name =
           "meshes/truncated_" + std::to_string(serial++) + ".msh";
         std::ofstream file(out / name);
         std::string   what;
         if (chance(50))
           {
             // its first k lines, k < all: $EndElements is missing
             const unsigned int k = below(mesh.size());
             for (unsigned int i = 0; i < k; ++i)
               file << mesh[i] << '\n';
             what = "half_disc.msh cut after line " + std::to_string(k);
           }
         else
           {
             // a count in the header of $Nodes or $Elements changed
             const std::string section = chance(50) ? "$Nodes" : "$Elements";
             for (std::size_t i = 0; i < mesh.size(); ++i)
               {
                 std::string l = mesh[i];
                 if (i > 0 && mesh[i - 1] == section)
                   {
                     std::vector<std::string> n     = split(l, ' ');
                     const unsigned int       which = below(n.size());
                     const long               old = std::atol(n[which].c_str());
                     const long               changed = pick(
                       std::vector<long>{old + 1, old - 1, old * 1000, -1});
                     what = "half_disc.msh with the count " +
                            std::to_string(which + 1) + " of " + section +
                            " changed from " + std::to_string(old) + " to " +
                            std::to_string(changed);
                     n[which] = std::to_string(changed);
                     l.clear();
                     for (std::size_t j = 0; j < n.size(); ++j)
                       l += (j ? " " : "") + n[j];
                   }
                 file << l << '\n';
               }
           }
         Scene c = s;
         put(c, "Geometry", "Mesh file", name);
         return with(c, "3", what);
       }});
    k.push_back({"mesh v2.2 count changed",
                 [out](const Scene &s) -> std::optional<Mutant> {
                   if (s.geometry != "mesh file" || s.dim != 2)
                     return std::nullopt;
                   std::ifstream       in(out / "meshes" / "half_disc_v22.msh");
                   static unsigned int serial = 0;
                   const std::string   name =
                     "meshes/v22_count_" + std::to_string(serial++) + ".msh";
                   std::ofstream     file(out / name);
                   const std::string section =
                     chance(50) ? "$Nodes" : "$Elements";
                   const long  delta = chance(50) ? 1 : -1;
                   std::string previous, what;
                   for (std::string l; std::getline(in, l); previous = l)
                     {
                       if (previous == section)
                         {
                           what = "half_disc_v22.msh with the count of " +
                                  section + " " + l + " changed by " +
                                  std::to_string(delta);
                           l = std::to_string(std::atol(l.c_str()) + delta);
                         }
                       file << l << '\n';
                     }
                   Scene c = s;
                   put(c, "Geometry", "Mesh file", name);
                   return with(c, "3", what);
                 }});

    // ---- loads the contact cannot hold: exit 7 (0 for a clamped body)
    k.push_back({"pulled off", [](const Scene &s) -> std::optional<Mutant> {
                   if (s.pull_off.empty())
                     return std::nullopt;
                   return with_value(s,
                                     {"Boundary conditions", "Tractions"},
                                     s.pull_off,
                                     s.pull_off_exits,
                                     "the normal load reversed");
                 }});
    k.push_back(
      {"tangential overload", [](const Scene &s) -> std::optional<Mutant> {
         if (s.overload.empty())
           return std::nullopt;
         return with_value(s,
                           {"Boundary conditions", "Tractions"},
                           s.overload,
                           "7",
                           "a tangential load 1.5 times what friction holds");
       }});

    // ---- changes that keep the scene valid: exit 0
    k.push_back({"number respelt", [](const Scene &s) -> std::optional<Mutant> {
                   const auto t =
                     some_entry(s,
                                {{"Material", "Young's modulus"},
                                 {"Material", "Poisson's ratio"},
                                 {"Foundation", "Point"},
                                 {"Foundation", "Normal"},
                                 {"Geometry", "Upper right corner"}});
                   if (!t)
                     return std::nullopt;
                   std::string v;
                   for (const std::string &part :
                        split(*get(s, t->section, t->entry), ','))
                     {
                       char buffer[64];
                       std::snprintf(buffer,
                                     sizeof buffer,
                                     chance(50) ? "%.6E" : "%+.8e",
                                     std::strtod(part.c_str(), nullptr));
                       v += (v.empty() ? "" : ",") + std::string(buffer);
                     }
                   return with_value(s, *t, v, "0", "the same number respelt");
                 }});
    k.push_back(
      {"tight tolerance", [](const Scene &s) -> std::optional<Mutant> {
         // a tolerance from 1e-13 to 1e-9 and r_rel from 1 to 1e4: the
         // solve converges, or stops at the round-off floor with a note
         // (exit 0 either way), on any number of ranks
         const double tolerance =
           rounded(power_of_ten(-13 + static_cast<int>(below(4))) *
                     uniform(1., 10.),
                   2);
         const double r =
           rounded(power_of_ten(static_cast<int>(below(4))) * uniform(1., 10.),
                   3);
         Scene c = s;
         put(c, "Solver", "Uzawa tolerance", text(tolerance));
         put(c, "Solver", "Augmentation parameter", text(r));
         return with(c,
                     "0",
                     "<Solver/Uzawa tolerance> = " + text(tolerance) +
                       ", <Solver/Augmentation parameter> = " + text(r));
       }});
    k.push_back({"layout changed", [](const Scene &s) -> std::optional<Mutant> {
                   // tabs, comments after values, blank lines, CRLF line ends
                   Scene                   c     = s;
                   const std::vector<Line> lines = parse(s.lines);
                   const bool              crlf  = chance(50);
                   for (std::size_t i = 0; i < lines.size(); ++i)
                     {
                       std::string &l = c.lines[i];
                       if (lines[i].kind == Line::set)
                         l =
                           "\t set\t" + lines[i].name +
                           "\t=  " + lines[i].value +
                           (chance(50) ? "   # comment, with = and : " : "\t");
                       if (crlf)
                         l += "\r";
                     }
                   c.lines.insert(c.lines.begin() + below(c.lines.size()),
                                  crlf ? "\r" : "  ");
                   return with(c,
                               "0",
                               std::string("tabs, comments and blank lines") +
                                 (crlf ? ", CRLF line ends" : ""));
                 }});
    k.push_back({"file truncated", [](const Scene &s) -> std::optional<Mutant> {
                   // cut anywhere: valid if the cut falls after the last entry
                   // the scene needs and between subsections
                   std::string all;
                   for (const std::string &l : s.lines)
                     all += l + '\n';
                   const std::size_t at = below(all.size());
                   Scene             c  = s;
                   c.lines              = split(all.substr(0, at), '\n');
                   if (!c.lines.empty() && c.lines.back().empty())
                     c.lines.pop_back();
                   Mutant m =
                     with(c,
                          "0,3,4,5,6,7",
                          "the file cut after byte " + std::to_string(at) +
                            " of " + std::to_string(all.size()));
                   m.newline_at_end = at > 0 && all[at - 1] == '\n';
                   return m;
                 }});
    return k;
  }

  // ------------------------------------------------------------ writing
  void
  write(const fs::path                 &file,
        const std::string              &header,
        const std::vector<std::string> &lines,
        const bool                      newline_at_end = true)
  {
    std::ofstream out(file, std::ios::binary);
    out << header;
    for (std::size_t i = 0; i < lines.size(); ++i)
      out << lines[i] << (i + 1 < lines.size() || newline_at_end ? "\n" : "");
  }
} // namespace

int
main(int argc, char **argv)
{
  if (argc != 3 && argc != 4)
    {
      std::cerr << "usage: random_scenes <source dir> <output dir> [seed]\n";
      return 2;
    }
  if (argc == 4)
    rng.seed(static_cast<std::uint32_t>(std::strtoul(argv[3], nullptr, 10)));
  const fs::path source = argv[1];
  const fs::path out    = argv[2];
  if (fs::exists(out))
    {
      std::cerr << "random_scenes: " << out << " exists\n";
      return 2;
    }
  fs::create_directories(out / "meshes");
  for (const char *mesh : {"half_disc.msh", "half_disc_v22.msh"})
    fs::copy_file(source / "prm" / "meshes" / mesh, out / "meshes" / mesh);

  std::ofstream manifest(out / "manifest.txt");

  // ---- the valid scenes: each family in turn (the friction laws take
  // turns too), 3 of them on 2 ranks (a 2-rank run costs two 1-rank ones:
  // mpirun's start): a 3D indenter with given friction, a 3D box with
  // Coulomb friction, a 2D half disc without friction
  const unsigned int                        n_valid  = 22;
  const std::vector<std::function<Scene()>> families = {
    [] { return box_on_plane(2); },
    [] { return disc_on_plane(2, false, false); },
    [] { return indenter(2, false); },
    [] { return box_on_plane(3); },
    [] { return disc_on_plane(2, true, false); },
    [] { return indenter(3, false); },
    [] { return box_on_plane(2); },
    [] { return disc_on_plane(3, false, false); },
    [] { return indenter(2, true); },
    [] { return disc_on_plane(2, false, true); }};
  std::vector<Scene> valid;
  for (unsigned int i = 0; i < n_valid; ++i)
    {
      Scene scene = families[i % families.size()]();
      scene.ranks = i % 8 == 5 ? 2 : 1;
      char name[32];
      std::snprintf(name, sizeof name, "valid_%02u", i);
      write(out / (std::string(name) + ".prm"),
            "# random_inputs " + std::string(name) + ": " + scene.name +
              " (valid: exit 0; tests/random_scenes.cc)\n",
            scene.lines);
      manifest << name << '\t' << scene.ranks << "\t0\t" << scene.name << '\n';
      valid.push_back(scene);
    }

  // ---- the valid scenes of two bodies, each family once or twice, 4 of
  // them on 2 ranks: the 3D two blocks with sliders, the 2D path that
  // unloads, the second Gmsh file of triangles (every rank reads it whole)
  // and the second pair of half discs
  const std::vector<std::pair<unsigned int, std::function<Scene()>>>
    pair_families = {
      {1, [&out] { return two_blocks(out, 2, Blocks::slider); }},
      {1, [&out] { return two_blocks(out, 2, Blocks::mesh_file); }},
      {1, [] { return two_half_discs(); }},
      {1, [&out] { return two_blocks(out, 2, Blocks::stack); }},
      {2, [&out] { return two_blocks(out, 3, Blocks::slider); }},
      {1, [&out] { return two_blocks(out, 2, Blocks::overhang); }},
      {2, [&out] { return two_blocks(out, 2, Blocks::unloading); }},
      {1, [&out] { return two_blocks(out, 3, Blocks::stack); }},
      {2, [&out] { return two_blocks(out, 2, Blocks::mesh_file); }},
      {2, [] { return two_half_discs(); }},
      {1, [&out] { return two_blocks(out, 3, Blocks::overhang); }},
      {1, [&out] { return two_blocks(out, 2, Blocks::slider); }},
      {1, [&out] { return two_blocks(out, 3, Blocks::unloading); }}};
  for (const auto &[ranks, family] : pair_families)
    {
      Scene scene = family();
      scene.ranks = ranks;
      char name[32];
      std::snprintf(name, sizeof name, "valid_%02zu", valid.size());
      write(out / (std::string(name) + ".prm"),
            "# random_inputs " + std::string(name) + ": " + scene.name +
              " (valid: exit 0; tests/random_scenes.cc)\n",
            scene.lines);
      manifest << name << '\t' << scene.ranks << "\t0\t" << scene.name << '\n';
      valid.push_back(scene);
    }

  // ---- the mutated inputs: each kind in turn, on a random base (a shipped
  // scene made cheap or a valid scene) to which it applies
  std::vector<fs::path> shipped_files;
  for (const auto &entry : fs::directory_iterator(source / "prm"))
    if (entry.path().extension() == ".prm")
      shipped_files.push_back(entry.path());
  std::sort(shipped_files.begin(), shipped_files.end());
  std::vector<Scene> bases;
  for (const fs::path &file : shipped_files)
    {
      Scene scene = cheap(read_scene(file));
      // their mesh files, copied next to the mutants
      if (const auto mesh = get(scene, "Geometry", "Mesh file"))
        if (!fs::exists(out / *mesh))
          fs::copy_file(file.parent_path() / *mesh, out / *mesh);
      bases.push_back(scene);
    }
  bases.insert(bases.end(), valid.begin(), valid.end());

  // the kinds that reach furthest into the program come first, in this
  // order: with more inputs than kinds, they are the ones that get a second
  // input
  std::vector<Kind>              mutation_kinds = kinds(out);
  const std::vector<std::string> first          = {"not a finite number",
                                                   "wrong number of components",
                                                   "mesh file garbled",
                                                   "tangential overload",
                                                   "file truncated",
                                                   "out of range",
                                                   "wrong type",
                                                   "subnormal number",
                                                   "pulled off",
                                                   "tight tolerance"};
  const auto                     rank           = [&first](const Kind &kind) {
    return std::find(first.begin(), first.end(), kind.name) - first.begin();
  };
  std::stable_sort(mutation_kinds.begin(),
                   mutation_kinds.end(),
                   [&rank](const Kind &a, const Kind &b) {
                     return rank(a) < rank(b);
                   });
  const unsigned int                             n_mutated = 34;
  std::set<std::pair<std::string, unsigned int>> used;
  for (unsigned int i = 0; i < n_mutated; ++i)
    {
      const Kind           &kind = mutation_kinds[i % mutation_kinds.size()];
      std::optional<Mutant> mutant;
      const Scene          *base = nullptr;
      for (unsigned int attempt = 0; attempt < 1000 && !mutant; ++attempt)
        {
          const unsigned int b = below(bases.size());
          // a kind applies to a base once
          if (!used.insert({kind.name, b}).second)
            continue;
          base   = &bases[b];
          mutant = kind.mutate(*base);
        }
      if (!mutant)
        {
          std::cerr << "random_scenes: no base for the mutation '" << kind.name
                    << "'\n";
          return 1;
        }
      // the first pulled-off body on 2 ranks: an error found after the mesh
      // is distributed, reported once, nothing written (a 2-rank error exit
      // costs 3 s of mpirun's tear-down: one is enough)
      if (kind.name == "pulled off" && i < mutation_kinds.size())
        mutant->ranks = 2;
      // a tight tolerance on 2 ranks too: where the round-off floor lies
      // depends on the partition, the exit status must not
      if (kind.name == "tight tolerance")
        mutant->ranks = 2;
      char name[32];
      std::snprintf(name, sizeof name, "mutated_%02u", i);
      const std::string description =
        kind.name + ": " + mutant->description + ", of " + base->name;
      // the description has no control characters: the mutation's own
      // are shown escaped
      write(out / (std::string(name) + ".prm"),
            "# random_inputs " + std::string(name) + ": " + description +
              " (allowed exit statuses: " + mutant->exits +
              "; tests/random_scenes.cc)\n",
            mutant->lines,
            mutant->newline_at_end);
      manifest << name << '\t' << mutant->ranks << '\t' << mutant->exits << '\t'
               << description << '\n';
    }
  return 0;
}
