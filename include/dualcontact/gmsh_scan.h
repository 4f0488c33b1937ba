// The scan of a Gmsh ASCII mesh file before deal.II's reader sees it: every
// count, tag and line of the sections that reader takes is checked, so that
// a damaged file ends with one message instead of a crash or a hang inside
// GridIn (deal.II checks them only in debug mode).
#ifndef dualcontact_gmsh_scan_h
#define dualcontact_gmsh_scan_h

#include <array>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace dualcontact
{
  /**
   * What the elements of a Gmsh file are, counted by Gmsh's type number;
   * its nodes, and its elements of dimension 2 and 3, for the check of the
   * cells' shapes (cell_shapes.h).
   */
  struct MshContents
  {
    double                       version = 0.;
    std::map<int, unsigned long> n_elements; // type -> count
    static constexpr int line = 1, triangle = 2, quad = 3, tetrahedron = 4,
                         hexahedron = 5, prism = 6, pyramid = 7, point = 15;
    unsigned long
    count(const int type) const
    {
      const auto it = n_elements.find(type);
      return it == n_elements.end() ? 0 : it->second;
    }

    /** The nodes in the order of the file: their tags and (x, y, z). */
    std::vector<int>                   node_tags;
    std::vector<std::array<double, 3>> node_coordinates;

    /** An element of the file: its Gmsh type, tag and nodes (their tags). */
    struct Element
    {
      int                type;
      int                tag;
      std::array<int, 8> nodes; // the first 3 (triangle), 4 or 8
    };
    /**
     * The triangles, quadrilaterals, tetrahedra and hexahedra in the order
     * of the file: the cells, and in 3D the boundary faces too.
     */
    std::vector<Element> elements;
  };

  /**
   * Scan a Gmsh ASCII file (format 2.x, 4.0 or 4.1): its version, the
   * count of each element type, its nodes and its elements of dimension 2
   * and 3, after checking that deal.II's reader can take it. `file` names the
   * file in messages. Throws InputError (exit status 3, cannot read the file)
   * with one sentence that says what is wrong and where (the line) otherwise.
   */
  MshContents
  scan_msh(std::istream &in, const std::string &file);

  /** "1 node", "3 nodes", "2 entities": a count with its noun, for messages. */
  inline std::string
  plural(const unsigned long n, const std::string &noun)
  {
    if (n == 1)
      return "1 " + noun;
    // "entity": "entities"
    if (!noun.empty() && noun.back() == 'y')
      return std::to_string(n) + " " + noun.substr(0, noun.size() - 1) + "ies";
    return std::to_string(n) + " " + noun + "s";
  }
} // namespace dualcontact

#endif
