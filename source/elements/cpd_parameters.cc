#include <pg/base/exceptions.h>
#include <pg/elements/cpd_parameters.h>

namespace pg
{
  namespace Parameters
  {
    void
    Cpd::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("CPD");
      {
        prm.declare_entry(
          "C1",
          "1",
          Patterns::Double(),
          "One-neighbour (bond) constant C_1 of continuum-kinematics-inspired "
          "peridynamics (Formulation = CPD; Javili et al. 2020, eq. 23): "
          "psi_1 = C_1 (l - L)^2 / (2 L). Units N m / m^7 in 3-D, N m / m^5 "
          "in 2-D. Must be positive. Alone (C2 = C3 = 0) it is Silling's "
          "bond-based micro-elastic material with nu = 1/4 (3-D) or 1/3 "
          "(2-D); doc/cpd.md relates C_1 to E.");
        prm.declare_entry(
          "C2",
          "0",
          Patterns::Double(),
          "Two-neighbour (area) constant C_2 (eq. 24): psi_2 = C_2 (a - A)^2 "
          "/ (2 A) for the triangles of a particle and two of its mutual "
          "neighbours. Units N m / m^11 (3-D), N m / m^8 (2-D). Raises the "
          "Poisson ratio (negative values lower it).");
        prm.declare_entry(
          "C3",
          "0",
          Patterns::Double(),
          "Three-neighbour (volume) constant C_3 (eq. 25, 3-D only): psi_3 = "
          "C_3 (v - V)^2 / (2 V) for the tetrahedra of a particle and three "
          "mutual neighbours. Units N m / m^15.");
        prm.declare_entry(
          "Partial volumes",
          "false",
          Patterns::Bool(),
          "Weigh each bond by the share beta of the neighbour's volume inside "
          "the horizon, beta = (delta + h/2 - |xi|)/h clipped to [0, 1] with "
          "h the particle spacing (families then reach delta + h/2). Off: "
          "every neighbour within delta counts fully, as in the source; on a "
          "regular lattice the discrete Poisson ratio then oscillates with "
          "delta/h (doc/cpd.md).");
      }
      prm.leave_subsection();
    }



    void
    Cpd::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("CPD");
      {
        C1              = prm.get_double("C1");
        C2              = prm.get_double("C2");
        C3              = prm.get_double("C3");
        partial_volumes = prm.get_bool("Partial volumes");
      }
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace pg
