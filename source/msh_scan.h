// The scan of a Gmsh file (gmsh_scan.h): the class that reads it line by
// line, shared by gmsh_scan.cc (the header sections: format, names,
// entities) and gmsh_scan_blocks.cc (the node and element blocks). Internal
// to the library.
#ifndef dualcontact_msh_scan_h
#define dualcontact_msh_scan_h

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
  namespace msh_scan
  {
    /** A Gmsh element type that check_elements() knows. */
    struct ElementType
    {
      unsigned int nodes;
      unsigned int dim;
      const char  *name;
    };

    /** The type `type` if check_elements() knows it, else nullptr. */
    inline const ElementType *
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

    inline const std::array<std::string, 4> entity_kinds = {
      {"point", "curve", "surface", "volume"}};

    // deal.II's reader holds tags and counts in int
    constexpr long long largest_int = std::numeric_limits<int>::max();

    /** A piece of the file for a message: one line, at most 40 characters. */
    inline std::string
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
      double
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
        return value;
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
      /**
       * Where the scan of a $Nodes or $Elements section stands: its header
       * (section_header()), the items of the blocks read so far, the
       * current block's header line, count and (for elements) type, and
       * the smallest and largest element tag so far.
       */
      struct SectionScan
      {
        unsigned long      start; // the line of the section's marker
        long long          n_blocks, total, min_tag, max_tag;
        long long          n_read     = 0;
        long long          n          = 0;
        unsigned long      block_line = 0;
        const ElementType *type       = nullptr;
        long long          smallest = largest_int, largest = 0;
      };

      void
      nodes_section();
      /** A 4.x node block's header: sets section.n and .block_line;
       * returns its parametric flag. */
      long long
      node_block_header(SectionScan       &section,
                        const long long    block,
                        const std::string &in_block);
      /** A 4.1 node block: the tags, one a line, then the coordinates. */
      void
      node_block_41(const SectionScan &section,
                    const std::string &in_block,
                    const std::size_t  n_coordinates,
                    const std::string &coordinates);
      /** A 2.x or 4.0 node block: a line per node, tag and coordinates. */
      void
      node_lines(const SectionScan &section,
                 const std::string &in_block,
                 const std::size_t  n_coordinates,
                 const std::string &coordinates);
      /** $EndNodes where it should be, and the counts as announced. */
      void
      end_of_nodes(const SectionScan &section);
      void
      node_lookup(const long long min_tag, const long long max_tag);
      void
      elements_section();
      /** The 2.x $Elements section: a line per element. */
      void
      element_lines_2(SectionScan &section);
      /** A 4.x element block's header: sets section.n, .type and
       * .block_line; returns the element type's number. */
      long long
      element_block_header(SectionScan       &section,
                           const long long    block,
                           const std::string &in_block);
      /** The lines of a 4.x element block: tag and nodes. */
      void
      element_lines(SectionScan       &section,
                    const long long    block,
                    const std::string &in_block,
                    const long long    number);
      /** $EndElements where it should be, the counts and the tag range as
       * announced. */
      void
      end_of_elements(const SectionScan &section);
      void
      element_nodes(const std::size_t first,
                    const long long   element,
                    const long long   type);
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
      // the node tags (contents.node_tags) looked up by element in a
      // bitmap if they are dense (as Gmsh numbers them), else in a hash set
      std::vector<bool>       node_bitmap;
      std::unordered_set<int> node_set;
      MshContents             contents;
    };

  } // namespace msh_scan
} // namespace dualcontact

#endif
