// Several bodies in one coarse mesh: the geometries of two bodies (the two
// blocks, the two half discs) build each on its own and join them here.
#ifndef dualcontact_geometries_join_bodies_h
#define dualcontact_geometries_join_bodies_h

#include <deal.II/grid/tria.h>

#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The bodies `parts` in one coarse mesh that shares no vertex between
   * them, not even where they touch (GridGenerator::merge_triangulations
   * would glue those): body i's cells get material id i. Boundary ids
   * are the caller's to set.
   */
  template <int dim>
  void
  join_bodies(const std::vector<const Triangulation<dim> *> &parts,
              Triangulation<dim>                            &result)
  {
    std::vector<Point<dim>>    vertices;
    std::vector<CellData<dim>> cells;
    for (unsigned int body = 0; body < parts.size(); ++body)
      {
        const unsigned int offset = vertices.size();
        vertices.insert(vertices.end(),
                        parts[body]->get_vertices().begin(),
                        parts[body]->get_vertices().end());
        for (const auto &cell : parts[body]->active_cell_iterators())
          {
            CellData<dim> data(cell->n_vertices());
            for (const unsigned int v : cell->vertex_indices())
              data.vertices[v] = offset + cell->vertex_index(v);
            data.material_id = body;
            cells.push_back(data);
          }
      }
    result.create_triangulation(vertices, cells, SubCellData());
  }
} // namespace dualcontact

#endif
