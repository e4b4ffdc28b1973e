#ifndef pg_elements_discretization_parameters_h
#define pg_elements_discretization_parameters_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

// The parameters of the discretization (subsection "Discretization"):
// the formulation code, the shape functions and the families.

namespace pg
{
  namespace Parameters
  {
    /** Subsection "Discretization". */
    struct Discretization
    {
      /** The dissertation's formulation code (Table 7.1), or FEM. */
      std::string formulation;
      /** MTE1 | MLS1 | WLS1 | WTE1 */
      std::string shape_functions;
      /**
       * delta^k = factor x local particle spacing h^k ('Horizon factor'); 0
       * if 'Horizon' is set.
       */
      double horizon_factor;
      /** Absolute horizon delta ('Horizon', length); 0: use the factor. */
      double horizon;
      /** > 0: the N nearest particles instead of a horizon. */
      unsigned int nearest_neighbours;
      /** omega = |dX|^(-2n). */
      double weight_exponent;
      /**
       * Peridigm's hourglass coefficient alpha of the U1 families (0: no
       * hourglass force), elements/u1_stabilisation.h.
       */
      double hourglass_coefficient = 0;
      /**
       * U1SIG: the master's weight in the MLS1 second derivatives is that
       * of a member at this distance (units of the shortest bond).
       */
      double self_weight_distance = 1e-3;
      /**
       * 'Quadrature weights = particle volumes': the PBG Unl weights scaled
       * so that they add up to each particle's volume
       * (FamilyElements::use_particle_volume_weights()).
       */
      bool particle_volume_weights = false;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace pg

#endif
