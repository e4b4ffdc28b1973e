#ifndef pg_analysis_dynamic_analysis_h
#define pg_analysis_dynamic_analysis_h

#include <pg/analysis/analysis.h>
#include <pg/solvers/mechanical_system.h>
#include <pg/solvers/time_integration.h>

namespace pg
{
  namespace Analysis
  {
    /**
     * 'Time/Integrator' leapfrog or newmark (with 'Analysis/Type =
     * static'): the initial conditions ('Initial displacement', 'Initial
     * velocity'), the masses (lumped, and consistent for Newmark), the
     * time loop of TimeStepper with the Leapfrog or Newmark integrator,
     * and the energy account in statistics.txt and summary.dynamics; at
     * the end particles.txt, the nodal stresses and the files.
     */
    template <int dim>
    class DynamicAnalysis : public Interface<dim>
    {
    public:
      using Interface<dim>::Interface;

      void
      run() override;

      /**
       * The energy columns (kinetic energy, internal, external and support
       * work, energy balance) and the disorder of time @p t in the
       * statistics table and summary.dynamics: the
       * ProblemView::add_dynamic_statistics of a dynamic run.
       */
      void
      add_statistics(const double t);

    private:
      /**
       * The disorder indicator of the particles at the current state: the
       * deviation of u from its local linear fit over each family
       * (TimeIntegration::local_fit_deviation), relative to the RMS of the
       * initial displacement about its mean.
       */
      double
      particle_disorder() const;

      /** The masses of the time integrators. */
      MassMatrices              masses;
      TimeIntegration::Energies energies;
      /** RMS of the initial particle displacement about its mean. */
      double disorder_reference = 0;
      /**
       * The positions, volumes and neighbours (family members but the
       * particle itself) of all particles, for particle_disorder(): set
       * once in run().
       */
      std::vector<Point<dim>>                disorder_positions;
      std::vector<double>                    disorder_volumes;
      std::vector<std::vector<unsigned int>> disorder_neighbours;
    };
  } // namespace Analysis
} // namespace pg

#endif
