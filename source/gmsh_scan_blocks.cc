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
      SectionScan section{start, n_blocks, total, min_tag, max_tag};
      section.block_line = start;
      for (long long block = 1; block <= n_blocks; ++block)
        {
          const std::string in_block =
            format == 2 ? std::string("$Nodes section") :
                          "$Nodes block " + std::to_string(block);
          long long parametric = 0;
          if (format == 2)
            section.n = total;
          else
            parametric = node_block_header(section, block, in_block);
          const std::size_t n_coordinates = 3 + 2 * parametric;
          const std::string coordinates =
            parametric ? "5 (x y z u v)" : "3 (x y z)";
          if (format == 41)
            node_block_41(section, in_block, n_coordinates, coordinates);
          else
            node_lines(section, in_block, n_coordinates, coordinates);
          section.n_read += section.n;
        }
      end_of_nodes(section);
      node_lookup(min_tag, max_tag);
    }

    long long
    MshScan::node_block_header(SectionScan       &section,
                               const long long    block,
                               const std::string &in_block)
    {
      const long long n = section.n;
      next_in("$Nodes");
      if (words.size() == 1 && block > 1 && format == 41 && !is_marker())
        throw fail("its $Nodes block " + std::to_string(block - 1) + " (line " +
                   std::to_string(section.block_line) + ") announces " +
                   plural(n, "node") + " but holds " +
                   std::to_string(n + count_lines_of(1)));
      if (words.size() != 4)
        throw fail((words.empty() || words[0] != "$EndNodes" ?
                      "the header of its " + in_block + " is not " +
                        (format == 41 ?
                           "'entityDim entityTag parametric numNodesInBlock'" :
                           "'entityTag entityDim parametric numNodesInBlock'") +
                        " (" + quoted() + ")" :
                      "its $Nodes section (line " +
                        std::to_string(section.start) + ") announces " +
                        plural(section.n_blocks, "block") + " but holds " +
                        std::to_string(block - 1)));
      section.block_line         = line_number;
      const std::size_t dim_word = format == 41 ? 0 : 1;
      const long long   entity_dim =
        integer(dim_word, 0, 3, "the entity dimension of its " + in_block);
      integer(1 - dim_word,
              -largest_int,
              largest_int,
              "the entity tag of its " + in_block);
      const long long parametric =
        integer(2, 0, 1, "the parametric flag of its " + in_block);
      section.n =
        integer(3, 0, largest_int, "the number of nodes of its " + in_block);
      // deal.II's reader takes two parametric coordinates for every
      // node: right on a surface only
      if (parametric == 1 && entity_dim != 2 && section.n > 0)
        throw fail("its " + in_block + " (" + where() + "), on a " +
                   entity_kinds[entity_dim] +
                   ", has parametric coordinates, which deal.II's "
                   "reader misreads (it takes two for every node, "
                   "right on surfaces only); write the mesh without "
                   "them ('Mesh.SaveParametric = 0;', the default)");
      return parametric;
    }

    void
    MshScan::node_block_41(const SectionScan &section,
                           const std::string &in_block,
                           const std::size_t  n_coordinates,
                           const std::string &coordinates)
    {
      const long long n = section.n;
      // the node tags, one a line, then their coordinates
      for (long long i = 0; i < n; ++i)
        {
          next_in("$Nodes");
          if (words.empty())
            throw fail("line " + std::to_string(line_number) +
                       ", where the tag of node " + std::to_string(i + 1) +
                       " of its " + in_block + " should be, is empty");
          if (words.size() != 1)
            throw fail("its " + in_block + " (line " +
                       std::to_string(section.block_line) + ") announces " +
                       plural(n, "node") + " but holds " + std::to_string(i));
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
                       std::to_string(section.block_line) + ") announces " +
                       plural(n, "node") + " but holds " +
                       std::to_string(n + count_lines_of(1)));
          const auto node = [&] {
            return "node " +
                   std::to_string(
                     contents.node_tags[contents.node_tags.size() - n + i]);
          };
          if (words.size() != n_coordinates)
            throw fail("the coordinates of " + node() + " of its " + in_block +
                       " (" + quoted() + ") are " +
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

    void
    MshScan::node_lines(const SectionScan &section,
                        const std::string &in_block,
                        const std::size_t  n_coordinates,
                        const std::string &coordinates)
    {
      const long long n = section.n;
      // a line per node: its tag and coordinates
      for (long long i = 0; i < n; ++i)
        {
          next_in("$Nodes");
          if (is_marker())
            throw fail(
              "its " + in_block + " (line " +
              std::to_string(format == 2 ? section.start : section.block_line) +
              ") announces " + plural(n, "node") + " but holds " +
              std::to_string(i));
          if (words.size() != 1 + n_coordinates)
            throw fail("line " + std::to_string(line_number) + " of its " +
                       in_block + " ('" + excerpt(line) +
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
    }

    void
    MshScan::end_of_nodes(const SectionScan &section)
    {
      if (!next_nonblank())
        throw fail("it ends inside its $Nodes section");
      if (words[0] != "$EndNodes")
        {
          if (format == 2 && words.size() == 4)
            throw fail("its $Nodes section (line " +
                       std::to_string(section.start) + ") announces " +
                       plural(section.total, "node") + " but holds " +
                       std::to_string(section.total + count_lines_of(4)));
          if (format == 41 && words.size() == 1 && !is_marker() &&
              section.n_blocks > 0)
            throw fail("its $Nodes block " + std::to_string(section.n_blocks) +
                       " (line " + std::to_string(section.block_line) +
                       ") announces " + plural(section.n, "node") +
                       " but holds " +
                       std::to_string(section.n + count_lines_of(1)));
          throw fail("its $Nodes section holds more than the " +
                     plural(section.n_blocks, "block") +
                     " it announces, or does not end with $EndNodes (" +
                     quoted() + ")");
        }
      if (section.n_read != section.total)
        throw fail("its $Nodes section (line " + std::to_string(section.start) +
                   ") announces " + plural(section.total, "node") +
                   " in all, but its blocks hold " +
                   std::to_string(section.n_read));
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
      SectionScan section{start, n_blocks, total, min_tag, max_tag};
      section.block_line = start;
      for (long long block = 1; block <= n_blocks; ++block)
        {
          if (format == 2)
            {
              section.n = total;
              element_lines_2(section);
              section.n_read += section.n;
              continue;
            }
          const std::string in_block =
            "$Elements block " + std::to_string(block);
          const long long number =
            element_block_header(section, block, in_block);
          element_lines(section, block, in_block, number);
          contents.n_elements[number] += section.n;
          section.n_read += section.n;
        }
      end_of_elements(section);
    }

    void
    MshScan::element_lines_2(SectionScan &section)
    {
      const long long n = section.n;
      // a line per element: tag, type, tags, nodes
      for (long long i = 0; i < n; ++i)
        {
          next_in("$Elements");
          if (is_marker())
            throw fail("its $Elements section (line " +
                       std::to_string(section.start) + ") announces " +
                       plural(n, "element") + " but holds " +
                       std::to_string(i));
          if (words.size() < 3)
            throw fail("line " + std::to_string(line_number) +
                       " of its $Elements section ('" + excerpt(line) +
                       "') is not 'tag type numTags tags... "
                       "nodes...'");
          const long long tag =
            integer(0, 1, largest_int, "an element tag of its $Elements");
          const auto name = [tag] { return "element " + std::to_string(tag); };
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
          section.type              = element_type(number);
          if (section.type != nullptr && n_nodes != section.type->nodes)
            throw fail("its " + name() + " (" + where() + ") lists " +
                       plural(n_nodes, "node") + ", but a " +
                       section.type->name + " has " +
                       std::to_string(section.type->nodes));
          element_nodes(3 + n_tags, tag, number);
          ++contents.n_elements[number];
          section.smallest = std::min(section.smallest, tag);
          section.largest  = std::max(section.largest, tag);
        }
    }

    long long
    MshScan::element_block_header(SectionScan       &section,
                                  const long long    block,
                                  const std::string &in_block)
    {
      const ElementType *type = section.type;
      next_in("$Elements");
      if (words.size() != 4 && type != nullptr && !is_marker() &&
          words.size() == 1 + type->nodes)
        throw fail("its $Elements block " + std::to_string(block - 1) +
                   " (line " + std::to_string(section.block_line) +
                   ") announces " + plural(section.n, "element") +
                   " but holds " +
                   std::to_string(section.n + count_lines_of(1 + type->nodes)));
      if (words.size() != 4)
        throw fail(
          (words.empty() || words[0] != "$EndElements" ?
             "the header of its " + in_block + " is not " +
               (format == 41 ?
                  "'entityDim entityTag elementType numElementsInBlock'" :
                  "'entityTag entityDim elementType "
                  "numElementsInBlock'") +
               " (" + quoted() + ")" :
             "its $Elements section (line " + std::to_string(section.start) +
               ") announces " + plural(section.n_blocks, "block") +
               " but holds " + std::to_string(block - 1)));
      section.block_line         = line_number;
      const std::size_t dim_word = format == 41 ? 0 : 1;
      const long long   entity_dim =
        integer(dim_word, 0, 3, "the entity dimension of its " + in_block);
      const long long entity = integer(1 - dim_word,
                                       -largest_int,
                                       largest_int,
                                       "the entity tag of its " + in_block);
      const long long number =
        integer(2, 1, largest_int, "the element type of its " + in_block);
      section.n =
        integer(3, 0, largest_int, "the number of elements of its " + in_block);
      section.type = type = element_type(number);
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
      return number;
    }

    void
    MshScan::element_lines(SectionScan       &section,
                           const long long    block,
                           const std::string &in_block,
                           const long long    number)
    {
      const ElementType *type = section.type;
      const long long    n    = section.n;
      for (long long i = 0; i < n; ++i)
        {
          next_in("$Elements");
          if (type == nullptr ? words.size() < 2 :
                                words.size() != 1 + type->nodes)
            {
              if (words.empty() || is_marker() ||
                  (block < section.n_blocks && looks_like_element_block()))
                throw fail("its " + in_block + " (line " +
                           std::to_string(section.block_line) + ") announces " +
                           plural(n, "element") + " but holds " +
                           std::to_string(i));
              if (type == nullptr)
                throw fail("line " + std::to_string(line_number) + " of its " +
                           in_block + " ('" + excerpt(line) +
                           "') is not an element tag and its nodes");
              throw fail("its element " + excerpt(words[0]) + " (" + where() +
                         ") lists " + plural(words.size() - 1, "node") +
                         ", but a " + type->name + " has " +
                         std::to_string(type->nodes));
            }
          const long long tag = integer(0, 1, largest_int, [&] {
            return "an element tag of its " + in_block;
          });
          element_nodes(1, tag, number);
          section.smallest = std::min(section.smallest, tag);
          section.largest  = std::max(section.largest, tag);
        }
    }

    void
    MshScan::end_of_elements(const SectionScan &section)
    {
      const ElementType *type = section.type;
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
                         std::to_string(section.start) + ") announces " +
                         plural(section.total, "element") + " but holds " +
                         std::to_string(section.total + more));
            }
          if (format != 2 && type != nullptr && section.n_blocks > 0 &&
              words.size() == 1 + type->nodes)
            throw fail(
              "its $Elements block " + std::to_string(section.n_blocks) +
              " (line " + std::to_string(section.block_line) + ") announces " +
              plural(section.n, "element") + " but holds " +
              std::to_string(section.n + count_lines_of(1 + type->nodes)));
          throw fail("its $Elements section holds more than the " +
                     plural(section.n_blocks, "block") +
                     " it announces, or does not end with $EndElements (" +
                     quoted() + ")");
        }
      if (section.n_read != section.total)
        throw fail(
          "its $Elements section (line " + std::to_string(section.start) +
          ") announces " + plural(section.total, "element") +
          " in all, but its blocks hold " + std::to_string(section.n_read));
      if (format == 41 && section.n_read > 0 &&
          (section.smallest != section.min_tag ||
           section.largest != section.max_tag))
        throw fail("its $Elements header gives the element tags as " +
                   std::to_string(section.min_tag) + " to " +
                   std::to_string(section.max_tag) + ", but they run from " +
                   std::to_string(section.smallest) + " to " +
                   std::to_string(section.largest));
    }
  } // namespace msh_scan
} // namespace dualcontact
