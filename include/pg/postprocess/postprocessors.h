#ifndef pg_postprocess_postprocessors_h
#define pg_postprocess_postprocessors_h

#include <pg/base/global.h>
#include <pg/postprocess/postprocessor.h>

#include <string>
#include <utility>
#include <vector>

namespace pg
{
  namespace Postprocess
  {
    /**
     * summary.points: the displacement at each of 'Output/Points' (the Q1
     * interpolant); prints them at the end of the run.
     */
    template <int dim>
    class PointValues : public Interface<dim>
    {
    public:
      void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary) override;
      void
      finalize(const ProblemView<dim> &view,
               const Step             &step,
               TableHandler           &statistics,
               RunSummary             &summary) override;
    };

    /**
     * summary.line_samples and displacement_along_lines.txt: the
     * displacement at the samples of 'Output/Lines'.
     */
    template <int dim>
    class LineSamples : public Interface<dim>
    {
    public:
      void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary) override;
    };

    /**
     * summary.reactions and summary.box_reactions: f_int - f_ext summed
     * over the prescribed components of the vertices of each Dirichlet
     * boundary id and each 'Dirichlet boxes' entry; printed at the end.
     */
    template <int dim>
    class Reactions : public Interface<dim>
    {
    public:
      void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary) override;
      void
      finalize(const ProblemView<dim> &view,
               const Step             &step,
               TableHandler           &statistics,
               RunSummary             &summary) override;
    };

    /**
     * At the end of the run: the gradient oscillation indicator of the
     * particles (summary.gradient_oscillation, printed) and particles.txt.
     */
    template <int dim>
    class ParticleFields : public Interface<dim>
    {
    public:
      void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary) override;
      void
      finalize(const ProblemView<dim> &view,
               const Step             &step,
               TableHandler           &statistics,
               RunSummary             &summary) override;

      /**
       * particles.txt: position, displacement, deformation gradient @p F
       * and volume of every particle (rank 0).
       */
      static void
      write_table(const ProblemView<dim>            &view,
                  const std::vector<Tensor<2, dim>> &F);
    };

    /**
     * With 'Compute errors': the L2, H1 and energy norms of the error
     * (eq. 7.3) at every step; the relative ones printed at the end.
     */
    template <int dim>
    class ErrorNorms : public Interface<dim>
    {
    public:
      void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary) override;
      void
      finalize(const ProblemView<dim> &view,
               const Step             &step,
               TableHandler           &statistics,
               RunSummary             &summary) override;

      /** The error norms of the current state into @p summary. */
      static void
      compute(const ProblemView<dim> &view, RunSummary &summary);
    };

    /**
     * At the end of the run: the Cauchy stress at the vertices from the FE
     * side (average of the adjacent Q1 cells) and the PG side (particle
     * value): summary.point_stresses, the interface jump and
     * stress_along_boundaries.txt.
     */
    template <int dim>
    class NodalStresses : public Interface<dim>
    {
    public:
      void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary) override;
      void
      finalize(const ProblemView<dim> &view,
               const Step             &step,
               TableHandler           &statistics,
               RunSummary             &summary) override;

      /** The same with the particle deformation gradients @p particle_F. */
      static void
      write(const ProblemView<dim>            &view,
            const std::vector<Tensor<2, dim>> &particle_F,
            RunSummary                        &summary);
    };

    /**
     * The columns of statistics.txt: step, load factor (time), Newton
     * iterations, residual, [energies], point displacements, [errors],
     * wall time; prints the total Newton iterations at the end.
     */
    template <int dim>
    class Statistics : public Interface<dim>
    {
    public:
      void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary) override;
      void
      finalize(const ProblemView<dim> &view,
               const Step             &step,
               TableHandler           &statistics,
               RunSummary             &summary) override;
    };

    /**
     * The files of a step: summary.timing, statistics.txt, summary.json,
     * timing.txt (rank 0) and, with 'VTU', solution_*.vtu and
     * particles_*.vtu with their PVD records.
     */
    template <int dim>
    class VtuOutput : public Interface<dim>
    {
    public:
      void
      execute(const ProblemView<dim> &view,
              const Step             &step,
              TableHandler           &statistics,
              RunSummary             &summary) override;
      void
      finalize(const ProblemView<dim> &view,
               const Step             &step,
               TableHandler           &statistics,
               RunSummary             &summary) override;

      /** Write the files of @p step at load factor (time) @p time. */
      void
      write(const ProblemView<dim> &view,
            const unsigned int      step,
            const double            time,
            const TableHandler     &statistics,
            RunSummary             &summary);

      /**
       * The PVD records (boost serialization, for checkpoints; the archive
       * needs boost/serialization/utility.hpp and vector.hpp).
       */
      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int /*version*/)
      {
        archive &pvd_cells &pvd_particles;
      }

    private:
      /** (time, file) of every VTU record written, for the PVD files. */
      std::vector<std::pair<double, std::string>> pvd_cells, pvd_particles;
    };

    /**
     * summary.assembly_cost: entries and flops of the local tangents of
     * this rank's Q1 cells and families, summed over all ranks.
     */
    template <int dim>
    void
    compute_assembly_cost(const ProblemView<dim> &view, RunSummary &summary);
  } // namespace Postprocess
} // namespace pg

#endif
