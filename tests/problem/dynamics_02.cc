// Implicit Newmark for the mixed formulations whose pressure (and
// dilatation) are global unknowns without mass: U2P1C, Unl+P1C (nodal p
// and Theta) and IUnlP0 (a pressure per family, nu = 0.5), beside the
// condensed UnlP0 and FEM Q1P0.
//
// The problem is a shear wave that is exact for every Poisson's ratio,
// the incompressible limit included: a strip 0 <= x <= 1, 0 <= y <= 1/4,
// clamped at x = 0, on rollers (u_x = 0) at y = 0 and y = 1/4, started
// undeformed with the velocity of its first transverse mode,
// v_y = A omega sin(pi x/2). Then u_x = 0, div u = 0, the pressure stays
// 0, and u_y = A sin(pi x/2) sin(omega t) with omega = pi/2 c_s,
// c_s = sqrt(mu/rho) = 1 (mu = rho = 1): period T = 4, whatever the bulk
// modulus. A = 0.01 keeps the neo-Hooke response linear to O(A^2). (The
// start from rest in the mode's displacement is not used: the discrete PG
// dilatation of that field is not exactly 1, and with K = 5000 mu its
// volumetric stress inverts families in the first step.)
//
// (1) At t = T/2 the exact tip u_y is 0; a relative frequency error eps
// gives u_y(tip) = -A sin(pi eps), so eps = -u_y/(pi A). Each mixed
// formulation must not lock (|eps| < 0.05; the displacement Unl at
// nu = 0.4999 has 0.10), keep the energy balance of the average
// acceleration rule to round-off, and keep its energy in the mode: at T/2
// (phase pi (1 + eps)) E_kin = E_kin(0) cos^2(pi eps) within 1 % (the
// start velocity is not exactly a discrete mode: PPG UnlP0 is off by
// 1.5e-3, the others by less than 1e-3).
// (2) IUnlP0 at nu = 0.5 is the limit of UnlP0 (K = 5000 mu here): the
// frequency errors agree within 1e-3.
// (3) U2P1C converges: eps falls by at least 4 from 16 x 4 to 32 x 8 cells.

#include "../tests.h"
#include "problem_fixture.h"

#include <algorithm>
#include <map>

namespace
{
  std::string
  shear_wave(const std::string &formulation,
             const std::string &material,
             const unsigned int n_x)
  {
    return "set Dimension = 2\n"
           "subsection Geometry\n"
           "  set Lower corner = 0, 0\n"
           "  set Upper corner = 1, 0.25\n"
           "  set Subdivisions = " +
           std::to_string(n_x) + ", " + std::to_string(n_x / 4) +
           "\nend\n"
           "subsection Discretization\n"
           "  set Formulation = " +
           formulation +
           "\nend\n"
           "subsection Material\n"
           "  set Model = isochoric-volumetric neo-Hooke\n" +
           material +
           "  set Density = 1\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet = 0: xy, 2: x, 3: x\n"
           "end\n"
           "subsection Linear solver\n"
           "  set Type = direct\n"
           "end\n"
           "subsection Time\n"
           "  set Integrator = newmark\n"
           "  set Time step = 0.02\n"
           "  set End time = 2\n"
           "  set Output interval = 0.1\n"
           "  subsection Initial velocity\n"
           "    set Function constants  = A=0.01\n"
           "    set Function expression = 0; A*pi/2*sin(pi/2*x)\n"
           "  end\n"
           "end\n"
           "subsection Output\n"
           "  set VTU    = false\n"
           "  set Points = tip: 1, 0.125\n"
           "end\n";
  }

  // mu = 1 in every case; K = 5000 mu is nu = 0.4999
  const std::string nearly_incompressible =
    "  set Shear modulus = 1\n  set Bulk modulus = 5000\n";
  const std::string incompressible =
    "  set Young's modulus = 3\n  set Poisson's ratio = 0.5\n";
  const double A = 0.01;

  /** The relative frequency error from the tip at T/2. */
  double
  frequency_error(const pg::RunSummary &s)
  {
    return -s.points[0].second[1] / (numbers::PI * A);
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::ostringstream screen;

  // (1) half a period of every mixed formulation
  std::map<std::string, double> eps;
  for (const auto &[formulation, material] :
       std::vector<std::pair<std::string, std::string>>{
         {"FEM Q1P0", nearly_incompressible},
         {"VCBCPBG V5sn UnlP0", nearly_incompressible},
         {"VCBCPPG V3sn UnlP0", nearly_incompressible},
         {"VCPBG U2P1C", nearly_incompressible},
         {"VCPBG Unl+P1C", nearly_incompressible},
         {"VCPBG IUnlP0", incompressible},
         {"VCPPG IUnlP0", incompressible}})
    {
      const pg::RunSummary s =
        run_problem<2>(shear_wave(formulation, material, 16), screen);
      const auto  &d = s.dynamics;
      const double E_max =
        *std::max_element(d.kinetic.begin(), d.kinetic.end());
      double max_balance = 0;
      for (const double b : d.balance)
        max_balance = std::max(max_balance, std::abs(b));
      eps[formulation] = frequency_error(s);
      deallog << formulation << ": " << d.n_steps << " steps to T/2"
              << std::endl;
      print_bound("  |relative frequency error|", eps[formulation], 0.05);
      print_bound("  max |E balance| / max E_kin", max_balance / E_max, 1e-10);
      // the mode at the phase pi (1 + eps): E_kin = E_kin(0) cos^2(pi eps)
      const double phase = numbers::PI * eps[formulation];
      print_bound("  E_kin(T/2) / (E_kin(0) cos^2(pi eps)) - 1",
                  d.kinetic.back() /
                      (d.kinetic.front() * std::cos(phase) * std::cos(phase)) -
                    1.,
                  1e-2);
      print_bound("  |u_x(tip)| / A", s.points[0].second[0] / A, 1e-4);
    }
  // the displacement formulation locks: its frequency is far too high
  {
    const pg::RunSummary s =
      run_problem<2>(shear_wave("VCBCPBG V5sn Unl", nearly_incompressible, 16),
                     screen);
    deallog << "VCBCPBG V5sn Unl (locks): relative frequency error > 0.05: "
            << (frequency_error(s) > 0.05 ? "yes" : "NO") << std::endl;
  }

  // (2) IUnlP0 = the incompressible limit of UnlP0
  print_bound("PBG: |eps(IUnlP0) - eps(UnlP0)|",
              eps["VCPBG IUnlP0"] - eps["VCBCPBG V5sn UnlP0"],
              1e-3);
  print_bound("PPG: |eps(IUnlP0) - eps(UnlP0)|",
              eps["VCPPG IUnlP0"] - eps["VCBCPPG V3sn UnlP0"],
              1e-3);

  // (3) U2P1C converges under refinement
  {
    const pg::RunSummary s =
      run_problem<2>(shear_wave("VCPBG U2P1C", nearly_incompressible, 32),
                     screen);
    print_bound("U2P1C: eps(32 x 8) / eps(16 x 4)",
                frequency_error(s) / eps["VCPBG U2P1C"],
                0.25);
  }
}
