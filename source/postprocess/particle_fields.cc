#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/run_summary.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    ParticleFields<dim>::execute(const ProblemView<dim> &,
                                 const Step &,
                                 TableHandler &,
                                 RunSummary &)
    {}



    template <int dim>
    void
    ParticleFields<dim>::finalize(const ProblemView<dim> &view,
                                  const Step &,
                                  TableHandler &,
                                  RunSummary &summary)
    {
      const auto &particles = *view.particles;
      if (particles.n_particles() == 0)
        return;
      // The oscillation indicator and a plain table of the particle fields
      // (for plots) at the final state; every rank knows all particles.
      const std::vector<Tensor<2, dim>> F =
        view.particle_deformation_gradients();
      double oscillation = 0, deformation = 0;
      for (unsigned int k = 0; k < F.size(); ++k)
        {
          Tensor<2, dim> mean;
          double         volume = 0;
          for (const unsigned int j : view.families->members(k))
            {
              // a mirror image's F is its original's, reflected
              Tensor<2, dim> F_j = F[particles.original(j)];
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  F_j[a][b] *=
                    particles.mirror_sign(j, a) * particles.mirror_sign(j, b);
              mean += particles.member_volume(j) * F_j;
              volume += particles.member_volume(j);
            }
          mean /= volume;
          oscillation += particles.volume(k) * (F[k] - mean).norm_square();
          deformation +=
            particles.volume(k) *
            (F[k] - Tensor<2, dim>(unit_symmetric_tensor<dim>())).norm_square();
        }
      summary.gradient_oscillation =
        deformation > 0 ? std::sqrt(oscillation / deformation) : 0.;
      write_table(view, F);

      std::ostringstream line;
      line << std::setprecision(3) << summary.gradient_oscillation;
      *view.pcout << "  gradient oscillation of the particles: " << line.str()
                  << std::endl;
    }



    template <int dim>
    void
    ParticleFields<dim>::write_table(const ProblemView<dim>            &view,
                                     const std::vector<Tensor<2, dim>> &F)
    {
      // collective, before the root test
      const Vector<double> u_all = view.gather_displacement();
      if (!view.root)
        return;
      const auto   &particles = *view.particles;
      std::ofstream table(view.parameters->output.directory + "/particles.txt");
      table << "# x y" << (dim == 3 ? " z" : "") << " u_x u_y"
            << (dim == 3 ? " u_z" : "") << " F_ij (row-major) volume\n"
            << std::setprecision(10);
      for (unsigned int k = 0; k < F.size(); ++k)
        {
          table << particles.position(k);
          for (unsigned int c = 0; c < dim; ++c)
            table << " " << u_all[particles.dof(k, c)];
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              table << " " << F[k][i][j];
          table << " " << particles.volume(k) << "\n";
        }
    }



    template class ParticleFields<2>;
    template class ParticleFields<3>;
  } // namespace Postprocess
} // namespace pg
