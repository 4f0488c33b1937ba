#include <dualcontact/gmsh_scan.h>
#include <dualcontact/input_error.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace dualcontact
{
  namespace
  {
    /** A Gmsh element type that check_elements() knows. */
    struct ElementType
    {
      unsigned int nodes;
      unsigned int dim;
      const char  *name;
    };

    /** The type `type` if check_elements() knows it, else nullptr. */
    const ElementType *
    element_type(const long long type)
    {
      static const std::map<long long, ElementType> types = {
        {MshContents::point, {1, 0, "point"}},
        {MshContents::line, {2, 1, "line"}},
        {MshContents::triangle, {3, 2, "triangle"}},
        {MshContents::quad, {4, 2, "quadrilateral"}},
        {MshContents::tetrahedron, {4, 3, "tetrahedron"}},
        {MshContents::hexahedron, {8, 3, "hexahedron"}},
        {MshContents::prism, {6, 3, "prism"}},
        {MshContents::pyramid, {5, 3, "pyramid"}}};
      const auto it = types.find(type);
      return it == types.end() ? nullptr : &it->second;
    }

    const std::array<std::string, 4> entity_kinds = {
      {"point", "curve", "surface", "volume"}};

    // deal.II's reader holds tags and counts in int
    constexpr long long largest_int = std::numeric_limits<int>::max();

    /** A piece of the file for a message: one line, at most 40 characters. */
    std::string
    excerpt(const std::string_view text)
    {
      std::string shown(text.substr(0, 40));
      for (char &c : shown)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
          c = '?';
      return shown + (text.size() > 40 ? "..." : "");
    }

    /**
     * The scan of a Gmsh ASCII file (format 2.x, 4.0 or 4.1) before
     * deal.II's GridIn::read_msh sees it. In release mode that reader checks
     * neither counts nor tags: it reads the nodes of all blocks into a
     * vector sized by the header's total (blocks that hold more write past
     * its end), takes a node tag, a coordinate or an element's node
     * wherever the previous read stopped, indexes its four entity maps by
     * the entity dimension of an element block, passes an element with a
     * repeated node, or a boundary element with a node that is not in
     * $Nodes, on to the triangulation, reads two parametric coordinates for
     * every node of a parametric block, and loops over every count it reads
     * and until the end markers of $PhysicalNames and $PartitionedEntities
     * even at the end of the file. So every count is checked against what
     * follows, every line against its form, every tag against the range the
     * reader holds it in and every element's nodes against $Nodes: one pass,
     * line by line (each line as Gmsh writes it), linear in the size of the
     * file. The sections must come in the order the reader takes them; it
     * stops at $EndElements, and so does the scan. Element types other than
     * those of element_type() are counted and left to check_elements().
     */
    class MshScan
    {
    public:
      MshScan(std::istream &in, const std::string &file)
          : in(in)
          , file(file)
      {}

      MshContents
      run();

    private:
      InputError
      fail(const std::string &why) const
      {
        return InputError("The file " + file +
                            " is not a Gmsh mesh that can be read: " + why +
                            ".",
                          exit_cannot_read_file);
      }

      /** Split `line` into `words`. */
      void
      split()
      {
        words.clear();
        const char *p = line.data(), *const end = p + line.size();
        while (p < end)
          {
            while (p < end && std::isspace(static_cast<unsigned char>(*p)))
              ++p;
            const char *const start = p;
            while (p < end && !std::isspace(static_cast<unsigned char>(*p)))
              ++p;
            if (p > start)
              words.emplace_back(start, p - start);
          }
      }

      /** Read the next line into `words`; false at the end of the file. */
      bool
      next()
      {
        words.clear();
        if (!std::getline(in, line))
          return false;
        ++line_number;
        split();
        return true;
      }

      /** The next line that is not blank; false at the end of the file. */
      bool
      next_nonblank()
      {
        while (next())
          if (!words.empty())
            return true;
        return false;
      }

      /** The next line of `section`, which the end of the file cuts off. */
      void
      next_in(const std::string &section)
      {
        if (!next())
          throw fail("it ends inside its " + section + " section");
      }

      /** The next line that is not blank, where `marker` should stand. */
      void
      expect_end(const std::string &section, const std::string &marker)
      {
        if (!next_nonblank())
          throw fail("it ends inside its " + section + " section");
        if (words[0] != marker)
          throw fail("its " + section + " section does not end with " + marker +
                     " where it should (" + quoted() + ")");
      }

      bool
      is_marker() const
      {
        return !words.empty() && words[0][0] == '$';
      }

      std::string
      where() const
      {
        return "line " + std::to_string(line_number);
      }

      std::string
      quoted() const
      {
        return where() + ": '" + excerpt(line) + "'";
      }

      /** `what`: a string, or (on the lines of the nodes and elements) a
       * callable that makes it, called only for a message. */
      template <typename What>
      static std::string
      text(const What &what)
      {
        if constexpr (std::is_invocable_v<const What &>)
          return what();
        else
          return std::string(what);
      }

      /** Word i as a whole number from low to high, or throw naming it. */
      template <typename What>
      long long
      integer(const std::size_t i,
              const long long   low,
              const long long   high,
              const What       &what) const
      {
        long long              value = 0;
        const std::string_view word  = words[i];
        const auto             result =
          std::from_chars(word.data(), word.data() + word.size(), value);
        if (result.ec != std::errc() ||
            result.ptr != word.data() + word.size() || value < low ||
            value > high)
          throw fail(text(what) + " (" + where() + ") is '" + excerpt(word) +
                     "', not a whole number from " + std::to_string(low) +
                     " to " + std::to_string(high));
        return value;
      }

      /** Word i as a finite number, or throw naming it. */
      template <typename What>
      void
      real(const std::size_t i, const What &what) const
      {
        double                 value = 0;
        const std::string_view word  = words[i];
        const auto             result =
          std::from_chars(word.data(), word.data() + word.size(), value);
        if (result.ec != std::errc() ||
            result.ptr != word.data() + word.size() || !std::isfinite(value))
          throw fail(text(what) + " (" + where() + ") is '" + excerpt(word) +
                     "', not a finite number");
      }

      /** How many lines from the current one on have `n_words` words. */
      unsigned long
      count_lines_of(const std::size_t n_words)
      {
        unsigned long n = 0;
        while (words.size() == n_words && !is_marker())
          {
            ++n;
            if (!next())
              break;
          }
        return n;
      }

      bool
      node_exists(const long long tag) const
      {
        if (!node_bitmap.empty())
          return static_cast<std::size_t>(tag) < node_bitmap.size() &&
                 node_bitmap[tag];
        return node_set.count(static_cast<int>(tag)) > 0;
      }

      /**
       * The header line of $Nodes or $Elements (`section`, whose items are
       * `item`s): the number of blocks (1 in format 2), the number of
       * items, and in 4.1 their smallest and largest tag (else 0).
       */
      std::array<long long, 4>
      section_header(const std::string &section, const std::string &item)
      {
        const std::size_t size = format == 41 ? 4 : format == 40 ? 2 : 1;
        const std::string items =
          std::string(1, static_cast<char>(std::toupper(item[0]))) +
          item.substr(1) + "s";
        if (words.size() != size)
          throw fail("its $" + section + " section does not begin with " +
                     (format == 41 ?
                        "'numEntityBlocks num" + items + " min" +
                          items.substr(0, items.size() - 1) + "Tag max" +
                          items.substr(0, items.size() - 1) + "Tag'" :
                      format == 40 ? "'numEntityBlocks num" + items + "'" :
                                     "the number of " + item + "s") +
                     " (" + quoted() + ")");
        std::array<long long, 4> header{{1, 0, 0, 0}};
        if (format != 2)
          header[0] =
            integer(0,
                    0,
                    largest_int,
                    "the number of blocks of its $" + section + " section");
        header[1] = integer(format == 2 ? 0 : 1,
                            0,
                            largest_int,
                            "the number of " + item + "s of its $" + section +
                              " section");
        if (format == 41)
          {
            header[2] = integer(2,
                                0,
                                largest_int,
                                "the smallest " + item + " tag of $" + section);
            header[3] = integer(3,
                                0,
                                largest_int,
                                "the largest " + item + " tag of $" + section);
          }
        return header;
      }

      void
      physical_names();
      void
      skip_to(const std::string &section, const std::string &marker);
      void
      entities_section();
      void
      entity(const unsigned int d);
      void
      nodes_section();
      void
      node_lookup(const long long min_tag, const long long max_tag);
      void
      elements_section();
      void
      element_nodes(const std::size_t first, const long long element);
      bool
      looks_like_element_block() const;

      std::istream                 &in;
      const std::string             file;
      std::string                   line;
      std::vector<std::string_view> words;
      unsigned long                 line_number  = 0;
      int                           format       = 0; // 2 (2.x), 40 or 41
      bool                          has_entities = false;
      bool                          partitioned  = false;
      // the tags of $Entities, by dimension
      std::array<std::unordered_set<long long>, 4> entities;
      // the node tags; then looked up by element in a bitmap if they are
      // dense (as Gmsh numbers them), else in a hash set
      std::vector<int>        node_tags;
      std::vector<bool>       node_bitmap;
      std::unordered_set<int> node_set;
      MshContents             contents;
    };

    MshContents
    MshScan::run()
    {
      if (!next_nonblank() || words[0] != "$MeshFormat")
        throw fail("it does not begin with $MeshFormat (write it with "
                   "Gmsh: 'gmsh -2 mesh.geo' or 'gmsh -3 mesh.geo')");
      long long file_type = -1;
      bool      parsed    = next() && words.size() == 3;
      if (parsed)
        {
          const std::string_view v = words[0], t = words[1];
          const auto             version =
            std::from_chars(v.data(), v.data() + v.size(), contents.version);
          const auto type =
            std::from_chars(t.data(), t.data() + t.size(), file_type);
          parsed = version.ec == std::errc() && type.ec == std::errc() &&
                   std::isfinite(contents.version);
        }
      if (!parsed)
        throw fail("its $MeshFormat line is not 'version 0 8'");
      const double version = contents.version;
      format               = version >= 2. && version < 2.25   ? 2 :
                             version >= 4. && version < 4.05   ? 40 :
                             version >= 4.05 && version < 4.15 ? 41 :
                                                                 0;
      if (format == 0)
        throw fail("its format " + std::to_string(version).substr(0, 3) +
                   " is neither 2.2 nor 4.1 (Gmsh: 'gmsh -format msh41' or "
                   "'Mesh.MshFileVersion = 4.1;')");
      if (file_type != 0)
        throw fail("it is binary; write it as ASCII ('Mesh.Binary = 0;', or "
                   "'gmsh' without '-bin')");
      expect_end("$MeshFormat", "$EndMeshFormat");

      // deal.II's reader takes these sections in this order, those before
      // $Nodes only if they are there, and stops after $Elements
      const std::vector<std::string> order =
        format == 2 ?
          std::vector<std::string>{"$PhysicalNames", "$Nodes", "$Elements"} :
          std::vector<std::string>{"$PhysicalNames",
                                   "$Entities",
                                   "$PartitionedEntities",
                                   "$Nodes",
                                   "$Elements"};
      const std::size_t nodes = order.size() - 2;
      std::size_t       first = 0; // the first section that may come next
      while (first < order.size())
        {
          if (!next_nonblank())
            throw fail("it has no $Nodes or no $Elements section");
          const std::size_t position =
            std::find(order.begin(), order.end(), words[0]) - order.begin();
          if (position < first || position > std::max(first, nodes))
            {
              std::string expected = "$Nodes";
              if (first > nodes)
                expected = "$Elements (right after $EndNodes)";
              else if (first < nodes)
                {
                  expected += " (before it only ";
                  for (std::size_t s = first; s < nodes; ++s)
                    expected += order[s] + (s + 1 < nodes ? ", " : "");
                  expected += nodes - first > 1 ? ", in this order)" : ")";
                }
              throw fail((is_marker() ? "its section " + excerpt(words[0]) +
                                          " (" + where() + ")" :
                                        quoted()) +
                         " stands where deal.II's reader expects " + expected);
            }
          const std::string &section = order[position];
          if (section == "$PhysicalNames")
            physical_names();
          else if (section == "$Entities")
            entities_section();
          else if (section == "$PartitionedEntities")
            {
              skip_to(section, "$EndPartitionedEntities");
              partitioned = true;
            }
          else if (section == "$Nodes")
            nodes_section();
          else
            elements_section();
          first = position + 1;
        }
      return contents;
    }

    void
    MshScan::physical_names()
    {
      const unsigned long start = line_number;
      next_in("$PhysicalNames");
      if (words.size() != 1)
        throw fail("its $PhysicalNames section does not begin with the "
                   "number of names (" +
                   quoted() + ")");
      const long long n = integer(
        0, 0, largest_int, "the number of names of its $PhysicalNames section");
      for (long long i = 0; i < n; ++i)
        {
          next_in("$PhysicalNames");
          if (words.empty() || is_marker())
            throw fail("its $PhysicalNames section (line " +
                       std::to_string(start) + ") announces " +
                       plural(n, "name") + " but holds " + std::to_string(i));
        }
      expect_end("$PhysicalNames", "$EndPhysicalNames");
    }

    void
    MshScan::skip_to(const std::string &section, const std::string &marker)
    {
      const unsigned long start = line_number;
      while (next())
        if (!words.empty() && words[0] == marker)
          return;
      throw fail("its " + section + " section (line " + std::to_string(start) +
                 ") has no " + marker);
    }

    void
    MshScan::entities_section()
    {
      const unsigned long start = line_number;
      next_in("$Entities");
      if (words.size() != 4)
        throw fail("its $Entities section does not begin with the numbers "
                   "of points, curves, surfaces and volumes (" +
                   quoted() + ")");
      std::array<long long, 4> n{};
      long long                total = 0;
      for (unsigned int d = 0; d < 4; ++d)
        {
          n[d] = integer(d,
                         0,
                         largest_int,
                         "the number of " + entity_kinds[d] +
                           "s of its $Entities section");
          total += n[d];
        }
      // The section is small: its lines are held, so that a count that
      // does not match them is told as such, not as a malformed line.
      std::vector<std::pair<unsigned long, std::string>> lines;
      while (true)
        {
          if (!next_nonblank() || (is_marker() && words[0] != "$EndEntities"))
            throw fail("its $Entities section (line " + std::to_string(start) +
                       ") has no $EndEntities");
          if (words[0] == "$EndEntities")
            break;
          lines.emplace_back(line_number, line);
        }
      if (static_cast<long long>(lines.size()) != total)
        throw fail("its $Entities section (line " + std::to_string(start) +
                   ") announces " + plural(total, "entity") + " (" +
                   plural(n[0], "point") + ", " + plural(n[1], "curve") + ", " +
                   plural(n[2], "surface") + ", " + plural(n[3], "volume") +
                   ") but holds " + std::to_string(lines.size()));
      const unsigned long end   = line_number;
      std::size_t         index = 0;
      for (unsigned int d = 0; d < 4; ++d)
        for (long long i = 0; i < n[d]; ++i, ++index)
          {
            line_number = lines[index].first;
            line        = std::move(lines[index].second);
            split();
            entity(d);
          }
      line_number  = end;
      has_entities = true;
    }

    void
    MshScan::entity(const unsigned int d)
    {
      const std::string &kind = entity_kinds[d];
      // a point of format 4.1 has its coordinates, the rest a bounding box
      const std::size_t box = d == 0 && format == 41 ? 3 : 6;
      if (words.size() < box + 2)
        throw fail("its $Entities line for a " + kind + " is too short (" +
                   quoted() + ")");
      const long long tag =
        integer(0, 1, largest_int, "the tag of a " + kind + " of $Entities");
      const std::string name = kind + " " + std::to_string(tag);
      for (std::size_t k = 1; k <= box; ++k)
        real(k, "a coordinate of its $Entities " + name);
      const long long n_physical =
        integer(box + 1,
                0,
                largest_int,
                "the number of physical tags of its $Entities " + name);
      std::size_t expected   = box + 2 + n_physical;
      long long   n_bounding = 0;
      if (d > 0 && words.size() > expected)
        n_bounding = integer(expected,
                             0,
                             largest_int,
                             "the number of bounding entities of its "
                             "$Entities " +
                               name);
      if (d > 0)
        expected += 1 + n_bounding;
      if (words.size() != expected)
        throw fail("its $Entities " + name + " (" + where() + ") has " +
                   plural(words.size(), "number") + " where its counts (" +
                   plural(n_physical, "physical tag") +
                   (d > 0 ? ", " + plural(n_bounding, "bounding entity") :
                            std::string()) +
                   ") make " + std::to_string(expected));
      if (n_physical > 1)
        throw fail("its $Entities " + name + " (" + where() + ") is in " +
                   std::to_string(n_physical) +
                   " physical groups; deal.II's reader takes one at most "
                   "(its number becomes the boundary id)");
      if (n_physical == 1)
        integer(box + 2,
                0,
                largest_int,
                "the physical tag of its $Entities " + name);
      for (std::size_t k = box + 3 + n_physical; k < words.size(); ++k)
        integer(k,
                -largest_int,
                largest_int,
                "a bounding entity of its $Entities " + name);
      entities[d].insert(tag);
    }

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
                  node_tags.push_back(
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
                           std::to_string(node_tags[node_tags.size() - n + i]);
                  };
                  if (words.size() != n_coordinates)
                    throw fail("the coordinates of " + node() + " of its " +
                               in_block + " (" + quoted() + ") are " +
                               std::to_string(words.size()) + " numbers, not " +
                               coordinates);
                  for (std::size_t k = 0; k < n_coordinates; ++k)
                    real(k, [&] { return "a coordinate of " + node(); });
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
                node_tags.push_back(static_cast<int>(tag));
                for (std::size_t k = 1; k <= n_coordinates; ++k)
                  real(k, [&] {
                    return "a coordinate of node " + std::to_string(tag);
                  });
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
      node_tags = std::vector<int>();
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
    MshScan::element_nodes(const std::size_t first, const long long element)
    {
      const auto name = [element] {
        return "element " + std::to_string(element);
      };
      for (std::size_t k = first; k < words.size(); ++k)
        {
          const long long node = integer(k, 1, largest_int, [&] {
            return "a node of its " + name();
          });
          if (!node_exists(node))
            throw fail("its " + name() + " (" + where() + ") refers to node " +
                       std::to_string(node) + ", which $Nodes does not define");
          for (std::size_t j = first; j < k; ++j)
            if (words[j] == words[k])
              throw fail("its " + name() + " (" + where() + ") lists node " +
                         std::to_string(node) + " twice");
        }
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
                  element_nodes(3 + n_tags, tag);
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
              element_nodes(1, tag);
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
  } // namespace

  MshContents
  scan_msh(std::istream &in, const std::string &file)
  {
    return MshScan(in, file).run();
  }
} // namespace dualcontact
