#ifndef pg_mesh_meshfree_region_h
#define pg_mesh_meshfree_region_h

#include <pg/base/global.h>

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace pg
{
  namespace Mesh
  {
    /**
     * A region of the mesh as 'Geometry/Meshfree region' (and 'Hole') give
     * it: 'all', 'none', 'material ids 1,2', 'box x0,y0 : x1,y1' or 'ball
     * cx,cy : r'.
     */
    template <int dim>
    struct MeshfreeRegion
    {
      enum class Kind
      {
        all,
        none,
        material_ids,
        box,
        ball
      };

      /**
       * The region that @p text describes; anything else is reported as
       * ExcBadParameter for @p entry.
       */
      static MeshfreeRegion
      parse(const std::string &text,
            const std::string &entry = "Geometry/Meshfree region");

      Kind                            kind = Kind::all;
      std::vector<types::material_id> material_ids;
      Point<dim>                      lower;
      Point<dim>                      upper;
      Point<dim>                      centre;
      double                          radius = 0.;

      /**
       * Whether the centre of @p cell is in the region. Box and ball are
       * closed, with a tolerance of 1e-10 of their size, so that centres on
       * their boundary count despite round-off.
       */
      bool
      contains(
        const typename Triangulation<dim>::active_cell_iterator &cell) const;

      /** Whether @p p lies in the box or ball (closed, as above). */
      bool
      contains_point(const Point<dim> &p) const;
    };
  } // namespace Mesh
} // namespace pg

#endif
