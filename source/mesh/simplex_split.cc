#include <pg/mesh/simplex_split.h>

#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <utility>
#include <vector>

namespace pg
{
  namespace Mesh
  {
    /**
     * 'Cells = simplices': split the quadrilaterals (hexahedra) of
     * @p hypercubes into 8 triangles (24 tetrahedra) each with
     * GridGenerator::convert_hypercube_to_simplex_mesh(), into the empty
     * @p triangulation. deal.II 9.4's function takes the active cells of a
     * refined mesh and keeps the material and boundary ids, but puts the
     * new vertices (edge midpoints and cell centres in 2-D, face centres
     * in 3-D) at the mean of the old ones, ignoring the manifolds: the
     * new vertices of a curved boundary (the hole of the plate with a
     * hole) are moved here onto it (the manifold's centre of the face).
     * It copies the manifold ids but not the manifolds; the simplices are
     * straight P1 cells (pg/mesh/linear_cells.h) that are not refined
     * again, so every manifold id is reset to flat.
     */
    template <int dim>
    void
    split_into_simplices(const Triangulation<dim> &hypercubes,
                         Triangulation<dim>       &triangulation)
    {
      // the straight and the curved centres of the curved boundary faces
      std::vector<std::pair<Point<dim>, Point<dim>>> curved;
      for (const auto &cell : hypercubes.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              face->manifold_id() != numbers::flat_manifold_id)
            curved.emplace_back(face->center(), face->center(true));

      GridGenerator::convert_hypercube_to_simplex_mesh(hypercubes,
                                                       triangulation);
      triangulation.set_all_manifold_ids(numbers::flat_manifold_id);

      if (curved.empty())
        return;
      std::vector<bool> moved(triangulation.n_vertices(), false);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            for (const unsigned int v : face->vertex_indices())
              {
                const unsigned int i = face->vertex_index(v);
                if (moved[i])
                  continue;
                moved[i] = true;
                for (const auto &[straight, on_manifold] : curved)
                  if (face->vertex(v).distance(straight) <=
                      1e-10 * face->diameter())
                    {
                      face->vertex(v) = on_manifold;
                      break;
                    }
              }
    }



    /**
     * The size of @p size split into simplices: 8 triangles per
     * quadrilateral and a vertex at each edge midpoint and cell centre of
     * the @p n cells per direction (a grid of 2 n + 1 vertices per
     * direction); 24 tetrahedra per hexahedron and a vertex at each face
     * centre. The spacing is that of the vertices.
     */
    template <int dim>
    void
    predict_split_size(const std::vector<double> &n,
                       const double               measure,
                       MeshSize                  &size)
    {
      if (dim == 2)
        {
          size.n_cells    = 8. * n[0] * n[1];
          size.n_vertices = (2. * n[0] + 1.) * (2. * n[1] + 1.);
        }
      else
        {
          size.n_cells    = 24. * n[0] * n[1] * n[2];
          size.n_vertices = (n[0] + 1.) * (n[1] + 1.) * (n[2] + 1.) +
                            n[0] * n[1] * (n[2] + 1.) +
                            n[0] * (n[1] + 1.) * n[2] +
                            (n[0] + 1.) * n[1] * n[2];
        }
      size.spacing = std::pow(measure / size.n_vertices, 1. / dim);
      // for the P1 rows of the memory estimate: 6 edge neighbours per
      // vertex on average in 2-D (Euler), about 14 in 3-D
      size.simplex         = true;
      size.edge_neighbours = (dim == 2 ? 6. : 14.);
    }



    template void
    split_into_simplices<2>(const Triangulation<2> &, Triangulation<2> &);
    template void
    split_into_simplices<3>(const Triangulation<3> &, Triangulation<3> &);
    template void
    predict_split_size<2>(const std::vector<double> &,
                          const double,
                          MeshSize &);
    template void
    predict_split_size<3>(const std::vector<double> &,
                          const double,
                          MeshSize &);
  } // namespace Mesh
} // namespace pg
