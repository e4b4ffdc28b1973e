// pg::Discretization: what reinit() builds for FEM, PBG U1 and CPD on a
// rectangle [0,2] x [0,1] of 8 x 4 cells whose right half is meshfree (the
// cell counts, the Q1 DoFs and index sets, the particles, families, tables,
// the meshfree cells a predicate selects, the mesh diameter), the same in
// 3-D; and Postprocess::locate_points / locate_line_samples on a mesh with a
// hole (a point in the hole is rejected, line samples in it are left out).

#include <pg/base/formulation_code.h>
#include <pg/base/parameters.h>
#include <pg/dofs/discretization.h>
#include <pg/postprocess/sample_locations.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/mapping_q1.h>

#include "../geometry_fixture.h"
#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>


namespace
{



  pg::Parameters::Discretization
  discretization_parameters()
  {
    pg::Parameters::Discretization p;
    p.shape_functions    = "MTE1";
    p.horizon_factor     = 1.51;
    p.horizon            = 0;
    p.nearest_neighbours = 0;
    p.weight_exponent    = 1;
    return p;
  }



  pg::Parameters::Cpd
  cpd_parameters()
  {
    pg::Parameters::Cpd p;
    p.C1              = 1;
    p.C2              = 0;
    p.C3              = 0;
    p.partial_volumes = false;
    return p;
  }



  /** Expected sizes of a discretization. */
  struct Expected
  {
    unsigned int n_cells, n_meshfree, n_dofs, n_particles, n_loaded;
    double       diameter;
  };



  /**
   * Set up @p code on @p geometry_entries; the predicate selects the meshfree
   * cells with centre x > @p x_loaded. Checks against @p expected.
   */
  template <int dim>
  void
  check(const std::string &code,
        const std::string &geometry_entries,
        const double       x_loaded,
        const Expected    &expected)
  {
    pg::Discretization<dim> d(MPI_COMM_WORLD,
                              geometry_parameters(geometry_entries));
    unsigned int            n_asked = 0;
    d.reinit(pg::parse_formulation_code(code),
             discretization_parameters(),
             cpd_parameters(),
             [&](const typename DoFHandler<dim>::active_cell_iterator &cell) {
               ++n_asked;
               return cell->center()[0] > x_loaded;
             });

    const unsigned int n_meshfree =
      std::count(d.meshfree.begin(), d.meshfree.end(), true);
    deallog << dim << "-D " << code << ": cells "
            << d.triangulation.n_active_cells() << " (" << n_meshfree
            << " meshfree, " << d.owned_fe_cells.size() << " owned FE, "
            << d.owned_meshfree_neumann_cells.size() << " of " << n_asked
            << " asked meshfree cells loaded), DoFs " << d.dof_handler.n_dofs()
            << " (owned " << d.owned_dofs.n_elements() << ", relevant "
            << d.relevant_dofs.n_elements() << "), particles "
            << d.particles.n_particles() << ", families "
            << d.families.n_families() << " (owned " << d.owned_families.size()
            << ", tables " << d.family_tables.size() << ")" << std::endl;
    print_rounded("  mesh diameter", d.mesh_diameter, 10);
    if (d.cpd)
      {
        const auto n = d.cpd->n_interactions();
        deallog << "  CPD interactions: " << n[0] << " bonds" << std::endl;
        AssertThrow(n[0] > 0, ExcInternalError());
      }

    AssertThrow(d.triangulation.n_active_cells() == expected.n_cells,
                ExcInternalError());
    AssertThrow(n_meshfree == expected.n_meshfree, ExcInternalError());
    AssertThrow(d.owned_fe_cells.size() == expected.n_cells - n_meshfree,
                ExcInternalError());
    AssertThrow(n_asked == n_meshfree, ExcInternalError());
    AssertThrow(d.owned_meshfree_neumann_cells.size() == expected.n_loaded,
                ExcInternalError());
    AssertThrow(d.dof_handler.n_dofs() == expected.n_dofs, ExcInternalError());
    AssertThrow(d.owned_dofs.n_elements() == expected.n_dofs,
                ExcInternalError());
    AssertThrow(d.relevant_dofs.n_elements() == expected.n_dofs,
                ExcInternalError());
    AssertThrow(d.particles.n_particles() == expected.n_particles,
                ExcInternalError());
    AssertThrow(d.families.n_families() == expected.n_particles,
                ExcInternalError());
    AssertThrow(d.owned_families.size() == expected.n_particles,
                ExcInternalError());
    AssertThrow(d.family_tables.size() == expected.n_particles,
                ExcInternalError());
    AssertThrow((d.family_elements != nullptr) == (expected.n_particles > 0),
                ExcInternalError());
    AssertThrow((d.cpd != nullptr) == (code == "CPD"), ExcInternalError());
    AssertThrow(std::abs(d.mesh_diameter - expected.diameter) < 1e-12,
                ExcInternalError());
    AssertThrow(d.mesh_notes.empty(), ExcInternalError());
    AssertThrow(d.time_mesh >= 0 && d.time_setup >= 0 && d.time_shape >= 0,
                ExcInternalError());
  }



  void
  test_discretization()
  {
    const std::string rectangle = "set Upper corner = 2, 1\n"
                                  "set Subdivisions = 8, 4\n"
                                  "set Meshfree region = box 1,0 : 2,1\n";
    // 9 x 5 vertices, 5 x 5 particles, the right column of meshfree cells
    // loaded
    check<2>("FEM", rectangle, 1.75, {32, 0, 90, 0, 0, std::sqrt(5.)});
    check<2>("PBG U1", rectangle, 1.75, {32, 16, 90, 25, 4, std::sqrt(5.)});
    check<2>("CPD", rectangle, 1.75, {32, 16, 90, 25, 4, std::sqrt(5.)});
    check<3>("PBG U1",
             "set Lower corner = 0, 0, 0\n"
             "set Upper corner = 1, 1, 1\n"
             "set Subdivisions = 3\n"
             "set Meshfree region = all\n",
             2.,
             {27, 27, 192, 64, 0, std::sqrt(3.)});
  }



  void
  test_sample_locations()
  {
    deallog << "sample locations on [0,2] x [0,1], 8 x 4 cells, hole "
            << "(0.5,1) x (0,0.5)" << std::endl;
    pg::Discretization<2> d(MPI_COMM_WORLD,
                            geometry_parameters(
                              "set Upper corner = 2, 1\n"
                              "set Subdivisions = 8, 4\n"
                              "set Hole = box 0.5,0 : 1,0.5\n"));
    d.reinit(pg::parse_formulation_code("FEM"),
             discretization_parameters(),
             cpd_parameters(),
             [](const auto &) { return false; });
    AssertThrow(d.triangulation.n_active_cells() == 28, ExcInternalError());

    const MappingQ1<2> mapping;
    const auto         points =
      pg::Postprocess::locate_points(d.dof_handler,
                                     {{"A", {1.6, 0.7}}, {"B", {0., 1.}}});
    AssertThrow(points.size() == 2, ExcInternalError());
    for (const auto &[cell, reference] : points)
      {
        const Point<2> p = mapping.transform_unit_to_real_cell(cell, reference);
        deallog << "point at (" << p[0] << ", " << p[1] << ") in the cell "
                << "centred at (" << cell->center()[0] << ", "
                << cell->center()[1] << ")" << std::endl;
        AssertThrow(GeometryInfo<2>::is_inside_unit_cell(reference, 1e-12),
                    ExcInternalError());
      }
    AssertThrow(points[0].first->center().distance(Point<2>(1.625, 0.625)) <
                  1e-12,
                ExcInternalError());
    AssertThrow(
      mapping.transform_unit_to_real_cell(points[1].first, points[1].second)
          .distance(Point<2>(0., 1.)) < 1e-12,
      ExcInternalError());

    bool rejected = false;
    try
      {
        pg::Postprocess::locate_points(d.dof_handler,
                                       {{"in the hole", {0.75, 0.25}}});
      }
    catch (const ExceptionBase &e)
      {
        rejected = true;
        deallog << "point in the hole: " << exception_message(e) << std::endl;
      }
    AssertThrow(rejected, ExcInternalError());

    // 9 samples at x = 0, 0.25, ..., 2 on y = 0.125: the one at x = 0.75
    // lies in the hole
    const auto samples = pg::Postprocess::locate_line_samples(
      d.dof_handler,
      {{"bottom", {0., 0.125}, {2., 0.125}}},
      9);
    deallog << "line samples: " << samples.size() << ", arc lengths";
    for (const auto &s : samples)
      deallog << " " << s.arc_length;
    deallog << std::endl;
    AssertThrow(samples.size() == 8, ExcInternalError());
    for (const auto &s : samples)
      {
        AssertThrow(s.line == 0, ExcInternalError());
        AssertThrow(std::abs(s.arc_length - s.position[0]) < 1e-12,
                    ExcInternalError());
        AssertThrow(mapping.transform_unit_to_real_cell(s.cell, s.reference)
                        .distance(s.position) < 1e-12,
                    ExcInternalError());
        AssertThrow(std::abs(s.position[0] - 0.75) > 1e-12, ExcInternalError());
      }
  }
} // namespace



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  test_discretization();
  test_sample_locations();
}
