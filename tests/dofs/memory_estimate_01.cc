// The memory check of issue 45, item 1 (pg/dofs/memory_estimate.h): the
// lattice counts behind the nonzeros per row; the predicted mesh sizes
// against the meshes create_mesh() builds (generated meshes exactly, a mesh
// file as an upper bound); the estimate for prm/cook_membrane_2d.prm and
// for larger FEM and PG runs of it against their measured peak memory
// (within a factor 3); and the message of a mesh too large for the machine,
// which 'Memory check = false' silences.

#include <pg/base/exceptions.h>
#include <pg/base/formulation_code.h>
#include <pg/dofs/memory_estimate.h>
#include <pg/mesh/mesh_generator.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/tria.h>

#include "../geometry_fixture.h"
#include "../tests.h"

#include <cmath>
#include <fstream>
#include <string>
#include <tuple>


namespace
{



  pg::Parameters::Discretization
  discretization(const double horizon_factor)
  {
    pg::Parameters::Discretization p;
    p.shape_functions    = "MTE1";
    p.horizon_factor     = horizon_factor;
    p.horizon            = 0;
    p.nearest_neighbours = 0;
    p.weight_exponent    = 1;
    return p;
  }



  template <int dim>
  void
  compare(const std::string &name, const std::string &entries)
  {
    const pg::Parameters::Geometry g = geometry_parameters(entries);
    Triangulation<dim>             triangulation;
    pg::Mesh::MeshSize             predicted;
    bool                           called = false;
    pg::Mesh::create_mesh(g,
                          triangulation,
                          nullptr,
                          [&](const pg::Mesh::MeshSize &size) {
                            // before refinement: at most the coarse mesh
                            called    = true;
                            predicted = size;
                            AssertThrow(triangulation.n_active_cells() <=
                                          size.n_coarse_cells,
                                        ExcInternalError());
                          });
    deallog << name << ": called " << (called ? "yes" : "no") << ", cells "
            << static_cast<long long>(predicted.n_cells) << " (built "
            << triangulation.n_active_cells() << "), vertices "
            << static_cast<long long>(predicted.n_vertices) << " (built "
            << triangulation.n_used_vertices() << "), spacing "
            << std::round(1e4 * predicted.spacing) / 1e4 << std::endl;
  }
} // namespace



int
main()
{
  initlog();

  for (const unsigned int dim : {2u, 3u})
    for (const double radius : {1.51, 2.51, 3.02, 5.02})
      deallog << "lattice points within " << radius << " in " << dim << "-D: "
              << static_cast<long long>(pg::lattice_points_in_ball(dim, radius))
              << std::endl;

  compare<2>("hyper rectangle 3 x 2, r2",
             "set Upper corner = 3, 2\nset Subdivisions = 3, 2\n"
             "set Global refinement = 2\n");
  compare<3>("cube 2 x 2 x 1, r1",
             "set Lower corner = 0, 0, 0\nset Upper corner = 2, 2, 1\n"
             "set Subdivisions = 2, 2, 1\nset Global refinement = 1\n");
  compare<2>("cook membrane 8, r1",
             "set Mesh = cook membrane\nset Subdivisions = 8\n"
             "set Global refinement = 1\n");
  compare<2>("plate with hole, r2",
             "set Mesh = plate with hole\nset Global refinement = 2\n");
  {
    Triangulation<2> coarse;
    GridGenerator::subdivided_hyper_rectangle(coarse,
                                              {5, 3},
                                              Point<2>(),
                                              Point<2>(5., 3.));
    std::ofstream out("memory_estimate_01.msh");
    GridOut().write_msh(coarse, out);
  }
  compare<2>("mesh file 5 x 3, r2 (an upper bound)",
             "set Mesh = file\nset File name = memory_estimate_01.msh\n"
             "set Global refinement = 2\n");

  // prm/cook_membrane_2d.prm (BCPBG Unl, horizon factor 2.51, 8 x 8
  // cells, refinement 1) and two larger variants of it (1 load step, no
  // VTU), measured with the Debug build of 2026-12-07 (/usr/bin/time -v,
  // maximum resident set size, KiB x 1024): 373,036 KiB at 578 DoFs (the
  // process alone, Debug: about 380 MB), FEM at refinement 5 694,052 KiB
  // at 132,098 DoFs, BCPBG Unl at refinement 4 1,264,192 KiB at 33,282
  // DoFs (181 nonzeros per row).
  for (const auto &[formulation, refinement, measured] :
       {std::make_tuple("BCPBG Unl TL", 1, 373036 * 1024.),
        std::make_tuple("FEM", 5, 694052 * 1024.),
        std::make_tuple("BCPBG Unl TL", 4, 1264192 * 1024.)})
    {
      const pg::Parameters::Geometry g =
        geometry_parameters("set Mesh = cook membrane\nset Subdivisions = 8\n"
                            "set Global refinement = " +
                            std::to_string(refinement) + "\n");
      const pg::MemoryEstimate e =
        pg::estimate_memory<2>(pg::Mesh::predict_mesh_size<2>(g),
                               pg::parse_formulation_code(formulation),
                               discretization(2.51));
      deallog << "cook membrane, " << formulation << ", refinement "
              << refinement << ": " << static_cast<long long>(e.n_dofs)
              << " DoFs, family " << e.family_size << ", nonzeros per row "
              << e.nonzeros_per_row << ", estimate "
              << std::round(e.bytes / 1e6)
              << " MB, within a factor 3 of the measured "
              << std::round(measured / 1e6) << " MB: "
              << (e.bytes < 3 * measured && measured < 3 * e.bytes ? "yes" :
                                                                     "NO")
              << std::endl;
    }

  // the typo of issue 45 and its override
  {
    pg::Parameters::Geometry g =
      geometry_parameters("set Subdivisions = 200000, 100000\n");
    const pg::Mesh::MeshSize size = pg::Mesh::predict_mesh_size<2>(g);
    const pg::MemoryEstimate e =
      pg::estimate_memory<2>(size,
                             pg::parse_formulation_code("FEM"),
                             discretization(2.51));
    for (const bool check : {true, false})
      {
        g.memory_check = check;
        try
          {
            pg::check_memory(g, size, "FEM", e, 16e9);
            deallog << "Memory check = " << check << ": no message"
                    << std::endl;
          }
        catch (const std::exception &exc)
          {
            deallog << "Memory check = " << check << ": "
                    << pg::one_line(pg::user_message(exc)) << std::endl;
          }
      }
  }
}
