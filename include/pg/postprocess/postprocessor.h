#ifndef pg_postprocess_postprocessor_h
#define pg_postprocess_postprocessor_h

#include <pg/base/global.h>
#include <pg/postprocess/problem_view.h>

#include <deal.II/base/table_handler.h>

#include <memory>
#include <vector>

namespace pg
{
  struct RunSummary;

  namespace Postprocess
  {
    /** The (sub)step being postprocessed. */
    struct Step
    {
      /** Load step or time step number (0: the initial state). */
      unsigned int number = 0;
      /** Load factor, or time of a dynamic run. */
      double time = 0;
      /** Newton iterations of the step (summed over its substeps). */
      unsigned int newton_iterations = 0;
    };

    /**
     * One postprocessor (as ASPECT's Postprocess::Interface): execute()
     * after every converged step, finalize() once at the end of a static
     * run. Both read the problem through @p view only and write the
     * statistics table, the summary and their own files.
     */
    template <int dim>
    class Interface
    {
    public:
      virtual ~Interface() = default;

      virtual void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary) = 0;

      /** End-of-run work at the final @p step (default: none). */
      virtual void
      finalize(const ProblemView<dim> &view,
               const Step             &step,
               TableHandler           &statistics,
               RunSummary             &summary);
    };

    template <int dim>
    class VtuOutput;

    /**
     * The postprocessors of a run in their fixed order: point values, line
     * samples, reactions, particle fields, error norms, nodal stresses,
     * statistics, output files. The order is that of the statistics
     * columns and of the final report; the output files come last since
     * they contain everything the others computed.
     */
    template <int dim>
    class Manager
    {
    public:
      Manager();
      ~Manager();

      /** execute() of every postprocessor in order. */
      void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary);

      /** finalize() of every postprocessor in order. */
      void
      finalize(const ProblemView<dim> &view,
               const Step             &step,
               TableHandler           &statistics,
               RunSummary             &summary);

      /**
       * The writer of statistics.txt, summary.json, timing.txt and the
       * VTU/PVD files, also used on its own (a failed step, eigenmodes).
       */
      VtuOutput<dim> &
      output();

    private:
      std::vector<std::unique_ptr<Interface<dim>>> postprocessors;
      VtuOutput<dim>                              *output_writer = nullptr;
    };
  } // namespace Postprocess
} // namespace pg

#endif
