// J2 plasticity through the whole Problem (FEM H1 and H1P0, VCBCPBG V5sn
// Unl and UnlP0, VCPPG V3sn Unl): the unit cube (distorted mesh,
// 3 x 3 x 3 cells) on the symmetry planes x = 0, y = 0, z = 0, stretched to
// u_x = 0.1 on x = 1 in 10 load steps with free lateral faces, with the
// necking material of §7.3.5 (E 206.9, nu 0.29, sigma_y0 0.45, sigma_inf
// 1.165, H 0.13, delta 16.93). The deformation is homogeneous, so every
// formulation that passes the patch test must give at every step the
// material point's answer: F = diag(lambda, lambda_l, lambda_l) with
// P_22(F) = 0 solved at the point (with the committed state of the
// previous step). Checked for each formulation:
//  1. the reaction on x = 1 against P_11 of the point at u_x = 0.1 (the
//     cube's face has area 1; plastic from the first step on), relative to
//     1e-8;
//  2. the lateral displacement of the corner (1, 1, 1) against lambda_l - 1;
//  3. Newton converges quadratically in every (plastic) step: the last
//     pair of relative residuals with r_k <= 1e-3 and r_k+1 above round-off
//     (1e-13) has r_k+1 <= 200 r_k^2 (measured: FEM and PBG about 1.5
//     r_k^2, UnlP0 5 to 10, PPG about 50; a linear rate rho would give
//     rho / r_k >= 1e3 rho).

#include <pg/materials/material.h>

#include "../tests.h"
#include "problem_fixture.h"

#include <sstream>

using namespace pg;

const std::string material_text = R"(
subsection Material
  set Model                    = J2 plasticity
  set Young's modulus          = 206.9
  set Poisson's ratio          = 0.29
  set Initial yield stress     = 0.45
  set Saturation yield stress  = 1.165
  set Linear hardening modulus = 0.13
  set Saturation exponent      = 16.93
end
)";

const std::string cube_text = R"(
subsection Geometry
  set Mesh          = hyper rectangle
  set Lower corner  = 0, 0, 0
  set Upper corner  = 1, 1, 1
  set Subdivisions  = 3, 3, 3
  set Distortion    = 0.2
end
)";

/** P_11 and lambda_l of every step at the material point. */
std::vector<std::pair<double, double>>
material_point(const unsigned int steps, const double final_stretch)
{
  ParameterHandler prm;
  declare_all_parameters<3>(prm);
  prm.parse_input_from_string("set Dimension = 3\n" + cube_text +
                              material_text);
  Parameters::AllParameters<3> all;
  all.parse_parameters(prm);
  const auto          material = Materials::create_material<3>(all.material);
  const unsigned int  n        = material->n_state_variables();
  std::vector<double> committed(n), trial(n);
  material->initialize_state(make_array_view(committed));

  std::vector<std::pair<double, double>> answers;
  double                                 lateral = 1.;
  for (unsigned int step = 1; step <= steps; ++step)
    {
      const double stretch = 1. + (final_stretch - 1.) * step / steps;
      Tensor<2, 3> F, P;
      Tensor<4, 3> A;
      for (unsigned int it = 0; it < 50; ++it)
        {
          F[0][0] = stretch;
          F[1][1] = F[2][2] = lateral;
          material->evaluate_with_state(F,
                                        make_array_view(committed),
                                        make_array_view(trial),
                                        P,
                                        &A);
          if (std::abs(P[1][1]) < 1e-15)
            break;
          // d P_22 / d lambda_l with F_22 = F_33 = lambda_l
          lateral -= P[1][1] / (A[1][1][1][1] + A[1][1][2][2]);
        }
      committed = trial;
      answers.emplace_back(P[0][0], lateral);
    }
  return answers;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const unsigned int steps  = 10;
  const auto         points = material_point(steps, 1.1);

  for (const std::string code : {"FEM",
                                 "FEM H1P0",
                                 "VCBCPBG V5sn Unl",
                                 "VCBCPBG V5sn UnlP0",
                                 "VCPPG V3sn Unl"})
    {
      const std::string text = R"(
set Dimension = 3
)" + cube_text + R"(
subsection Discretization
  set Formulation = )" + code + R"(
end
)" + material_text + R"(
subsection Boundary conditions
  set Symmetry  = 0, 2, 4
  set Dirichlet = 1: x
  subsection Prescribed displacement
    set Function expression = 0.1 * t; 0; 0
  end
end
subsection Loading
  set Load steps = 10
end
subsection Newton
  set Relative tolerance = 1e-13
  set Absolute tolerance = 1e-14
end
subsection Output
  set Directory = output_)" + std::to_string(code.size()) +
                               R"(
  set VTU       = false
  set Points    = corner: 1, 1, 1
end
)";
      std::ostringstream screen;
      const RunSummary   summary = run_problem<3>(text, screen);
      deallog << code << ": converged " << (summary.converged ? "yes" : "no")
              << ", load steps " << summary.load_steps << std::endl;
      const double reaction = std::abs(summary.reactions.at(1)[0]);
      print_bound("  |reaction_x - P_11| / P_11 at u_x = 0.1",
                  reaction / points.back().first - 1.,
                  1e-8);
      print_bound("  |u_y(corner) - (lambda_l - 1)|",
                  summary.points.at(0).second[1] - (points.back().second - 1.),
                  1e-10);
      // quadratic convergence: the last pair of relative residuals with
      // r_k <= 1e-3 and r_k+1 above round-off (1e-13) has r_k+1 <= 200 r_k^2
      // (a linear rate rho would give rho / r_k >= 1e3 rho)
      unsigned int quadratic_steps = 0;
      for (const auto &r : summary.newton_residuals)
        for (unsigned int k = r.size() - 1; k >= 2; --k)
          if (r[k] > 1e-13 * r[0] && r[k - 1] <= 1e-3 * r[0])
            {
              if (r[k] / r[0] <= 200. * std::pow(r[k - 1] / r[0], 2))
                ++quadratic_steps;
              break;
            }
      deallog << "  Newton quadratic in every load step: "
              << (quadratic_steps == summary.newton_residuals.size() ? "yes" :
                                                                       "NO")
              << " (" << summary.newton_residuals.size() << " steps)"
              << std::endl;
      print_rounded("  P_11 at u_x = 0.1", points.back().first, 4);
    }
}
