// The smallest program on an installed pg: the particles and families of
// the meshfree right half of a 2-D Q1 mesh, and the PBG Unl quadrature of
// one family, whose weights add up to the family's share of the volume.
// CI builds it against `cmake --install` and checks its output.

#include <pg/elements/family_elements.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>
#include <pg/version.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <iostream>

int
main()
{
  using namespace dealii;
  std::cout << "pg " << pg::version() << " (headers " << PG_VERSION_STRING
            << ", " << PG_BUILD_TYPE << ")" << std::endl;

  Triangulation<2> triangulation;
  GridGenerator::subdivided_hyper_rectangle(triangulation,
                                            {8, 4},
                                            Point<2>(0, 0),
                                            Point<2>(2, 1));
  FESystem<2>   fe(FE_Q<2>(1), 2);
  DoFHandler<2> dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);

  // the cells right of x = 1 are meshfree: their vertices are particles
  std::vector<bool> meshfree;
  for (const auto &cell : triangulation.active_cell_iterators())
    meshfree.push_back(cell->center()[0] > 1);
  pg::ParticleSet<2> particles;
  particles.reinit(dof_handler, meshfree);
  pg::FamilySet<2> families;
  families.reinit(particles, 2.51, 0);

  pg::FamilyElements<2> elements(particles,
                                 families,
                                 pg::parse_formulation_code("PBG Unl"),
                                 pg::ShapeFunctions::Base::mte1,
                                 1.);
  elements.initialize();
  double volume = 0;
  for (unsigned int k = 0; k < particles.n_particles(); ++k)
    {
      pg::QuadratureTable<2> table;
      elements.build(k, table);
      for (const double w : table.weights)
        volume += w;
    }
  std::cout << "particles: " << particles.n_particles()
            << ", volume of the family quadrature: " << volume
            << " (meshfree volume " << particles.total_volume() << ")"
            << std::endl;
  return (std::abs(volume - 1.) < 1e-12 ? 0 : 1);
}
