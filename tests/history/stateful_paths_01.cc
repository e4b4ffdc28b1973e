// The material history in every formulation (issue 46, deliverable 2), with
// the test material 'isochoric damage neo-Hooke' (stateful_split_material.h:
// isochoric-volumetric neo-Hooke whose isochoric part is degraded by
// d(kappa), kappa the largest isochoric strain measure e = W_iso / mu).
//
// 1. Its tangent against central differences of its stress (2-D plane
//    strain and 3-D; loading and unloading states; the full material and
//    the isochoric part of the split).
// 2. For every formulation of Table 7.5 a homogeneous plane strain stretch
//    F = diag(1 + g(t), 1) of the unit square, imposed on the whole
//    boundary, in three load steps g = 0.1, 0.2 (loading), 0.05
//    (unloading): the committed state at every point of every group equals
//    the closed form (kappa = e(1.2), d = d(kappa)); the Cauchy stress
//    sigma_xx at the centre (the nodal stress, from the committed state)
//    equals (1 - d) sigma_iso + p at F = diag(1.05, 1), and differs from
//    the stress with the damage of F alone (the unloading is degraded);
//    summary.json's max_damage equals d. The same in 3-D (FEM H1, H1P0,
//    VCBCPBG Unl, UnlP0), with CG and the Q1 AMG operator, and for IUnlP0
//    (nu = 0.5, F = diag(1 + g, 1 / (1 + g)), top free). CPD refuses the
//    material.
// 3. A step cut: with 'Increment limit' the material's update throws when
//    kappa would grow by more than the limit in one step, so the single
//    load step to g = 0.2 fails, is cut to t = 0.5 and grown again (the
//    linearized predictor keeps every iterate homogeneous). The
//    committed state and the displacement equal those of two plain load
//    steps bit for bit (the failed attempt left nothing behind; Unl+P1C to
//    round-off: its bubble iteration starts from the failed attempt's
//    bubble, a warm start outside the history).
// 4. A restart from the checkpoint of step 2 gives the committed state of
//    the uninterrupted run bit for bit (U1SIG: material state and the
//    kernel's F in one store).
// 5. The VTU files (cells and particles) carry the state outputs.
// 6. J2 plasticity in every formulation: a homogeneous stretch by 2 %
//    (loading, more loading, unloading) gives the same largest equivalent
//    plastic strain (summary.json) as FEM to 1e-10.

#include <pg/base/exceptions.h>
#include <pg/problem.h>

#include "../problem/problem_fixture.h"
#include "../tests.h"
#include "stateful_split_material.h"

#include <cstring>
#include <filesystem>

using namespace pg;

namespace
{
  /** g(t): 0.1, 0.2, 0.05 at t = 1/3, 2/3, 1 (a cubic through them). */
  const std::string stretch = "0.05*t + 1.125*t^2 - 1.125*t^3";

  double
  g(const double t)
  {
    return 0.05 * t + 1.125 * t * t - 1.125 * t * t * t;
  }

  /**
   * The unit square (cube: @p dim = 3) stretched by x_new = (1 + g(t)) x on
   * its whole boundary; @p incompressible: nu = 0.5 (IUnlP0), u_x given on
   * x = 0 and x = 1, u_y = 0 on y = 0, the top free (F = diag(1 + g,
   * 1 / (1 + g)), no indeterminate pressure).
   */
  std::string
  settings(const std::string &formulation,
           const unsigned int load_steps,
           const std::string &stretch_function,
           const double       increment_limit,
           const std::string &output,
           const bool         linearized_predictor = false,
           const unsigned int dim                  = 2,
           const bool         incompressible       = false,
           const std::string &extra                = "")
  {
    const bool three = (dim == 3);
    return "set Dimension = " + std::to_string(dim) +
           "\n"
           "subsection Geometry\n  set Lower corner = " +
           (three ? "0, 0, 0" : "0, 0") +
           "\n  set Upper corner = " + (three ? "1, 1, 1" : "1, 1") +
           "\n  set Subdivisions = " + (three ? "2, 2, 2" : "4, 4") +
           "\nend\n"
           "subsection Discretization\n  set Formulation = " +
           formulation +
           "\nend\n"
           "subsection Material\n  set Model = isochoric damage neo-Hooke\n"
           "  set Young's modulus = 100\n  set Poisson's ratio = " +
           (incompressible ? "0.5" : "0.3") +
           "\n"
           "  subsection isochoric damage neo-Hooke\n"
           "    set Damage strain = 0.05\n"
           "    set Increment limit = " +
           std::to_string(increment_limit) +
           "\n  end\nend\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet = " +
           (three          ? "0: xyz, 1: xyz, 2: xyz, 3: xyz, 4: xyz, 5: xyz" :
            incompressible ? "0: x, 1: x, 2: y" :
                             "0: xy, 1: xy, 2: xy, 3: xy") +
           "\n"
           "  subsection Prescribed displacement\n"
           "    set Function expression = (" +
           stretch_function + ")*x; 0" + (three ? "; 0" : "") +
           "\n  end\nend\n"
           "subsection Loading\n  set Load steps = " +
           std::to_string(load_steps) +
           (linearized_predictor ? "\n  set Predictor = linearized" : "") +
           "\nend\n"
           "subsection Newton\n  set Relative tolerance = 1e-13\n"
           "  set Absolute tolerance = 1e-12\nend\n"
           "subsection Output\n  set Points = centre: " +
           (three ? "0.5, 0.5, 0.5" : "0.5, 0.5") + "\n" + output + "end\n" +
           extra;
  }

  struct Result
  {
    RunSummary          summary;
    std::vector<double> committed;
    unsigned int        n_variables = 0;
    std::vector<double> points;
    std::string         screen;
  };

  template <int dim = 2>
  Result
  run(const std::string &parameters, const bool restart = false)
  {
    std::ostringstream       screen;
    dealii::ParameterHandler prm;
    declare_all_parameters<dim>(prm);
    prm.parse_input_from_string(parameters);
    Parameters::AllParameters<dim> all;
    all.parse_parameters(prm);
    Problem<dim> problem(all, MPI_COMM_WORLD, screen, restart);
    problem.run();
    Result result;
    result.summary     = problem.summary();
    result.committed   = problem.history().committed_values();
    result.n_variables = problem.history().n_variables();
    result.points      = result.summary.points.at(0).second;
    result.screen      = screen.str();
    return result;
  }

  Parameters::Material
  material_parameters(const bool incompressible = false)
  {
    dealii::ParameterHandler prm;
    declare_all_parameters<2>(prm);
    prm.parse_input_from_string(
      settings(incompressible ? "VCPBG IUnlP0" : "FEM",
               3,
               stretch,
               1e3,
               "",
               false,
               2,
               incompressible));
    Parameters::AllParameters<2> all;
    all.parse_parameters(prm);
    return all.material;
  }

  bool
  bitwise_equal(const std::vector<double> &a, const std::vector<double> &b)
  {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
  }



  /** max |A - dP/dF (central differences)| / |A| at F from @p committed. */
  template <int dim>
  double
  tangent_error(const Materials::IsochoricDamageNeoHooke<dim> &material,
                const Tensor<2, dim>                          &F,
                const std::vector<double>                     &committed,
                const bool                                     isochoric)
  {
    const auto evaluate =
      [&](const Tensor<2, dim> &G, Tensor<2, dim> &P, Tensor<4, dim> *A) {
        std::vector<double> trial(2);
        if (isochoric)
          material.evaluate_isochoric_with_state(G,
                                                 make_array_view(committed),
                                                 make_array_view(trial),
                                                 P,
                                                 A);
        else
          material.evaluate_with_state(G,
                                       make_array_view(committed),
                                       make_array_view(trial),
                                       P,
                                       A);
      };
    Tensor<2, dim> P;
    Tensor<4, dim> A;
    evaluate(F, P, &A);
    const double h     = 1e-6;
    double       error = 0;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        {
          Tensor<2, dim> Fp = F, Fm = F, Pp, Pm;
          Fp[c][d] += h;
          Fm[c][d] -= h;
          evaluate(Fp, Pp, nullptr);
          evaluate(Fm, Pm, nullptr);
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              error = std::max(error,
                               std::abs(A[a][b][c][d] -
                                        (Pp[a][b] - Pm[a][b]) / (2 * h)));
        }
    return error / A.norm();
  }



  template <int dim>
  void
  check_tangents(const Parameters::Material &parameters)
  {
    const Materials::IsochoricDamageNeoHooke<dim> material(parameters);
    Tensor<2, dim>                                F;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[i][j] = (i == j ? 1.1 + 0.05 * i : 0.03 * (i + 2 * j + 1));
    const double e = material.strain_measure(F);
    for (const bool isochoric : {false, true})
      {
        // loading: kappa_committed below e; unloading: above
        const double loading =
          tangent_error(material,
                        F,
                        {0.5 * e, material.damage(0.5 * e)},
                        isochoric);
        const double unloading =
          tangent_error(material,
                        F,
                        {2. * e, material.damage(2. * e)},
                        isochoric);
        print_bound(std::to_string(dim) + "d tangent " +
                      (isochoric ? "(isochoric part) " : "") +
                      "loading, relative FD error",
                    loading,
                    1e-7);
        print_bound(std::to_string(dim) + "d tangent " +
                      (isochoric ? "(isochoric part) " : "") +
                      "unloading, relative FD error",
                    unloading,
                    1e-7);
        AssertThrow(loading < 1e-7 && unloading < 1e-7, ExcInternalError());
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  // 1. the tangent
  const Parameters::Material parameters = material_parameters();
  const Materials::IsochoricDamageNeoHooke<2> material(parameters);
  check_tangents<2>(parameters);
  check_tangents<3>(parameters);

  // the closed form of the homogeneous stretch
  const auto F_of = [](const double t) {
    Tensor<2, 2> F = unit_symmetric_tensor<2>();
    F[0][0] += g(t);
    return F;
  };
  double kappa = 0;
  for (const double t : {1. / 3, 2. / 3, 1.})
    kappa = std::max(kappa, material.strain_measure(F_of(t)));
  const double       d        = material.damage(kappa);
  const double       state[2] = {kappa, d};
  const Tensor<2, 3> sigma =
    material.cauchy_stress_with_state(F_of(1.), make_array_view(state));
  const Tensor<2, 3> undamaged = material.cauchy_stress(F_of(1.));
  deallog << "closed form: kappa = " << kappa << ", d = " << d
          << ", sigma_xx = " << sigma[0][0]
          << " (with the damage of the last F alone: " << undamaged[0][0] << ")"
          << std::endl;

  // 2. every formulation: the committed state at every point, the stress
  // at the centre and summary.json's max_damage against the closed form
  const auto check = [](const std::string &label,
                        const Result      &r,
                        const double       kappa,
                        const double       d,
                        const double       sigma_xx) {
    double       state_error = 0;
    unsigned int n_points    = 0;
    for (unsigned int i = 0; i < r.committed.size(); i += r.n_variables)
      {
        state_error = std::max({state_error,
                                std::abs(r.committed[i] - kappa) / kappa,
                                std::abs(r.committed[i + 1] - d) / d});
        ++n_points;
      }
    const double stress_error =
      std::abs(r.summary.point_stresses.at(0).second[0] - sigma_xx) /
      std::abs(sigma_xx);
    double max_damage = -1;
    for (const auto &[name, value] : r.summary.state_output_maxima)
      if (name == "damage")
        max_damage = value;
    const bool ok = r.summary.converged && state_error < 1e-10 &&
                    stress_error < 1e-8 && std::abs(max_damage - d) < 1e-10 * d;
    deallog << std::left << std::setw(23) << label << std::right << " points "
            << std::setw(4) << n_points << ", values per point "
            << r.n_variables
            << ": state, sigma_xx, max_damage exact: " << (ok ? "yes" : "NO")
            << std::endl;
    if (!ok)
      deallog << "  state " << state_error << ", stress " << stress_error
              << ", max_damage " << max_damage << std::endl;
  };
  const std::string no_vtu = "  set VTU = false\n";
  for (const std::string formulation : {"FEM",
                                        "FEM Q1P0",
                                        "VCBCPBG V5sn Unl",
                                        "VCPBG V5sn U2",
                                        "VCBCPBG V5sn UnlP0",
                                        "VCPBG U2P1",
                                        "VCPBG U2P1C",
                                        "VCPBG Unl+P1C",
                                        "VCPBG U1SUnl",
                                        "VCPBG U1SIG",
                                        "VCBCPPG V3sn Unl",
                                        "VCBCPPG V3sn UnlP0"})
    try
      {
        // (the nodal-pressure codes need smaller steps under the
        // softening of the damage: their first Newton iterates invert
        // families; the grid t = k/12 still has its largest g at 2/3)
        const bool nodal_pressure =
          formulation.find("P1C") != std::string::npos;
        check(formulation,
              run(settings(formulation,
                           nodal_pressure ? 12 : 3,
                           stretch,
                           1e3,
                           no_vtu)),
              kappa,
              d,
              sigma[0][0]);
      }
    catch (const std::exception &e)
      {
        deallog << formulation << " failed: " << e.what() << std::endl;
      }
  // CG with the AMG hierarchy of the Q1 tangent of the cells (the initial
  // state's: a preconditioner only)
  check("VCBCPBG V5sn Unl, AMG Q1",
        run(settings("VCBCPBG V5sn Unl",
                     3,
                     stretch,
                     1e3,
                     no_vtu,
                     false,
                     2,
                     false,
                     "subsection Linear solver\n  set Type = cg\n"
                     "  set AMG operator = Q1 cells\nend\n")),
        kappa,
        d,
        sigma[0][0]);
  // 3-D: F = diag(1 + g, 1, 1) has the plane strain closed form
  for (const std::string formulation :
       {"FEM", "FEM H1P0", "VCBCPBG V5sn Unl", "VCBCPBG V5sn UnlP0"})
    try
      {
        check("3d " + formulation,
              run<3>(settings(formulation, 3, stretch, 1e3, no_vtu, false, 3)),
              kappa,
              d,
              sigma[0][0]);
      }
    catch (const std::exception &e)
      {
        deallog << "3d " << formulation << " failed: " << e.what() << std::endl;
      }
  // IUnlP0 (nu = 0.5, the material without its volumetric energy): F =
  // diag(1 + g, 1 / (1 + g)) with the top free, sigma_yy = 0, so
  // sigma_xx = (1 - d) (sigma_iso_xx - sigma_iso_yy)
  {
    const Materials::IsochoricDamageNeoHooke<2> isochoric(
      material_parameters(true).without_volumetric_energy());
    const auto F_incompressible = [](const double t) {
      Tensor<2, 2> F;
      F[0][0] = 1. + g(t);
      F[1][1] = 1. / (1. + g(t));
      return F;
    };
    double kappa_i = 0;
    for (const double t : {1. / 3, 2. / 3, 1.})
      kappa_i =
        std::max(kappa_i, isochoric.strain_measure(F_incompressible(t)));
    const double       d_i        = isochoric.damage(kappa_i);
    const double       state_i[2] = {kappa_i, d_i};
    const Tensor<2, 3> c =
      isochoric.cauchy_stress_with_state(F_incompressible(1.),
                                         make_array_view(state_i));
    deallog << "incompressible closed form: kappa = " << kappa_i
            << ", d = " << d_i << ", sigma_xx = " << c[0][0] - c[1][1]
            << std::endl;
    for (const std::string formulation : {"VCPBG IUnlP0", "VCPPG IUnlP0"})
      try
        {
          check(
            formulation,
            run(settings(formulation, 3, stretch, 1e3, no_vtu, false, 2, true)),
            kappa_i,
            d_i,
            c[0][0] - c[1][1]);
        }
      catch (const std::exception &e)
        {
          deallog << formulation << " failed: " << e.what() << std::endl;
        }
  }
  deallog << "sigma_xx(committed) / sigma_xx(damage of the last F alone) = "
          << sigma[0][0] / undamaged[0][0] << std::endl;

  // CPD has no material to carry the state
  try
    {
      run(settings("CPD", 3, stretch, 1e3, no_vtu));
      deallog << "CPD: accepted: NO" << std::endl;
    }
  catch (const std::exception &e)
    {
      const std::string text = pg::one_line(e.what());
      deallog << "CPD refused: "
              << (text.find("cannot carry the history") != std::string::npos ?
                    "yes" :
                    "NO")
              << std::endl;
      if (text.find("cannot carry the history") == std::string::npos)
        deallog << text << std::endl;
    }

  // 3. a step cut: the committed state after the cut equals that of two
  // plain steps bit for bit
  for (const std::string formulation : {"FEM Q1P0",
                                        "VCBCPBG V5sn UnlP0",
                                        "VCPBG U2P1",
                                        "VCPBG Unl+P1C",
                                        "VCPBG U1SIG"})
    {
      const Result cut =
        run(settings(formulation, 1, "0.2*t", 0.02, no_vtu, true));
      const Result two =
        run(settings(formulation, 2, "0.2*t", 1e3, no_vtu, true));
      const bool cuts =
        cut.screen.find("cutting the step to dt = 0.5") != std::string::npos &&
        cut.screen.find("test material failed") != std::string::npos;
      deallog << std::left << std::setw(20) << formulation << std::right
              << " step cut: " << (cuts ? "yes" : "NO");
      if (formulation.find("Unl+P1C") == std::string::npos)
        deallog << ", committed state and u bit for bit those of two steps: "
                << (bitwise_equal(cut.committed, two.committed) &&
                        bitwise_equal(cut.points, two.points) ?
                      "yes" :
                      "NO")
                << std::endl;
      else
        {
          // the bubble's local iteration starts from the bubble of the
          // failed attempt (a warm start, not part of the history): the
          // same state to round-off only
          double difference = 0;
          for (unsigned int i = 0; i < cut.committed.size(); ++i)
            difference =
              std::max(difference,
                       std::abs(cut.committed[i] - two.committed[i]) /
                         std::abs(two.committed[i]));
          deallog << std::endl;
          print_bound("  committed state, relative difference to two steps",
                      difference,
                      1e-12);
        }
    }

  // 4. restart from the checkpoint of step 2 (of 3)
  {
    namespace fs = std::filesystem;
    const std::string output =
      "  set VTU = false\n  set Checkpoint interval = 2\n"
      "  set Directory = restart_full\n";
    const Result full = run(settings("VCPBG U1SIG", 3, stretch, 1e3, output));
    fs::remove_all("restart_again");
    fs::create_directories("restart_again");
    fs::copy("restart_full/checkpoint",
             "restart_again/checkpoint",
             fs::copy_options::recursive);
    const Result again =
      run(settings("VCPBG U1SIG",
                   3,
                   stretch,
                   1e3,
                   "  set VTU = false\n  set Checkpoint interval = 2\n"
                   "  set Directory = restart_again\n"),
          true);
    deallog << "VCPBG U1SIG restart from step 2: restarted "
            << (again.screen.find("restart after") != std::string::npos ?
                  "yes" :
                  "NO")
            << ", load steps " << again.summary.load_steps << " of "
            << full.summary.load_steps
            << ", committed state and u bit for bit equal: "
            << (bitwise_equal(full.committed, again.committed) &&
                    bitwise_equal(full.points, again.points) ?
                  "yes" :
                  "NO")
            << std::endl;
  }

  // 6. J2 plasticity (issue 46's material) through every formulation: the
  // homogeneous stretch by 2 % (g / 10) gives the same largest equivalent
  // plastic strain in each (relative to FEM's)
  {
    const auto j2 = [&](const std::string &formulation) {
      std::string text =
        settings(formulation, 3, "0.1*(" + stretch + ")", 1e3, no_vtu, true);
      const std::string from = "  set Model = isochoric damage neo-Hooke\n";
      text.replace(text.find(from),
                   from.size(),
                   "  set Model = J2 plasticity\n"
                   "  set Initial yield stress = 0.45\n"
                   "  set Saturation yield stress = 0.715\n"
                   "  set Linear hardening modulus = 0.13\n"
                   "  set Saturation exponent = 16.93\n");
      const std::string entries =
        text.substr(text.find("  subsection isochoric damage neo-Hooke"),
                    text.find("  end\nend\nsubsection Boundary") + 6 -
                      text.find("  subsection isochoric damage neo-Hooke"));
      text.replace(text.find(entries), entries.size(), "");
      const RunSummary summary = run(text).summary;
      for (const auto &[name, value] : summary.state_output_maxima)
        if (name == "equivalent_plastic_strain")
          return value;
      return -1.;
    };
    const double reference = j2("FEM");
    deallog << "J2 plasticity, max equivalent plastic strain (FEM) = "
            << reference << std::endl;
    for (const std::string formulation : {"FEM Q1P0",
                                          "VCBCPBG V5sn Unl",
                                          "VCPBG V5sn U2",
                                          "VCBCPBG V5sn UnlP0",
                                          "VCPBG U2P1",
                                          "VCPBG U2P1C",
                                          "VCPBG Unl+P1C",
                                          "VCPBG U1SUnl",
                                          "VCPBG U1SIG",
                                          "VCBCPPG V3sn Unl",
                                          "VCBCPPG V3sn UnlP0"})
      try
        {
          print_bound("  " + formulation + ", relative difference to FEM",
                      std::abs(j2(formulation) - reference) / reference,
                      1e-10);
        }
      catch (const std::exception &e)
        {
          deallog << formulation << " failed: " << e.what() << std::endl;
        }
  }

  // 5. the state outputs in the VTU files and summary.json
  {
    namespace fs = std::filesystem;
    fs::remove_all("vtu_state");
    run(settings("VCBCPBG V5sn Unl",
                 3,
                 stretch,
                 1e3,
                 "  set VTU = true\n  set Directory = vtu_state\n"));
    bool cells = false, particles = false;
    for (const auto &entry : fs::directory_iterator("vtu_state"))
      if (entry.path().extension() == ".vtu")
        {
          const std::string text = read_file(entry.path().string());
          const bool        has =
            text.find("Name=\"damage\"") != std::string::npos &&
            text.find("Name=\"damage_strain\"") != std::string::npos;
          if (entry.path().filename().string().rfind("particles", 0) == 0)
            particles = particles || has;
          else if (entry.path().filename().string().rfind("solution", 0) == 0)
            cells = cells || has;
        }
    const std::string summary = read_file("vtu_state/summary.json");
    deallog << "VTU fields damage, damage_strain: cells "
            << (cells ? "yes" : "NO") << ", particles "
            << (particles ? "yes" : "NO")
            << "; summary.json max_damage, max_damage_strain: "
            << (summary.find("\"max_damage\":") != std::string::npos &&
                    summary.find("\"max_damage_strain\":") !=
                      std::string::npos ?
                  "yes" :
                  "NO")
            << std::endl;
  }
}
