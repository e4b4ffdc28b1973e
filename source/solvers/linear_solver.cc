#include <pg/solvers/linear_solver.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

namespace pg
{
  template <int dim>
  unsigned int
  solve_linear_system(const Parameters::LinearSolver    &parameters,
                      const DoFHandler<dim>             &dof_handler,
                      const LinearAlgebra::SparseMatrix &matrix,
                      LinearAlgebra::Vector             &solution,
                      const LinearAlgebra::Vector       &rhs)
  {
    if (parameters.type == "direct")
      {
        SolverControl control(1, 0, false, false);
        TrilinosWrappers::SolverDirect::AdditionalData data(false,
                                                            "Amesos_Klu");
        TrilinosWrappers::SolverDirect                 solver(control, data);
        solver.solve(matrix, solution, rhs);
        return 0;
      }

    TrilinosWrappers::PreconditionAMG                 amg;
    TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
    std::vector<std::vector<bool>>                    constant_modes;
    DoFTools::extract_constant_modes(dof_handler,
                                     ComponentMask(),
                                     constant_modes);
    amg_data.constant_modes  = constant_modes;
    amg_data.elliptic        = (parameters.type == "cg");
    amg_data.smoother_sweeps = 2;
    amg.initialize(matrix, amg_data);

    SolverControl control(std::max<unsigned int>(1000, rhs.size()),
                          parameters.tolerance * rhs.l2_norm(),
                          false,
                          false);
    if (parameters.type == "cg")
      {
        SolverCG<LinearAlgebra::Vector> cg(control);
        cg.solve(matrix, solution, rhs, amg);
      }
    else
      {
        // right preconditioning: the stopping test sees the true residual
        // (with left preconditioning it sees the AMG-preconditioned one,
        // and Newton then needs extra steps on linear problems)
        SolverGMRES<LinearAlgebra::Vector> gmres(
          control,
          SolverGMRES<LinearAlgebra::Vector>::AdditionalData(
            100,
            /*right_preconditioning=*/true));
        gmres.solve(matrix, solution, rhs, amg);
      }
    return control.last_step();
  }



  template unsigned int
  solve_linear_system<2>(const Parameters::LinearSolver &,
                         const DoFHandler<2> &,
                         const LinearAlgebra::SparseMatrix &,
                         LinearAlgebra::Vector &,
                         const LinearAlgebra::Vector &);
  template unsigned int
  solve_linear_system<3>(const Parameters::LinearSolver &,
                         const DoFHandler<3> &,
                         const LinearAlgebra::SparseMatrix &,
                         LinearAlgebra::Vector &,
                         const LinearAlgebra::Vector &);
} // namespace pg
