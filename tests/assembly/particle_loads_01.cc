// ParticleLoads, the load term of the Assembler on particles (pg-methods.md
// section 8.2, eqs. 4.32-4.35), on the all-meshfree unit square (4 x 4
// cells, 25 particles, BCPBG Unl, horizon 2.51 h), Neumann on x = 1
// (id 1) with T = (2 t, -t) at load factor t = 0.5 and b = (0.5, 0.25):
// 1. 'geometry': the body force V^k b plus the FE-consistent face load;
//    the total is exact, T + b (area 1, volume 1).
// 2. 'test functions': the traction at particle k is c T with c = n . d^k
//    at the particles of one boundary part; the total is b + T sum c.
// 3. 'exact stress': the loaded surface particles get the exact-stress
//    force (here a marker) in place of body force and traction.
// 4. particle_stress_force() of P = 1 is the unit-stress residual d^k.

#include <pg/assembly/assembler.h>
#include <pg/assembly/loads.h>
#include <pg/assembly/particle_loads.h>
#include <pg/base/formulation_code.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/unit_stress_residual.h>
#include <pg/problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include "../particle_fixture.h"
#include "../tests.h"

using namespace pg;

constexpr int dim = 2;

/** The parameters of 'Particle traction area = @p area'. */
void
parse(const std::string &area, Parameters::AllParameters<dim> &all)
{
  ParameterHandler prm;
  declare_all_parameters<dim>(prm);
  prm.parse_input_from_string("set Dimension = 2\n"
                              "subsection Boundary conditions\n"
                              "  set Neumann = 1\n"
                              "  set Particle traction area = " +
                              area +
                              "\n"
                              "  subsection Traction\n"
                              "    set Function expression = 2*t; -t\n"
                              "  end\n"
                              "  subsection Body force\n"
                              "    set Function expression = 0.5; 0.25\n"
                              "  end\n"
                              "end\n");
  all.parse_parameters(prm);
  all.set_load_factor(0.5);
}



/** print_bound() that also stops the test if the bound fails. */
void
check_bound(const std::string &name, const double value, const double bound)
{
  print_bound(name, value, bound);
  AssertThrow(std::abs(value) <= bound, ExcMessage(name));
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const ParticleFixture<dim> fixture(4, 0., 2.51);
  const ParticleSet<dim>    &particles   = fixture.particles;
  const FormulationCode      formulation = parse_formulation_code("BCPBG Unl");
  FamilyElements<dim>        elements(particles,
                               fixture.families,
                               formulation,
                               ShapeFunctions::Base::mte1,
                               1.);
  elements.initialize();
  std::vector<unsigned int>         owned(particles.n_particles());
  std::vector<QuadratureTable<dim>> tables(owned.size());
  for (unsigned int k = 0; k < owned.size(); ++k)
    {
      owned[k] = k;
      elements.build(k, tables[k]);
    }

  const Tensor<1, dim> T({1., -0.5}), b({0.5, 0.25});
  const Tensor<1, dim> marker({1000., 0.});
  const auto           exact_force = [&](const unsigned int k) {
    return marker + Tensor<1, dim>({0., 1. * k});
  };
  const IndexSet dofs = complete_index_set(fixture.dof_handler.n_dofs());
  AffineConstraints<double> constraints;
  constraints.close();
  pg::LinearAlgebra::Vector       rhs(dofs, MPI_COMM_WORLD), force(rhs);
  const pg::LinearAlgebra::Vector u(rhs);

  for (const std::string area : {"geometry", "test functions", "exact stress"})
    {
      Parameters::AllParameters<dim> parameters;
      parse(area, parameters);
      const Loads<dim> loads(parameters);
      std::vector<typename DoFHandler<dim>::active_cell_iterator> cells;
      if (area == "geometry")
        for (const auto &cell : fixture.dof_handler.active_cell_iterators())
          if (loads.has_neumann_face(cell))
            cells.push_back(cell);
      ParticleLoads<dim> particle_loads(parameters,
                                        formulation,
                                        loads,
                                        particles,
                                        owned,
                                        cells,
                                        exact_force);
      particle_loads.compute_unit_stress_residual(fixture.families,
                                                  tables,
                                                  MPI_COMM_WORLD);
      AssertThrow(particle_loads.traction_from_test_functions() ==
                      (area == "test functions") &&
                    particle_loads.traction_from_exact_stress() ==
                      (area == "exact stress"),
                  ExcInternalError());

      Assembler<dim>    assembler(constraints, {});
      const std::string failure =
        assembler.assemble(u, nullptr, rhs, force, particle_loads.load_term());
      AssertThrow(failure.empty(), ExcMessage(failure));

      // the load of each particle (rhs = -force = f_ext without constraints)
      Tensor<1, dim> total;
      double         seen = 0, worst = 0;
      for (unsigned int k = 0; k < particles.n_particles(); ++k)
        {
          Tensor<1, dim> load;
          for (unsigned int c = 0; c < dim; ++c)
            {
              load[c] = rhs(particles.dof(k, c));
              AssertThrow(load[c] == -force(particles.dof(k, c)),
                          ExcInternalError());
            }
          total += load;
          const auto    &parts    = particles.boundary_area_vectors(k);
          const bool     loaded   = parts.find(1) != parts.end();
          Tensor<1, dim> expected = particles.volume(k) * b;
          if (area == "test functions" && loaded)
            {
              const double c = particle_loads.boundary_area_weights()[k].at(1);
              // one boundary part: c = n . d^k
              if (parts.size() == 1)
                AssertThrow(std::abs(c - particle_loads.unit_stress()[k][0]) <
                              1e-14,
                            ExcInternalError());
              seen += c;
              expected += c * T;
            }
          if (area == "exact stress" && loaded)
            expected = exact_force(k);
          if (area != "geometry")
            worst = std::max(worst, (load - expected).norm());
        }
      deallog << area << ": total load = " << total << std::endl;
      if (area == "geometry")
        check_bound("  |total - (T + b)|", (total - T - b).norm(), 1e-13);
      else
        check_bound("  max |load - expected| over the particles", worst, 1e-13);
      if (area == "test functions")
        {
          deallog << "  Neumann area seen by the test functions = " << seen
                  << std::endl;
          check_bound("  |total - (b + T sum c)|",
                      (total - b - seen * T).norm(),
                      1e-13);
        }
    }

  // particle_stress_force of P = 1 is d^k
  const std::vector<Tensor<1, dim>> d = unit_stress_residual(fixture.families,
                                                             owned,
                                                             tables,
                                                             particles,
                                                             MPI_COMM_WORLD);
  double                            worst = 0;
  for (unsigned int k = 0; k < particles.n_particles(); ++k)
    worst =
      std::max(worst,
               (particle_stress_force<dim>(fixture.particles,
                                           fixture.families,
                                           elements,
                                           k,
                                           [](const Point<dim> &) {
                                             return Tensor<2, dim>(
                                               unit_symmetric_tensor<dim>());
                                           }) -
                d[k])
                 .norm());
  check_bound("particle_stress_force(P = 1) - d^k", worst, 1e-14);
}
