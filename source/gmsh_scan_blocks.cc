// The scan of a Gmsh file (gmsh_scan.h, msh_scan.h): its $Nodes and
// $Elements blocks, each count against what follows and each element's
// nodes against $Nodes; the nodes' coordinates and the elements of
// dimension 2 and 3 are kept for the check of the cells' shapes.
#include "msh_scan.h"

namespace dualcontact
{
  namespace msh_scan
  {
    void
    MshScan::nodes_section()
    {
      const unsigned long start = line_number;
      next_in("$Nodes");
      const auto [n_blocks, total, min_tag, max_tag] =
        section_header("Nodes", "node");

      long long     n_read     = 0; // nodes in the blocks so far
      long long     n          = 0; // nodes in the current block
      unsigned long block_line = start;
      for (long long block = 1; block <= n_blocks; ++block)
        {
          const std::string in_block =
            format == 2 ? std::string("$Nodes section") :
                          "$Nodes block " + std::to_string(block);
          long long parametric = 0;
          if (format == 2)
            n = total;
          else
            {
              next_in("$Nodes");
              if (words.size() == 1 && block > 1 && format == 41 &&
                  !is_marker())
                throw fail("its $Nodes block " + std::to_string(block - 1) +
                           " (line " + std::to_string(block_line) +
                           ") announces " + plural(n, "node") + " but holds " +
                           std::to_string(n + count_lines_of(1)));
              if (words.size() != 4)
                throw fail(
                  (words.empty() || words[0] != "$EndNodes" ?
                     "the header of its " + in_block + " is not " +
                       (format == 41 ?
                          "'entityDim entityTag parametric numNodesInBlock'" :
                          "'entityTag entityDim parametric numNodesInBlock'") +
                       " (" + quoted() + ")" :
                     "its $Nodes section (line " + std::to_string(start) +
                       ") announces " + plural(n_blocks, "block") +
                       " but holds " + std::to_string(block - 1)));
              block_line                   = line_number;
              const std::size_t dim_word   = format == 41 ? 0 : 1;
              const long long   entity_dim = integer(
                dim_word, 0, 3, "the entity dimension of its " + in_block);
              integer(1 - dim_word,
                      -largest_int,
                      largest_int,
                      "the entity tag of its " + in_block);
              parametric =
                integer(2, 0, 1, "the parametric flag of its " + in_block);
              n = integer(3,
                          0,
                          largest_int,
                          "the number of nodes of its " + in_block);
              // deal.II's reader takes two parametric coordinates for every
              // node: right on a surface only
              if (parametric == 1 && entity_dim != 2 && n > 0)
                throw fail("its " + in_block + " (" + where() + "), on a " +
                           entity_kinds[entity_dim] +
                           ", has parametric coordinates, which deal.II's "
                           "reader misreads (it takes two for every node, "
                           "right on surfaces only); write the mesh without "
                           "them ('Mesh.SaveParametric = 0;', the default)");
            }
          const std::size_t n_coordinates = 3 + 2 * parametric;
          const std::string coordinates =
            parametric ? "5 (x y z u v)" : "3 (x y z)";

          if (format == 41)
            {
              // the node tags, one a line, then their coordinates
              for (long long i = 0; i < n; ++i)
                {
                  next_in("$Nodes");
                  if (words.empty())
                    throw fail("line " + std::to_string(line_number) +
                               ", where the tag of node " +
                               std::to_string(i + 1) + " of its " + in_block +
                               " should be, is empty");
                  if (words.size() != 1)
                    throw fail("its " + in_block + " (line " +
                               std::to_string(block_line) + ") announces " +
                               plural(n, "node") + " but holds " +
                               std::to_string(i));
                  contents.node_tags.push_back(
                    static_cast<int>(integer(0, 1, largest_int, [&] {
                      return "a node tag of its " + in_block;
                    })));
                }
              for (long long i = 0; i < n; ++i)
                {
                  next_in("$Nodes");
                  if (words.size() == 1 && !is_marker())
                    throw fail("its " + in_block + " (line " +
                               std::to_string(block_line) + ") announces " +
                               plural(n, "node") + " but holds " +
                               std::to_string(n + count_lines_of(1)));
                  const auto node = [&] {
                    return "node " +
                           std::to_string(
                             contents
                               .node_tags[contents.node_tags.size() - n + i]);
                  };
                  if (words.size() != n_coordinates)
                    throw fail("the coordinates of " + node() + " of its " +
                               in_block + " (" + quoted() + ") are " +
                               std::to_string(words.size()) + " numbers, not " +
                               coordinates);
                  std::array<double, 3> x;
                  for (std::size_t k = 0; k < n_coordinates; ++k)
                    {
                      const double value =
                        real(k, [&] { return "a coordinate of " + node(); });
                      if (k < 3)
                        x[k] = value;
                    }
                  contents.node_coordinates.push_back(x);
                }
            }
          else
            // a line per node: its tag and coordinates
            for (long long i = 0; i < n; ++i)
              {
                next_in("$Nodes");
                if (is_marker())
                  throw fail("its " + in_block + " (line " +
                             std::to_string(format == 2 ? start : block_line) +
                             ") announces " + plural(n, "node") +
                             " but holds " + std::to_string(i));
                if (words.size() != 1 + n_coordinates)
                  throw fail("line " + std::to_string(line_number) +
                             " of its " + in_block + " ('" + excerpt(line) +
                             "') is not a node tag and " + coordinates);
                const long long tag = integer(0, 1, largest_int, [&] {
                  return "a node tag of its " + in_block;
                });
                contents.node_tags.push_back(static_cast<int>(tag));
                std::array<double, 3> x;
                for (std::size_t k = 1; k <= n_coordinates; ++k)
                  {
                    const double value = real(k, [&] {
                      return "a coordinate of node " + std::to_string(tag);
                    });
                    if (k <= 3)
                      x[k - 1] = value;
                  }
                contents.node_coordinates.push_back(x);
              }
          n_read += n;
        }

      if (!next_nonblank())
        throw fail("it ends inside its $Nodes section");
      if (words[0] != "$EndNodes")
        {
          if (format == 2 && words.size() == 4)
            throw fail("its $Nodes section (line " + std::to_string(start) +
                       ") announces " + plural(total, "node") + " but holds " +
                       std::to_string(total + count_lines_of(4)));
          if (format == 41 && words.size() == 1 && !is_marker() && n_blocks > 0)
            throw fail("its $Nodes block " + std::to_string(n_blocks) +
                       " (line " + std::to_string(block_line) + ") announces " +
                       plural(n, "node") + " but holds " +
                       std::to_string(n + count_lines_of(1)));
          throw fail("its $Nodes section holds more than the " +
                     plural(n_blocks, "block") +
                     " it announces, or does not end with $EndNodes (" +
                     quoted() + ")");
        }
      if (n_read != total)
        throw fail("its $Nodes section (line " + std::to_string(start) +
                   ") announces " + plural(total, "node") +
                   " in all, but its blocks hold " + std::to_string(n_read));
      node_lookup(min_tag, max_tag);
    }

    void
    MshScan::node_lookup(const long long min_tag, const long long max_tag)
    {
      const std::vector<int> &node_tags = contents.node_tags;
      if (node_tags.empty())
        return;
      const auto [smallest, largest] =
        std::minmax_element(node_tags.begin(), node_tags.end());
      if (format == 41 && (*smallest != min_tag || *largest != max_tag))
        throw fail("its $Nodes header gives the node tags as " +
                   std::to_string(min_tag) + " to " + std::to_string(max_tag) +
                   ", but they run from " + std::to_string(*smallest) + " to " +
                   std::to_string(*largest));
      const auto twice = [&](const int tag) {
        return fail("its $Nodes section defines node " + std::to_string(tag) +
                    " twice");
      };
      if (static_cast<std::size_t>(*largest) <= 8 * node_tags.size() + 1024)
        {
          node_bitmap.assign(*largest + 1, false);
          for (const int tag : node_tags)
            {
              if (node_bitmap[tag])
                throw twice(tag);
              node_bitmap[tag] = true;
            }
        }
      else
        {
          node_set.reserve(node_tags.size());
          for (const int tag : node_tags)
            if (!node_set.insert(tag).second)
              throw twice(tag);
        }
    }

    bool
    MshScan::looks_like_element_block() const
    {
      if (words.size() != 4)
        return false;
      long long value[4];
      for (unsigned int k = 0; k < 4; ++k)
        {
          const auto result = std::from_chars(words[k].data(),
                                              words[k].data() + words[k].size(),
                                              value[k]);
          if (result.ec != std::errc() ||
              result.ptr != words[k].data() + words[k].size())
            return false;
        }
      const long long    dim  = value[format == 41 ? 0 : 1];
      const ElementType *type = element_type(value[2]);
      return type != nullptr && dim == type->dim;
    }

    void
    MshScan::element_nodes(const std::size_t first,
                           const long long   element,
                           const long long   type)
    {
      const auto name = [element] {
        return "element " + std::to_string(element);
      };
      // the cells (and in 3D the boundary faces) are kept for the check of
      // their shapes
      const bool kept =
        type == MshContents::triangle || type == MshContents::quad ||
        type == MshContents::tetrahedron || type == MshContents::hexahedron;
      MshContents::Element kept_element{static_cast<int>(type),
                                        static_cast<int>(element),
                                        {}};
      for (std::size_t k = first; k < words.size(); ++k)
        {
          const long long node = integer(k, 1, largest_int, [&] {
            return "a node of its " + name();
          });
          if (kept)
            kept_element.nodes[k - first] = static_cast<int>(node);
          if (!node_exists(node))
            throw fail("its " + name() + " (" + where() + ") refers to node " +
                       std::to_string(node) + ", which $Nodes does not define");
          for (std::size_t j = first; j < k; ++j)
            if (words[j] == words[k])
              throw fail("its " + name() + " (" + where() + ") lists node " +
                         std::to_string(node) + " twice");
        }
      if (kept)
        contents.elements.push_back(kept_element);
    }

    void
    MshScan::elements_section()
    {
      const unsigned long start = line_number;
      next_in("$Elements");
      const auto [n_blocks, total, min_tag, max_tag] =
        section_header("Elements", "element");

      long long          n_read = 0, n = 0;
      long long          smallest = largest_int, largest = 0;
      const ElementType *type       = nullptr;
      unsigned long      block_line = start;
      for (long long block = 1; block <= n_blocks; ++block)
        {
          const std::string in_block =
            "$Elements block " + std::to_string(block);
          if (format == 2)
            {
              n = total;
              // a line per element: tag, type, tags, nodes
              for (long long i = 0; i < n; ++i)
                {
                  next_in("$Elements");
                  if (is_marker())
                    throw fail("its $Elements section (line " +
                               std::to_string(start) + ") announces " +
                               plural(n, "element") + " but holds " +
                               std::to_string(i));
                  if (words.size() < 3)
                    throw fail("line " + std::to_string(line_number) +
                               " of its $Elements section ('" + excerpt(line) +
                               "') is not 'tag type numTags tags... "
                               "nodes...'");
                  const long long tag = integer(
                    0, 1, largest_int, "an element tag of its $Elements");
                  const auto name = [tag] {
                    return "element " + std::to_string(tag);
                  };
                  const long long number = integer(1, 1, largest_int, [&] {
                    return "the type of its " + name();
                  });
                  const long long n_tags = integer(2, 0, words.size() - 3, [&] {
                    return "the number of tags of its " + name();
                  });
                  if (n_tags > 0)
                    integer(3, 0, largest_int, [&] {
                      return "the physical tag of its " + name();
                    });
                  for (long long k = 1; k < n_tags; ++k)
                    integer(3 + k, -largest_int, largest_int, [&] {
                      return "a tag of its " + name();
                    });
                  const std::size_t n_nodes = words.size() - 3 - n_tags;
                  type                      = element_type(number);
                  if (type != nullptr && n_nodes != type->nodes)
                    throw fail("its " + name() + " (" + where() + ") lists " +
                               plural(n_nodes, "node") + ", but a " +
                               type->name + " has " +
                               std::to_string(type->nodes));
                  element_nodes(3 + n_tags, tag, number);
                  ++contents.n_elements[number];
                  smallest = std::min(smallest, tag);
                  largest  = std::max(largest, tag);
                }
              n_read += n;
              continue;
            }

          next_in("$Elements");
          if (words.size() != 4 && type != nullptr && !is_marker() &&
              words.size() == 1 + type->nodes)
            throw fail("its $Elements block " + std::to_string(block - 1) +
                       " (line " + std::to_string(block_line) + ") announces " +
                       plural(n, "element") + " but holds " +
                       std::to_string(n + count_lines_of(1 + type->nodes)));
          if (words.size() != 4)
            throw fail(
              (words.empty() || words[0] != "$EndElements" ?
                 "the header of its " + in_block + " is not " +
                   (format == 41 ?
                      "'entityDim entityTag elementType numElementsInBlock'" :
                      "'entityTag entityDim elementType "
                      "numElementsInBlock'") +
                   " (" + quoted() + ")" :
                 "its $Elements section (line " + std::to_string(start) +
                   ") announces " + plural(n_blocks, "block") + " but holds " +
                   std::to_string(block - 1)));
          block_line                 = line_number;
          const std::size_t dim_word = format == 41 ? 0 : 1;
          const long long   entity_dim =
            integer(dim_word, 0, 3, "the entity dimension of its " + in_block);
          const long long entity = integer(1 - dim_word,
                                           -largest_int,
                                           largest_int,
                                           "the entity tag of its " + in_block);
          const long long number =
            integer(2, 1, largest_int, "the element type of its " + in_block);
          n    = integer(3,
                      0,
                      largest_int,
                      "the number of elements of its " + in_block);
          type = element_type(number);
          if (type != nullptr && type->dim != entity_dim)
            throw fail("its " + in_block + " (" + where() + ") holds " +
                       type->name + " elements but belongs to a " +
                       entity_kinds[entity_dim]);
          // deal.II's reader takes the boundary id from $Entities
          if (has_entities && entities[entity_dim].count(entity) == 0)
            throw fail("its " + in_block + " (" + where() + ") belongs to " +
                       entity_kinds[entity_dim] + " " + std::to_string(entity) +
                       ", which $Entities does not define" +
                       (partitioned ? " (the reader takes the boundary ids "
                                      "from $Entities, not from "
                                      "$PartitionedEntities: write the mesh "
                                      "unpartitioned)" :
                                      ""));
          for (long long i = 0; i < n; ++i)
            {
              next_in("$Elements");
              if (type == nullptr ? words.size() < 2 :
                                    words.size() != 1 + type->nodes)
                {
                  if (words.empty() || is_marker() ||
                      (block < n_blocks && looks_like_element_block()))
                    throw fail("its " + in_block + " (line " +
                               std::to_string(block_line) + ") announces " +
                               plural(n, "element") + " but holds " +
                               std::to_string(i));
                  if (type == nullptr)
                    throw fail("line " + std::to_string(line_number) +
                               " of its " + in_block + " ('" + excerpt(line) +
                               "') is not an element tag and its nodes");
                  throw fail(
                    "its element " + excerpt(words[0]) + " (" + where() +
                    ") lists " + plural(words.size() - 1, "node") + ", but a " +
                    type->name + " has " + std::to_string(type->nodes));
                }
              const long long tag = integer(0, 1, largest_int, [&] {
                return "an element tag of its " + in_block;
              });
              element_nodes(1, tag, number);
              smallest = std::min(smallest, tag);
              largest  = std::max(largest, tag);
            }
          contents.n_elements[number] += n;
          n_read += n;
        }

      if (!next_nonblank())
        throw fail("it ends inside its $Elements section");
      if (words[0] != "$EndElements")
        {
          if (format == 2 && !is_marker())
            {
              unsigned long more = 0;
              while (!is_marker())
                {
                  ++more;
                  if (!next_nonblank())
                    break;
                }
              throw fail("its $Elements section (line " +
                         std::to_string(start) + ") announces " +
                         plural(total, "element") + " but holds " +
                         std::to_string(total + more));
            }
          if (format != 2 && type != nullptr && n_blocks > 0 &&
              words.size() == 1 + type->nodes)
            throw fail("its $Elements block " + std::to_string(n_blocks) +
                       " (line " + std::to_string(block_line) + ") announces " +
                       plural(n, "element") + " but holds " +
                       std::to_string(n + count_lines_of(1 + type->nodes)));
          throw fail("its $Elements section holds more than the " +
                     plural(n_blocks, "block") +
                     " it announces, or does not end with $EndElements (" +
                     quoted() + ")");
        }
      if (n_read != total)
        throw fail("its $Elements section (line " + std::to_string(start) +
                   ") announces " + plural(total, "element") +
                   " in all, but its blocks hold " + std::to_string(n_read));
      if (format == 41 && n_read > 0 &&
          (smallest != min_tag || largest != max_tag))
        throw fail("its $Elements header gives the element tags as " +
                   std::to_string(min_tag) + " to " + std::to_string(max_tag) +
                   ", but they run from " + std::to_string(smallest) + " to " +
                   std::to_string(largest));
    }
  } // namespace msh_scan
} // namespace dualcontact
