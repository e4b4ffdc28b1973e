// 'Discretization/Quadrature weights = particle volumes' (issue 45,
// deliverable 5): the PBG Unl family weights V^k V^j / V^{H^k} (eq. 4.30)
// scaled so that the weights at every particle add up to its volume
// (FamilyElements::use_particle_volume_weights()).
//
// 1. The scaled weights, summed over the built tables of a 20 x 20 mesh
//    of [-1, 1]^2 with interior vertices moved by up to 0.3 of the spacing,
//    give each particle its volume to 1e-12, on the surface too; with
//    eq. 4.30 the surface particles get about 0.7 of theirs (printed, 2
//    digits).
// 2. The linear patch test (B-4) on the same mesh: the VC codes, built
//    with the same weights, stay exact to round-off, alone and coupled to
//    Q1 cells (meshfree right half), for Unl, UnlP0, Unl+P1C, U1SUnl and
//    U2. Uncorrected BCPBG Unl is not exact with either weights (printed).
// 3. Codes without member points (PPG, U1) are refused with a message.

#include <pg/base/formulation_code.h>
#include <pg/elements/family_elements.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include "../tests.h"
#include "problem_fixture.h"

std::string
patch_test(const std::string &formulation,
           const std::string &region,
           const std::string &weights)
{
  return read_file(SOURCE_DIR "/../../prm/linear_patch_test.prm") +
         "subsection Discretization\n  set Formulation = " + formulation +
         "\n  set Quadrature weights = " + weights +
         "\nend\nsubsection Geometry\n  set Meshfree region = " + region +
         "\nend\nsubsection Output\n  set VTU = false\nend\n";
}



/** The mean over the surface particles of (sum of the weights at j) / V^j,
 * and the largest |sum / V^j - 1| over all particles. */
std::pair<double, double>
weight_sums(const bool particle_volumes)
{
  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_cube(tria, 20, -1, 1);
  GridTools::distort_random(0.3, tria, true, 7);
  FESystem<2>   fe(FE_Q<2>(1), 2);
  DoFHandler<2> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  pg::ParticleSet<2> particles;
  particles.reinit(dof_handler, std::vector<bool>(tria.n_active_cells(), true));
  pg::FamilySet<2> families;
  families.reinit(particles, 2.51, 0);
  pg::FamilyElements<2> elements(particles,
                                 families,
                                 pg::parse_formulation_code("PBG Unl noBC"),
                                 pg::ShapeFunctions::Base::mte1,
                                 1.);
  if (particle_volumes)
    elements.use_particle_volume_weights();
  elements.initialize();
  const unsigned int     n = particles.n_particles();
  std::vector<double>    s(n, 0.);
  pg::QuadratureTable<2> table;
  for (unsigned int k = 0; k < n; ++k)
    {
      elements.build(k, table);
      const auto members = families.members(k);
      for (unsigned int q = 0; q < members.size(); ++q)
        s[members[q]] += table.weights[q];
    }
  double       surface = 0, largest = 0;
  unsigned int n_surface = 0;
  for (unsigned int j = 0; j < n; ++j)
    {
      s[j] /= particles.volume(j);
      largest           = std::max(largest, std::abs(s[j] - 1.));
      const Point<2> &x = particles.position(j);
      if (std::max(std::abs(x[0]), std::abs(x[1])) > 1 - 1e-12)
        {
          surface += s[j];
          ++n_surface;
        }
    }
  return {surface / n_surface, largest};
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  for (const bool particle_volumes : {false, true})
    {
      const auto [surface, largest] = weight_sums(particle_volumes);
      deallog << (particle_volumes ? "particle volumes" : "eq. 4.30")
              << ": mean weight sum / volume on the surface "
              << std::setprecision(2) << std::fixed << surface
              << std::defaultfloat << std::setprecision(6) << std::endl;
      if (particle_volumes)
        print_bound("  max |weight sum / volume - 1|", largest, 1e-12);
    }

  std::ostringstream screen;
  for (const std::string region : {"all", "box 0, -1.1 : 1.1, 1.1"})
    {
      deallog << "Patch test, particle volumes, meshfree region = " << region
              << std::endl;
      for (const std::string code : {"VCBCPBG V5sn Unl",
                                     "VCPBG V5p Unl noBC",
                                     "VCBCPBG V5sn UnlP0",
                                     "VCBCPBG V5sn Unl+P1C",
                                     "VCPBG V5sn U1SUnl",
                                     "VCPBG V5sn U2"})
        {
          const pg::RunSummary s =
            run_problem<2>(patch_test(code, region, "particle volumes"),
                           screen);
          const bool exact = s.L2_relative < 1e-11 && s.H1_relative < 1e-11;
          deallog << "  " << std::left << std::setw(20) << code << std::right
                  << " round-off: " << (exact ? "yes" : "NO") << std::endl;
          if (!exact)
            deallog << "    L2 " << s.L2_relative << " H1 " << s.H1_relative
                    << std::endl;
        }
    }

  deallog << "Not exact without VC (relative L2 error):" << std::endl;
  for (const std::string weights : {"horizon", "particle volumes"})
    {
      const pg::RunSummary s =
        run_problem<2>(patch_test("BCPBG Unl", "all", weights), screen);
      print_rounded("  BCPBG Unl, " + weights, s.L2_relative, 2);
    }

  deallog << "Refused:" << std::endl;
  for (const std::string code : {"VCBCPPG V3sn Unl", "VCPBG V5sn U1"})
    try
      {
        run_problem<2>(patch_test(code, "all", "particle volumes"), screen);
        deallog << "  " << code << ": no error (wrong)" << std::endl;
      }
    catch (ExceptionBase &e)
      {
        deallog << "  " << code << ": " << exception_message(e) << std::endl;
      }
}
