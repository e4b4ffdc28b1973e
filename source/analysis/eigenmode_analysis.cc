#include <pg/analysis/eigenmode_analysis.h>
#include <pg/analysis/eigenmodes.h>
#include <pg/dofs/field_layout.h>

#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace pg
{
  namespace Analysis
  {
    template <int dim>
    void
    EigenmodeAnalysis<dim>::run()
    {
      const auto       &access  = this->access;
      const auto       &prm     = access.parameters;
      auto             &summary = access.summary;
      const std::string failure = access.system.assemble_residual(true);
      AssertThrow(failure.empty(), ExcMessage(failure));
      // U2P1C, Unl+P1C, IUnlP0: the eigenvalues of the displacement
      // stiffness, their nodal or family pressures eliminated
      std::vector<bool> is_displacement;
      if (access.formulation.n_nodal_fields() > 0)
        {
          const FieldLayout<dim> *layout      = this->view().field_layout;
          const DoFHandler<dim>  &dof_handler = *this->view().dof_handler;
          const IndexSet          u_dofs =
            DoFTools::extract_dofs(dof_handler, layout->displacement_mask());
          is_displacement.resize(dof_handler.n_dofs());
          for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
            is_displacement[i] = u_dofs.is_element(i);
        }
      unsigned int              pressure_modes = 0;
      const std::vector<double> values =
        dense_eigenvalues(access.system.tangent(),
                          is_displacement,
                          &pressure_modes);
      summary.max_eigenvalue     = values.back();
      summary.n_zero_eigenvalues = 0;
      for (const double v : values)
        if (std::abs(v) < 1e-10 * summary.max_eigenvalue)
          ++summary.n_zero_eigenvalues;
      summary.eigenvalues.assign(
        values.begin(),
        values.begin() +
          std::min<std::size_t>(values.size(), prm.analysis.n_eigenvalues));
      summary.converged = true;

      std::ostringstream line;
      if (!is_displacement.empty())
        line << "  eigenvalues of the displacement stiffness ("
             << (access.formulation.incompressible() ?
                   "on the incompressible displacements, " +
                     std::to_string(pressure_modes) +
                     " pressure modes without a constraint" :
                   "nodal pressure and dilatation eliminated")
             << ")\n";
      line << std::setprecision(4) << "  eigenvalues: max " << values.back()
           << ", below 1e-10 max: " << summary.n_zero_eigenvalues
           << "\n  smallest non-zero:";
      for (unsigned int i = summary.n_zero_eigenvalues;
           i <
           std::min<std::size_t>(values.size(), summary.n_zero_eigenvalues + 6);
           ++i)
        line << " " << values[i];
      access.pcout << line.str() << std::endl;

      access.write_files(0, 0.);
      if (access.root)
        {
          std::ofstream table(prm.output.directory + "/eigenvalues.txt");
          table << "# index  eigenvalue (real part, ascending)\n"
                << std::setprecision(12);
          for (unsigned int i = 0; i < summary.eigenvalues.size(); ++i)
            table << i + 1 << " " << summary.eigenvalues[i] << "\n";
        }
    }



    template class EigenmodeAnalysis<2>;
    template class EigenmodeAnalysis<3>;
  } // namespace Analysis
} // namespace pg
