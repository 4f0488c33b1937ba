// The scan of a Gmsh file before deal.II reads it (gmsh_scan.h): the file
// as a whole and its header sections (msh_scan.h has the class).
#include "msh_scan.h"

namespace dualcontact
{
  namespace msh_scan
  {
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

  } // namespace msh_scan

  MshContents
  scan_msh(std::istream &in, const std::string &file)
  {
    return msh_scan::MshScan(in, file).run();
  }
} // namespace dualcontact
