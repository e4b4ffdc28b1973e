#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/run_summary.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    ErrorNorms<dim>::execute(const ProblemView<dim> &view,
                             const Step             &step,
                             TableHandler &,
                             RunSummary &summary)
    {
      if (!view.parameters->compute_errors)
        return;
      view.set_load_factor(step.time);
      compute(view, summary);
    }



    template <int dim>
    void
    ErrorNorms<dim>::finalize(const ProblemView<dim> &view,
                              const Step &,
                              TableHandler &,
                              RunSummary &summary)
    {
      if (summary.have_errors)
        *view.pcout << "  errors: L2 relative = " << summary.L2_relative
                    << ", H1 relative = " << summary.H1_relative << std::endl;
    }



    template <int dim>
    void
    ErrorNorms<dim>::compute(const ProblemView<dim> &view, RunSummary &summary)
    {
      // eq. (7.3): FE cells by Gauss quadrature, particles by their volume
      // with the trial gradient at the master.
      const auto &exact     = view.parameters->exact_solution;
      const auto &particles = *view.particles;
      const auto &u_full    = *view.u; // owned cells and families
      const auto  comm      = view.mpi_communicator;
      double      e0 = 0, e1 = 0, n0 = 0, n1 = 0, eE = 0, nE = 0;
      // the energy norm of the linearised problem, G : A(1) : G
      Tensor<2, dim> P0;
      Tensor<4, dim> A0;
      view.material->evaluate(unit_symmetric_tensor<dim>(), P0, A0);
      const auto energy = [&A0](const Tensor<2, dim> &G) {
        return scalar_product(G, double_contract<2, 0, 3, 1>(A0, G));
      };
      const Quadrature<dim>            quadrature = view.cells->quadrature(3);
      FEValues<dim>                    fe_values(view.cells->mapping(),
                              *view.fe,
                              quadrature,
                              update_values | update_gradients |
                                update_quadrature_points | update_JxW_values);
      const FEValuesExtractors::Vector u(0);
      std::vector<Tensor<1, dim>>      values(quadrature.size());
      std::vector<Tensor<2, dim>>      gradients(quadrature.size());
      Vector<double>                   exact_value(dim);
      for (const auto &cell : *view.owned_fe_cells)
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_values(u_full, values);
          fe_values[u].get_function_gradients(u_full, gradients);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const Point<dim> &p = fe_values.quadrature_point(q);
              exact.vector_value(p, exact_value);
              const Tensor<2, dim> G = view.exact_displacement_gradient(p);
              for (unsigned int c = 0; c < dim; ++c)
                {
                  e0 += std::pow(exact_value(c) - values[q][c], 2) *
                        fe_values.JxW(q);
                  n0 += std::pow(exact_value(c), 2) * fe_values.JxW(q);
                }
              e1 += (G - gradients[q]).norm_square() * fe_values.JxW(q);
              n1 += G.norm_square() * fe_values.JxW(q);
              eE += energy(G - gradients[q]) * fe_values.JxW(q);
              nE += energy(G) * fe_values.JxW(q);
            }
        }
      for (const unsigned int k : *view.owned_families)
        {
          const Point<dim> &p = particles.position(k);
          const double      V = particles.volume(k);
          exact.vector_value(p, exact_value);
          for (unsigned int c = 0; c < dim; ++c)
            {
              e0 +=
                std::pow(exact_value(c) - u_full[particles.dof(k, c)], 2) * V;
              n0 += std::pow(exact_value(c), 2) * V;
            }
          const Tensor<2, dim> G = view.exact_displacement_gradient(p);
          const Tensor<2, dim> e = G - (view.particle_deformation_gradient(k) -
                                        unit_symmetric_tensor<dim>());
          e1 += e.norm_square() * V;
          n1 += G.norm_square() * V;
          eE += energy(e) * V;
          nE += energy(G) * V;
        }
      summary.have_errors = true;
      summary.L2          = std::sqrt(Utilities::MPI::sum(e0, comm));
      summary.H1          = std::sqrt(Utilities::MPI::sum(e1, comm));
      const double norm0  = std::sqrt(Utilities::MPI::sum(n0, comm));
      const double norm1  = std::sqrt(Utilities::MPI::sum(n1, comm));
      summary.L2_relative = norm0 > 0 ? summary.L2 / norm0 : summary.L2;
      summary.H1_relative = norm1 > 0 ? summary.H1 / norm1 : summary.H1;
      summary.energy = std::sqrt(std::max(0., Utilities::MPI::sum(eE, comm)));
      const double normE =
        std::sqrt(std::max(0., Utilities::MPI::sum(nE, comm)));
      summary.energy_relative =
        normE > 0 ? summary.energy / normE : summary.energy;
    }



    template class ErrorNorms<2>;
    template class ErrorNorms<3>;
  } // namespace Postprocess
} // namespace pg
