#include <pg/postprocess/setup_report.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    print_setup_report(
      const ConditionalOStream             &pcout,
      const Parameters::AllParameters<dim> &prm,
      const FormulationCode                &formulation,
      const Discretization<dim>            &discretization,
      const RunSummary                     &summary,
      const std::string                    &particle_traction_area,
      const std::function<bool(const types::boundary_id)> &is_neumann,
      const std::vector<std::map<types::boundary_id, double>>
        &boundary_area_weights)
    {
      const auto &particles = discretization.particles;
      const auto &families  = discretization.families;
      const auto &cpd       = discretization.cpd;

      unsigned int min_family = 0, max_family = 0;
      double       mean_family = 0;
      if (families.n_families() > 0)
        {
          min_family = max_family = families.members(0).size();
          for (unsigned int k = 0; k < families.n_families(); ++k)
            {
              const unsigned int s = families.members(k).size();
              min_family           = std::min(min_family, s);
              max_family           = std::max(max_family, s);
              mean_family += s;
            }
          mean_family /= families.n_families();
        }
      const bool mixed = formulation.mixed();
      const bool unl_p0 =
        (formulation.fields == FormulationCode::Fields::condensed_p0);
      // Q1P0 is called H1P0 in 3-D (Table 7.4)
      pcout << "pg_solve: " << dim << "-D, formulation '"
            << (formulation.method == FormulationCode::Method::fem && mixed &&
                    dim == 3 ?
                  std::string("FEM H1P0") :
                  formulation.text)
            << "'";
      if (formulation.method != FormulationCode::Method::fem && !cpd)
        pcout << " (" << formulation.method_name() << ", "
              << (unl_p0 ? "UnlP0" :
                  formulation.incompressible() ?
                           "IUnlP0" :
                  formulation.fields == FormulationCode::Fields::condensed_p1 ?
                           "U2P1" :
                  formulation.fields == FormulationCode::Fields::nodal_p1 ?
                           (formulation.bubble ? "Unl+P1C" : "U2P1C") :
                  formulation.points == FormulationCode::Points::unl ? "Unl" :
                  formulation.points == FormulationCode::Points::u1 &&
                      formulation.implicit_gradients ?
                                                                       "U1SIG" :
                  formulation.points == FormulationCode::Points::u1 ? "U1" :
                  formulation.points == FormulationCode::Points::u2 ? "U2" :
                                                                      "U1SUnl")
              << ", "
              << (formulation.points == FormulationCode::Points::u2 ?
                    std::string("WTE2") :
                    prm.discretization.shape_functions)
              << ", bond correction "
              << (formulation.bond_correction ? "on" : "off") << ")";
      if (!formulation.notice().empty())
        pcout << "\n  " << formulation.notice();
      if (formulation.points == FormulationCode::Points::u1s_unl)
        pcout << "\n  U1SUnl:          stabilisation nu~ = "
              << std::min(0.49, prm.material.poissons_ratio)
              << (prm.material.poissons_ratio > 0.49 ?
                    "" :
                    " = nu: the families equal Unl (eq. 6.18)");
      if (formulation.implicit_gradients)
        pcout << "\n  U1SIG:           A~ of nu~ = "
              << std::min(0.49, prm.material.poissons_ratio)
              << ", frozen per load step; MLS1 self-weight at "
              << prm.discretization.self_weight_distance
              << " x the shortest bond";
      if (prm.discretization.hourglass_coefficient > 0.)
        pcout << "\n  hourglass:       coefficient "
              << prm.discretization.hourglass_coefficient
              << " (Peridigm's penalty force, C = 18 alpha K / (pi "
                 "delta^4))";
      if (cpd)
        {
          const auto n = cpd->n_interactions();
          pcout << "\n  CPD:             C1 = " << prm.cpd.C1
                << ", C2 = " << prm.cpd.C2 << ", C3 = " << prm.cpd.C3
                << (prm.cpd.partial_volumes ? ", partial volumes" : "")
                << "\n  interactions:    " << n[0] << " bonds, " << n[1]
                << " triangles, " << n[2] << " tetrahedra";
          // Coupled to finite elements, bond-based CPD must have the FE
          // material's stiffness: C1 = 12 kappa / (pi delta^3) in 2-D,
          // 18 K / (pi delta^4) in 3-D (doc/cpd.md) at the mean horizon.
          // The default C1 = 1 against E = 100 missed the coupled patch
          // test by 7e2 (relative L2).
          if (summary.n_fe_cells > 0 && particles.n_particles() > 0 &&
              prm.cpd.C2 == 0. && prm.cpd.C3 == 0.)
            {
              double delta = 0;
              for (unsigned int k = 0; k < particles.n_particles(); ++k)
                delta +=
                  prm.discretization.horizon_factor * particles.spacing(k) +
                  prm.discretization.horizon;
              delta /= particles.n_particles();
              const double lambda = prm.material.lambda();
              const double mu     = prm.material.mu();
              // the bulk modulus of the (2-D) material, and its in-plane
              // Poisson ratio
              const bool   stress = (prm.material.plane == "stress");
              const double kappa =
                dim == 3 ? lambda + 2. * mu / 3. :
                stress   ? 2. * lambda * mu / (lambda + 2. * mu) + mu :
                           lambda + mu;
              const double nu3 = lambda / (2. * (lambda + mu));
              const double nu  = (dim == 2 && !stress) ? nu3 / (1. - nu3) : nu3;
              const double C1 =
                dim == 3 ? 18. * kappa / (numbers::PI * std::pow(delta, 4)) :
                           12. * kappa / (numbers::PI * std::pow(delta, 3));
              const double nu_cpd = (dim == 3 ? 0.25 : 1. / 3.);
              if (std::abs(prm.cpd.C1 / C1 - 1.) > 0.1 ||
                  std::abs(nu - nu_cpd) > 0.01)
                {
                  std::ostringstream c1;
                  c1 << std::setprecision(4) << C1 << " at the mean horizon "
                     << delta;
                  pcout
                    << "\n  warning:         CPD is coupled to finite "
                       "elements, but 'C1' (subsection 'CPD') and the FE "
                       "material (subsection 'Material') are not the same "
                       "material: bond-based CPD has nu = "
                    << (dim == 3 ? "1/4" :
                                   "1/3 in the plane (the FE material: "
                                   "nu = 1/3 with 'Plane = stress', or "
                                   "1/4 with plane strain)")
                    << " and the FE material's bulk modulus gives C1 = "
                    << (dim == 3 ? "18 K / (pi delta^4) = " :
                                   "12 kappa / (pi delta^3) = ")
                    << c1.str() << " (doc/cpd.md; given: C1 = " << prm.cpd.C1
                    << ", nu = " << nu
                    << "). Set both; even then the coupled linear patch test "
                       "is not passed, by CPD's surface effect within delta "
                       "of the boundary and of the FE interface "
                       "(doc/cpd.md).";
                }
            }
        }
      if (!cpd || summary.n_fe_cells > 0)
        {
          pcout << "\n  material:        " << prm.material.model;
          if (prm.material.bulk_modulus)
            pcout << ", K = " << *prm.material.bulk_modulus
                  << ", mu = " << prm.material.mu()
                  << " (E = " << prm.material.youngs_modulus
                  << ", nu = " << prm.material.poissons_ratio << ")";
          else
            pcout << ", E = " << prm.material.youngs_modulus
                  << ", nu = " << prm.material.poissons_ratio;
          if (prm.material.model == "J2 plasticity")
            pcout << "\n  yield stress:    sigma_y(alpha) = "
                  << prm.material.initial_yield_stress << " + "
                  << prm.material.linear_hardening_modulus << " alpha + ("
                  << prm.material.saturation_yield_stress << " - "
                  << prm.material.initial_yield_stress << ") (1 - exp(-"
                  << prm.material.saturation_exponent << " alpha))";
          if (formulation.incompressible())
            pcout << " (incompressible: mu = " << prm.material.mu()
                  << ", the volume held by the family pressures)";
          // Volumetric locking: the displacement formulations constrain
          // the volume at every evaluation point; its measure is K / mu.
          const double locking =
            (prm.material.lambda() + 2. / 3. * prm.material.mu()) /
            prm.material.mu();
          if (!mixed && prm.material.poissons_ratio >= 0.49 &&
              (dim == 3 || prm.material.plane != "stress"))
            pcout << "\n  Warning: nu = " << prm.material.poissons_ratio
                  << " (K/mu = " << locking
                  << ") is nearly incompressible, and the displacement "
                     "formulation locks volumetrically (too stiff, "
                     "oscillating pressure). Use a mixed code in "
                     "'Discretization/Formulation' ('FEM Q1P0', "
                     "'VCPPG V3sn UnlP0', 'VCPBG V5sn UnlP0') with 'Model "
                     "= isochoric-volumetric neo-Hooke'.";
        }
      pcout << "\n"
            << "  cells:           "
            << discretization.triangulation.n_active_cells() << " ("
            << summary.n_fe_cells << " finite elements"
            << (mixed && summary.n_fe_cells > 0 ?
                  (dim == 2 ? " Q1P0" : " H1P0") :
                  "")
            << ", " << summary.n_meshfree_cells << " meshfree)\n"
            << discretization.mesh_notes
            << "  particles:       " << particles.n_particles() << "\n";
      if (families.n_families() > 0 && prm.discretization.horizon > 0)
        pcout << "  horizon:         " << prm.discretization.horizon
              << " (absolute)\n";
      if (families.n_families() > 0)
        {
          std::ostringstream mean;
          mean << std::fixed << std::setprecision(1) << mean_family;
          pcout << "  family size:     min " << min_family << ", mean "
                << mean.str() << ", max " << max_family << " (master included)"
                << "\n";
        }
      if (!prm.boundary_conditions.neumann.empty() && particles.n_particles())
        {
          // How much of the geometric Neumann area the test functions see:
          // sum of n . d^k over the particles of Neumann faces divided by
          // the sum of |a^k| (1 for a variationally consistent method).
          double seen = 0, geometric = 0;
          for (unsigned int k = 0; k < particles.n_particles(); ++k)
            for (const auto &[id, area] : particles.boundary_area_vectors(k))
              if (is_neumann(id))
                {
                  seen += boundary_area_weights[k].at(id);
                  geometric += area.norm();
                }
          if (geometric > 0)
            {
              std::ostringstream percent;
              percent << std::fixed << std::setprecision(1)
                      << 100. * seen / geometric;
              pcout << "  particle traction area: " << particle_traction_area
                    << " (the test functions see " << percent.str()
                    << " % of the Neumann area)\n";
            }
        }
      // The resultant and moment of the ids with partly loaded particles
      // (the loads there are corrected; summary.json has every id).
      for (const auto &r : summary.neumann_resultants)
        if (r.n_partly_loaded > 0)
          {
            double force = 0, difference = 0;
            for (unsigned int c = 0; c < dim; ++c)
              {
                force += r.exact_force[c] * r.exact_force[c];
                difference += (r.force[c] - r.exact_force[c]) *
                              (r.force[c] - r.exact_force[c]);
              }
            force      = std::sqrt(force);
            difference = std::sqrt(difference);
            // round-off (below 1e-12 of the scale) printed as 0
            const auto print = [](const std::vector<double> &v,
                                  const double               scale) {
              std::ostringstream out;
              out << std::setprecision(6);
              for (unsigned int c = 0; c < v.size(); ++c)
                out << (c > 0 ? " " : "")
                    << (std::abs(v[c]) <= 1e-12 * scale ? 0. : v[c]);
              return out.str();
            };
            std::ostringstream relative;
            if (difference <= 1e-12 * force)
              relative << "< 1e-12";
            else
              relative << std::scientific << std::setprecision(2)
                       << (force > 0 ? difference / force : difference);
            const double length = std::pow(r.area, 1. / (dim - 1));
            pcout << "  Neumann " << static_cast<int>(r.id)
                  << ", partly loaded (" << r.n_partly_loaded
                  << " particles at the edge of the load), at t = 1:\n"
                  << "    resultant " << print(r.force, force) << ", exact "
                  << print(r.exact_force, force) << " (relative difference "
                  << relative.str() << ")\n"
                  << "    moment about (" << print(r.centre, length)
                  << "): " << print(r.moment, force * length) << ", exact "
                  << print(r.exact_moment, force * length) << "\n";
          }
      if (formulation.variational_consistency)
        {
          std::ostringstream vc;
          vc << std::scientific << std::setprecision(1)
             << summary.max_interior_unit_stress_residual
             << ", max |alpha| h = " << std::fixed << std::setprecision(2)
             << summary.max_correction_factor;
          pcout << "  VC correction:   interior |d^k|/h^(dim-1) <= " << vc.str()
                << "\n";
          unsigned int n_v1 = 0;
          for (unsigned int k = 0; k < particles.n_particles(); ++k)
            n_v1 += (discretization.family_elements->family_correction_function(
                       k) == FormulationCode::CorrectionFunction::v1 &&
                     formulation.correction_function !=
                       FormulationCode::CorrectionFunction::v1);
          if (n_v1 > 0)
            pcout << "  VC on the FE/meshfree interface: V1 in the " << n_v1
                  << " families of interface particles (doc/ambiguities.md, "
                     "item 17)\n";
          if (formulation.second_order_consistency)
            {
              std::ostringstream vc2;
              vc2 << std::scientific << std::setprecision(1)
                  << summary.max_interior_second_order_residual;
              pcout << "  VC2 correction:  interior |D^k|/h^dim <= "
                    << vc2.str() << "\n";
            }
        }
      pcout << "  DoFs:            " << discretization.dof_handler.n_dofs()
            << "\n"
            << "  matrix nonzeros: " << summary.matrix_nonzeros << std::endl;
      if (summary.amg_operator_nonzeros > 0)
        pcout << "  AMG operator:    Q1 cells, "
              << summary.amg_operator_nonzeros
              << " nonzeros (Linear solver/AMG operator)" << std::endl;
    }



    template void
    print_setup_report<2>(
      const ConditionalOStream &,
      const Parameters::AllParameters<2> &,
      const FormulationCode &,
      const Discretization<2> &,
      const RunSummary &,
      const std::string &,
      const std::function<bool(const types::boundary_id)> &,
      const std::vector<std::map<types::boundary_id, double>> &);
    template void
    print_setup_report<3>(
      const ConditionalOStream &,
      const Parameters::AllParameters<3> &,
      const FormulationCode &,
      const Discretization<3> &,
      const RunSummary &,
      const std::string &,
      const std::function<bool(const types::boundary_id)> &,
      const std::vector<std::map<types::boundary_id, double>> &);
  } // namespace Postprocess
} // namespace pg
