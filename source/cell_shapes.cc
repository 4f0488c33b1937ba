// The shapes of the cells of a Gmsh file (cell_shapes.h): zero measures,
// tangled quadrilaterals and hexahedra, cells folded over their neighbours.
#include <dualcontact/cell_shapes.h>
#include <dualcontact/input_error.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace dualcontact
{
  namespace
  {
    // a measure at most this share of its scale (the longest edge's
    // square or cube, the product of the edges at a corner) is zero: Gmsh
    // writes 16 digits, so a cell whose nodes are on one line (plane) has
    // some 1e-16 of it
    constexpr double zero_measure = 1e-10;

    using Vector = std::array<double, 3>;

    Vector
    minus(const Vector &a, const Vector &b)
    {
      return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
    }

    double
    norm(const Vector &a)
    {
      return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    }

    /** det(a, b) of the x and y components (2D), or det(a, b, c) (3D). */
    double
    determinant(const unsigned int dim,
                const Vector      &a,
                const Vector      &b,
                const Vector      &c)
    {
      if (dim == 2)
        return a[0] * b[1] - a[1] * b[0];
      return a[0] * (b[1] * c[2] - b[2] * c[1]) -
             a[1] * (b[0] * c[2] - b[2] * c[0]) +
             a[2] * (b[0] * c[1] - b[1] * c[0]);
    }

    /**
     * A kind of cell in Gmsh's numbering of its nodes: each face (edge in
     * 2D) as a cycle of its nodes that turns outwards for a cell of
     * positive measure; for a quadrilateral (hexahedron), the node next to
     * each corner along each direction of the unit square (cube) and
     * whether the corner is at the far end of that direction.
     */
    struct Shape
    {
      bool                                     simplex;
      unsigned int                             n_nodes;
      std::vector<std::vector<unsigned int>>   faces;
      std::vector<std::array<unsigned int, 3>> next;
      std::vector<std::array<bool, 3>>         far;
    };

    /** A quadrilateral's (dim = 2) or hexahedron's Shape. */
    Shape
    hypercube(const unsigned int dim)
    {
      Shape shape{false, dim == 2 ? 4u : 8u, {}, {}, {}};
      shape.faces = dim == 2 ?
                      std::vector<std::vector<unsigned int>>{{0, 1},
                                                             {1, 2},
                                                             {2, 3},
                                                             {3, 0}} :
                      std::vector<std::vector<unsigned int>>{{0, 3, 2, 1},
                                                             {4, 5, 6, 7},
                                                             {0, 1, 5, 4},
                                                             {3, 7, 6, 2},
                                                             {0, 4, 7, 3},
                                                             {1, 2, 6, 5}};
      // the corners' positions in the unit square (cube)
      const std::vector<std::array<bool, 3>> corners = {{{0, 0, 0}},
                                                        {{1, 0, 0}},
                                                        {{1, 1, 0}},
                                                        {{0, 1, 0}},
                                                        {{0, 0, 1}},
                                                        {{1, 0, 1}},
                                                        {{1, 1, 1}},
                                                        {{0, 1, 1}}};
      for (unsigned int v = 0; v < shape.n_nodes; ++v)
        {
          std::array<unsigned int, 3> next{};
          for (unsigned int d = 0; d < dim; ++d)
            {
              std::array<bool, 3> other = corners[v];
              other[d]                  = !other[d];
              next[d] = std::find(corners.begin(), corners.end(), other) -
                        corners.begin();
            }
          shape.next.push_back(next);
          shape.far.push_back(corners[v]);
        }
      return shape;
    }

    const Shape &
    shape_of(const int type)
    {
      static const Shape triangle{true, 3, {{0, 1}, {1, 2}, {2, 0}}, {}, {}};
      static const Shape tetrahedron{
        true, 4, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}, {}, {}};
      static const Shape quad = hypercube(2), hexahedron = hypercube(3);
      return type == MshContents::triangle    ? triangle :
             type == MshContents::quad        ? quad :
             type == MshContents::tetrahedron ? tetrahedron :
                                                hexahedron;
    }

    /** "node 4" or "nodes 4 9 12". */
    std::string
    nodes_text(const std::vector<int> &nodes)
    {
      std::string text = nodes.size() == 1 ? "node" : "nodes";
      for (const int node : nodes)
        text += " " + std::to_string(node);
      return text;
    }

    /** A face of a cell, for the search of the cells that share it. */
    struct Face
    {
      std::array<int, 4> key;  // its node tags, sorted (0 after the last)
      unsigned int       cell; // the cell's index among the cells
      unsigned char      face; // the face's number in the cell
      bool               turn; // how the cell turns it (turn_of())
    };

    /**
     * Which way a cycle of node tags turns, as a bit that two cycles of the
     * same nodes share if and only if they turn the same way: an edge
     * (a, b) by a < b; a triangle or quadrilateral, rotated to begin at its
     * smallest tag, by whether the next tag is smaller than the last.
     */
    bool
    turn_of(const std::array<int, 4> &cycle, const std::size_t n)
    {
      if (n == 2)
        return cycle[0] < cycle[1];
      const std::size_t first =
        std::min_element(cycle.begin(), cycle.begin() + n) - cycle.begin();
      return cycle[(first + 1) % n] < cycle[(first + n - 1) % n];
    }

    /**
     * The index of a node tag in MshContents::node_tags: by tag if the tags
     * are dense (as Gmsh numbers them), else hashed.
     */
    class NodeIndex
    {
    public:
      explicit NodeIndex(const std::vector<int> &tags)
      {
        const int largest =
          tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
        is_dense = static_cast<std::size_t>(largest) <= 8 * tags.size() + 1024;
        if (is_dense)
          {
            dense.assign(largest + 1, 0);
            for (unsigned int i = 0; i < tags.size(); ++i)
              dense[tags[i]] = i;
          }
        else
          for (unsigned int i = 0; i < tags.size(); ++i)
            sparse.emplace(tags[i], i);
      }

      unsigned int
      operator()(const int tag) const
      {
        return is_dense ? dense[tag] : sparse.at(tag);
      }

    private:
      bool                                  is_dense;
      std::vector<unsigned int>             dense;
      std::unordered_map<int, unsigned int> sparse;
    };

    /** The InputError that refuses `element` of `file` for `defect`. */
    InputError
    refusal(const MshContents::Element &element,
            const std::string          &defect,
            const std::string          &file)
    {
      const Shape     &kind = shape_of(element.type);
      std::vector<int> nodes(element.nodes.begin(),
                             element.nodes.begin() + kind.n_nodes);
      return InputError("The mesh " + file + " is damaged: element " +
                          std::to_string(element.tag) + " (" +
                          nodes_text(nodes) + ") " + defect +
                          "; mesh the body again or move the element's nodes "
                          "(doc/meshes.md).",
                        exit_cannot_read_file);
    }

    /**
     * Whether the simplex with corners `x` has negative measure; throws the
     * refusal of `element` if its measure is zero.
     */
    bool
    simplex_is_negative(const MshContents::Element  &element,
                        const std::array<Vector, 8> &x,
                        const unsigned int           dim,
                        const std::string           &file)
    {
      const Shape &kind    = shape_of(element.type);
      double       longest = 0.;
      for (unsigned int a = 0; a < kind.n_nodes; ++a)
        for (unsigned int b = a + 1; b < kind.n_nodes; ++b)
          longest = std::max(longest, norm(minus(x[b], x[a])));
      const double measure = determinant(dim,
                                         minus(x[1], x[0]),
                                         minus(x[2], x[0]),
                                         minus(x[dim], x[0]));
      if (!(std::abs(measure) > zero_measure * std::pow(longest, dim)))
        throw refusal(element,
                      dim == 2 ? "has zero area: its nodes are on one line" :
                                 "has zero volume: its nodes are on one plane",
                      file);
      return measure < 0.;
    }

    /**
     * The refusal of a quadrilateral (hexahedron) whose corners' Jacobian
     * signs `sign` (1, -1, or 0 for zero) are not one sign with fewer than
     * half of them zero.
     */
    InputError
    hypercube_refusal(const MshContents::Element &element,
                      const std::array<int, 8>   &sign,
                      const unsigned int          n_positive,
                      const unsigned int          n_negative,
                      const unsigned int          dim,
                      const std::string          &file)
    {
      const Shape &kind = shape_of(element.type);
      // the nodes of the corners where the sign is s
      const auto at = [&](const int s) {
        std::vector<int> nodes;
        for (unsigned int v = 0; v < kind.n_nodes; ++v)
          if (sign[v] == s)
            nodes.push_back(element.nodes[v]);
        return nodes;
      };
      if (n_positive + n_negative == 0)
        return refusal(element,
                       dim == 2 ? "has zero area: its nodes are on one line" :
                                  "has zero volume: its edges are in one plane "
                                  "at every corner",
                       file);
      if (n_positive * n_negative == 0)
        return refusal(element,
                       "is degenerate at " + nodes_text(at(0)) +
                         ": its Jacobian is zero there, at half its "
                         "corners or more (an edge of zero length, or " +
                         (dim == 2 ? "two edges in line" :
                                     "three edges in one plane") +
                         " at each)",
                       file);
      // the fewer corners first; of as many, those without the first node
      const int some =
        n_positive < n_negative || (n_positive == n_negative && sign[0] == -1) ?
          1 :
          -1;
      return refusal(element,
                     "is tangled: its Jacobian at " + nodes_text(at(some)) +
                       " has the opposite sign of that at " +
                       nodes_text(at(-some)) +
                       (dim == 2 ? " (it crosses itself or is not convex)" :
                                   " (it is turned inside out at a "
                                   "corner)"),
                     file);
    }

    /**
     * Whether the quadrilateral (hexahedron) with corners `x` has negative
     * measure; throws the refusal of `element` if it is degenerate or
     * tangled.
     */
    bool
    hypercube_is_negative(const MshContents::Element  &element,
                          const std::array<Vector, 8> &x,
                          const unsigned int           dim,
                          const std::string           &file)
    {
      const Shape &kind = shape_of(element.type);
      // the Jacobian at a corner: the determinant of the edges that leave
      // it along the directions of the unit square (cube); its sign, or 0
      std::array<int, 8> sign{};
      unsigned int       n_positive = 0, n_negative = 0;
      for (unsigned int v = 0; v < kind.n_nodes; ++v)
        {
          std::array<Vector, 3> edges{};
          double                lengths = 1.;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int w = kind.next[v][d];
              edges[d] = kind.far[v][d] ? minus(x[v], x[w]) : minus(x[w], x[v]);
              lengths *= norm(edges[d]);
            }
          const double jacobian =
            determinant(dim, edges[0], edges[1], edges[2]);
          sign[v] = !(std::abs(jacobian) > zero_measure * lengths) ? 0 :
                    jacobian > 0.                                  ? 1 :
                                                                     -1;
          n_positive += sign[v] == 1;
          n_negative += sign[v] == -1;
        }
      // A corner where the Jacobian is zero (a straight angle of a
      // quadrilateral, three edges of a hexahedron in one plane: Gmsh
      // makes them where a curved boundary meets a plane of symmetry)
      // leaves the map one-to-one, its Jacobian positive inside, if the
      // others agree in sign: in 2D the Jacobian is affine in the unit
      // square's coordinates. Half the corners or more at zero (a quadri-
      // lateral with an edge of zero length) is no such cell.
      const unsigned int n_zero = kind.n_nodes - n_positive - n_negative;
      if (2 * n_zero >= kind.n_nodes || n_positive * n_negative > 0)
        throw hypercube_refusal(
          element, sign, n_positive, n_negative, dim, file);
      return n_negative > 0;
    }

    /**
     * Each cell on its own: its measure, and the sign of its Jacobian at
     * its corners, which gives the cell's orientation (true: negative).
     * Throws the refusal of the first cell of zero measure or tangled.
     */
    std::vector<bool>
    orientations(const std::vector<const MshContents::Element *> &cells,
                 const MshContents                               &contents,
                 const NodeIndex                                 &index,
                 const unsigned int                               dim,
                 const std::string                               &file)
    {
      std::vector<bool> negative(cells.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const MshContents::Element &element = *cells[c];
          const Shape                &kind    = shape_of(element.type);
          std::array<Vector, 8>       x;
          for (unsigned int v = 0; v < kind.n_nodes; ++v)
            {
              x[v] = contents.node_coordinates[index(element.nodes[v])];
              if (dim == 2)
                x[v][2] = 0.;
            }
          negative[c] = kind.simplex ?
                          simplex_is_negative(element, x, dim, file) :
                          hypercube_is_negative(element, x, dim, file);
        }
      return negative;
    }

    /**
     * The faces, each turned the way its cell, turned by its own sign,
     * sees it (a face of two cells that lie on its two sides is seen turned
     * opposite ways), sorted by their smallest node (a counting sort,
     * linear), then each node's few faces by their nodes and cells.
     */
    std::vector<Face>
    sorted_faces(const std::vector<const MshContents::Element *> &cells,
                 const std::vector<bool>                         &negative,
                 const NodeIndex                                 &index,
                 const std::size_t                                n_tags)
    {
      std::vector<Face> faces;
      faces.reserve(cells.size() * shape_of(cells[0]->type).faces.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const MshContents::Element &element = *cells[c];
          const Shape                &kind    = shape_of(element.type);
          for (unsigned int f = 0; f < kind.faces.size(); ++f)
            {
              const std::size_t  n = kind.faces[f].size();
              std::array<int, 4> cycle{};
              for (std::size_t k = 0; k < n; ++k)
                cycle[k] = element.nodes[kind.faces[f][k]];
              Face face{cycle,
                        c,
                        static_cast<unsigned char>(f),
                        turn_of(cycle, n) != negative[c]};
              std::sort(face.key.begin(), face.key.begin() + n);
              faces.push_back(face);
            }
        }
      std::vector<std::size_t> first(n_tags + 1, 0);
      for (const Face &face : faces)
        ++first[index(face.key[0]) + 1];
      std::partial_sum(first.begin(), first.end(), first.begin());
      {
        std::vector<Face>        by_node(faces.size());
        std::vector<std::size_t> next(first.begin(), first.end() - 1);
        for (const Face &face : faces)
          by_node[next[index(face.key[0])]++] = face;
        faces.swap(by_node);
      }
      for (std::size_t i = 0; i + 1 < first.size(); ++i)
        std::sort(faces.begin() + first[i],
                  faces.begin() + first[i + 1],
                  [](const Face &a, const Face &b) {
                    return a.key < b.key || (a.key == b.key && a.cell < b.cell);
                  });
      return faces;
    }

    constexpr unsigned int none = std::numeric_limits<unsigned int>::max();

    /**
     * A cell's faces shared with other cells, those it shares with a cell
     * on the same side (or with two cells), and of these the one whose
     * other cell comes first.
     */
    struct Neighbours
    {
      unsigned int  shared      = 0;
      unsigned int  overlapping = 0;
      unsigned int  other       = none;
      unsigned char face        = 0;
      std::size_t   n_sharing   = 0; // the cells of that face
    };

    /** The Neighbours of each cell, from the sorted_faces(). */
    std::vector<Neighbours>
    neighbours_of(const std::vector<Face> &faces, const std::size_t n_cells)
    {
      std::vector<Neighbours> neighbours(n_cells);
      for (std::size_t begin = 0; begin < faces.size();)
        {
          std::size_t end = begin + 1;
          while (end < faces.size() && faces[end].key == faces[begin].key)
            ++end;
          const std::size_t n_sharing = end - begin;
          for (std::size_t i = begin; n_sharing > 1 && i < end; ++i)
            {
              Neighbours &n = neighbours[faces[i].cell];
              ++n.shared;
              // the other cells, those on the same side of the face
              unsigned int other = none;
              for (std::size_t j = begin; j < end; ++j)
                if (j != i && (n_sharing > 2 || faces[j].turn == faces[i].turn))
                  other = std::min(other, faces[j].cell);
              if (other == none)
                continue;
              ++n.overlapping;
              if (other < n.other)
                {
                  n.other     = other;
                  n.face      = faces[i].face;
                  n.n_sharing = n_sharing;
                }
            }
          begin = end;
        }
      return neighbours;
    }

    /**
     * The cell that disagrees with the largest share of its neighbours,
     * then with the most of them, then the first in the file; `none` if no
     * cell overlaps another.
     */
    unsigned int
    most_folded(const std::vector<Neighbours> &neighbours)
    {
      unsigned int folded = none;
      for (unsigned int c = 0; c < neighbours.size(); ++c)
        {
          const Neighbours &n = neighbours[c];
          if (n.overlapping == 0)
            continue;
          if (folded == none)
            {
              folded = c;
              continue;
            }
          const Neighbours &m       = neighbours[folded];
          const auto        share_c = std::uint64_t(n.overlapping) * m.shared;
          const auto        share_f = std::uint64_t(m.overlapping) * n.shared;
          if (share_c > share_f ||
              (share_c == share_f && n.overlapping > m.overlapping))
            folded = c;
        }
      return folded;
    }

    /** The refusal of the cell `folded`, with its Neighbours `n`. */
    InputError
    folded_refusal(const std::vector<const MshContents::Element *> &cells,
                   const unsigned int                               folded,
                   const Neighbours                                &n,
                   const unsigned int                               dim,
                   const std::string                               &file)
    {
      const MshContents::Element &element = *cells[folded];
      std::vector<int>            face_nodes;
      for (const unsigned int v : shape_of(element.type).faces[n.face])
        face_nodes.push_back(element.nodes[v]);
      const std::string face = dim == 2 ? "edge" : "face";
      return refusal(element,
                     "is folded: it overlaps its neighbours (" +
                       (n.n_sharing > 2 ?
                          "its " + face + ", " + nodes_text(face_nodes) +
                            ", is " + (dim == 2 ? "an " : "a ") + face +
                            " of " + std::to_string(n.n_sharing) + " elements" :
                          "it and element " +
                            std::to_string(cells[n.other]->tag) +
                            " lie on the same side of their common " + face +
                            ", " + nodes_text(face_nodes)) +
                       ")",
                     file);
    }
  } // namespace

  void
  check_cell_shapes(const MshContents &contents,
                    const unsigned int dim,
                    const std::string &file)
  {
    const int simplex_type =
      dim == 2 ? MshContents::triangle : MshContents::tetrahedron;
    const int hypercube_type =
      dim == 2 ? MshContents::quad : MshContents::hexahedron;
    std::vector<const MshContents::Element *> cells;
    for (const MshContents::Element &element : contents.elements)
      if (element.type == simplex_type || element.type == hypercube_type)
        cells.push_back(&element);
    if (cells.empty())
      return;

    const NodeIndex         index(contents.node_tags);
    const std::vector<bool> negative =
      orientations(cells, contents, index, dim, file);
    const std::vector<Neighbours> neighbours = neighbours_of(
      sorted_faces(cells, negative, index, contents.node_tags.size()),
      cells.size());
    const unsigned int folded = most_folded(neighbours);
    if (folded != none)
      throw folded_refusal(cells, folded, neighbours[folded], dim, file);
  }
} // namespace dualcontact
