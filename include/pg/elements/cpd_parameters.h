#ifndef pg_elements_cpd_parameters_h
#define pg_elements_cpd_parameters_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>


// The constants of the CPD interactions (subsection "CPD"), used by
// pg/elements/cpd_interactions.h.

namespace pg
{
  namespace Parameters
  {
    /**
     * Subsection "CPD": the constants of continuum-kinematics-inspired
     * peridynamics (Formulation = CPD).
     */
    struct Cpd
    {
      double C1, C2, C3;
      bool   partial_volumes;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace pg

#endif
