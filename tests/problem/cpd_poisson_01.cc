// The effective Poisson ratio of CPD (Javili et al. 2020, section 4.3;
// benchmarks C-4 and C-5) at the centre of a strip (2-D,
// prm/cpd_poisson_strip.prm) and a bar (3-D, prm/cpd_poisson_bar_3d.prm)
// stretched by 0.1 % with free lateral surfaces.
//
// Bond-based (C2 = C3 = 0): on a regular lattice the linearised bond
// energy gives the cubic elastic constants C11 ~ sum beta xi_x^4 / |xi|^3
// and C12 ~ sum beta xi_x^2 xi_y^2 / |xi|^3 over the bonds of a point, so
// nu = C12 / C11 in 2-D (purely two-dimensional) and C12 / (C11 + C12) in
// 3-D. With the continuum integral instead of the lattice sum these are 1/3
// and 1/4. The test computes the lattice sums itself (with and without
// partial volumes) and asserts that the measured nu matches them; then
// that nu rises monotonically with C2/C1 (2-D) and C3/C1 (3-D) towards the
// incompressible limits 1 and 1/2, and falls below the bond-based value
// for C2 < 0.

#include "../tests.h"
#include "problem_fixture.h"

#include <cmath>

/** nu of the lattice sums for horizon factor @p f (partial volumes: pv). */
double
lattice_poisson_ratio(const unsigned int dim, const double f, const bool pv)
{
  const int R   = static_cast<int>(f) + 2;
  double    c11 = 0, c12 = 0;
  for (int i = -R; i <= R; ++i)
    for (int j = -R; j <= R; ++j)
      for (int k = (dim == 3 ? -R : 0); k <= (dim == 3 ? R : 0); ++k)
        {
          const double L = std::sqrt(1. * i * i + j * j + k * k);
          if (L == 0)
            continue;
          const double beta =
            pv ? std::clamp(f + 0.5 - L, 0., 1.) : (L <= f ? 1. : 0.);
          c11 += beta * std::pow(i, 4) / std::pow(L, 3);
          c12 += beta * i * i * j * j / std::pow(L, 3);
        }
  return dim == 2 ? c12 / c11 : c12 / (c11 + c12);
}



template <int dim>
double
measured_poisson_ratio(const std::string &overrides)
{
  const std::string    file = dim == 2 ? "/../../prm/cpd_poisson_strip.prm" :
                                         "/../../prm/cpd_poisson_bar_3d.prm";
  std::ostringstream   screen;
  const pg::RunSummary s =
    run_problem<dim>(read_file(SOURCE_DIR + file) + overrides, screen);
  std::map<std::string, std::vector<double>> u(s.points.begin(),
                                               s.points.end());
  const double strain_x = (u["right"][0] - u["left"][0]) / 1.;
  const double strain_y = (u["top"][1] - u["bottom"][1]) / 0.5;
  return -strain_y / strain_x;
}



std::string
cpd(const std::string &entries)
{
  return "subsection CPD\n" + entries + "\nend\n";
}



std::string
number(const double x, const int digits = 4)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  deallog << "2-D strip, bond-based: nu measured / lattice sum" << std::endl;
  for (const bool pv : {false, true})
    for (const double f : {3.01, 5.01})
      {
        const double nu = measured_poisson_ratio<2>(
          "subsection Discretization\n set Horizon factor = " +
          std::to_string(f) + "\nend\n" +
          cpd(pv ? "set Partial volumes = true" : ""));
        const double expected = lattice_poisson_ratio(2, f, pv);
        deallog << "  delta/h = " << f << (pv ? ", partial volumes" : "")
                << ": lattice sum " << number(expected, 3) << ", ";
        print_bound("|nu - lattice sum|", nu - expected, 0.003);
      }

  deallog << "2-D strip, delta = 3.01 h: nu against C2/C1" << std::endl;
  double previous = -1;
  for (const double C2 : {-2., 0., 10., 100., 1000.})
    {
      const double nu =
        measured_poisson_ratio<2>(cpd("set C2 = " + std::to_string(C2)));
      deallog << "  C2/C1 = " << C2 << ": nu = " << number(nu, 3)
              << (nu > previous ? ", increasing" : ", NOT increasing")
              << std::endl;
      previous = nu;
    }
  print_bound("  1 - nu(C2/C1 = 1000)", 1 - previous, 0.1);

  deallog << "3-D bar, bond-based, delta = 1.51 h: lattice sum "
          << number(lattice_poisson_ratio(3, 1.51, false), 3) << ", ";
  const double nu3 = measured_poisson_ratio<3>("");
  print_bound("|nu - lattice sum|",
              nu3 - lattice_poisson_ratio(3, 1.51, false),
              0.005);
  deallog << "3-D bar: nu against C3/C1" << std::endl;
  previous = -1;
  for (const double C3 : {0., 5e3, 5e4, 5e6})
    {
      const double nu =
        measured_poisson_ratio<3>(cpd("set C3 = " + std::to_string(C3)));
      deallog << "  C3/C1 = " << C3 << ": nu = " << number(nu, 3)
              << (nu > previous ? ", increasing" : ", NOT increasing")
              << std::endl;
      previous = nu;
    }
  print_bound("  1/2 - nu(C3/C1 = 5e6)", 0.5 - previous, 0.005);
}
