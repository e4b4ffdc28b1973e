#ifndef pg_problem_h
#define pg_problem_h

#include <pg/base/global.h>
#include <pg/base/parameters.h>
#include <pg/history/quadrature_point_history.h>
#include <pg/postprocess/run_summary.h>

#include <deal.II/base/mpi.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace pg
{
  /**
   * A quasi-static, geometrically nonlinear problem on a mesh whose cells are
   * Q1 finite elements or meshfree PG cells sharing their vertices
   * (architecture.md section 3): setup, load stepping with Newton's method
   * and the consistent tangent, output.
   */
  template <int dim>
  class Problem
  {
  public:
    /**
     * @p out receives the progress report (printed on rank 0 only); it
     * contains no wall times, so tests can compare it.
     */
    Problem(const Parameters::AllParameters<dim> &parameters,
            const MPI_Comm                        mpi_communicator,
            std::ostream                         &out,
            const bool                            restart = false);
    ~Problem();

    /**
     * Run all load steps. Throws with a clear message on bad input or when
     * a load step does not converge after 'Maximum step cuts' cuts; the
     * files of the steps computed so far and summary.json stay on disk.
     */
    void
    run();

    const RunSummary &
    summary() const;

    /**
     * The point history of this rank's elements (committed: the state of
     * the last accepted step; doc/architecture.md, "History"), for tests.
     */
    const QuadraturePointHistory &
    history() const;

  private:
    class Implementation;
    std::unique_ptr<Implementation> implementation;
  };

  /**
   * Declare all parameters of a @p dim dimensional run in @p prm.
   */
  template <int dim>
  void
  declare_all_parameters(ParameterHandler &prm);

  /**
   * What `pg_solve file.prm` does: read 'Dimension', parse the file, run
   * (with @p restart: continue from the checkpoint in the output directory,
   * `pg_solve --restart file.prm`). Returns the summary.
   */
  RunSummary
  run_parameter_file(const std::string &filename,
                     const MPI_Comm     mpi_communicator,
                     std::ostream      &out,
                     const bool         restart = false);
} // namespace pg

#endif
