#include <pg/base/exceptions.h>
#include <pg/elements/discretization_parameters.h>

#include <deal.II/base/utilities.h>

#include <cmath>
#include <string>

namespace pg
{
  namespace Parameters
  {
    void
    Discretization::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      {
        prm.declare_entry(
          "Formulation",
          "BCPBG Unl TL",
          Patterns::Anything(),
          "The method, as the dissertation's code (Table 7.1), or FEM: "
          "[VC|VC2][BC]<method> [V<n><b>] <points> [noBC] [TL], with the "
          "table's defaults. <method>: PBG (eq. 4.30), PPG (= PPG1, eq. "
          "4.21) or PPG2 (eq. 4.22). <points>: Unl (default; shape functions "
          "at every family member), U1 (PBG at the master only: classical "
          "correspondence) or U2 (the quadratic WTE2 at every family member, "
          "whatever 'Shape functions' says). The bond correction BC (eq. "
          "5.55) is the default of Unl (Table 7.1: 'default for all first "
          "order formulations'), so 'PBG Unl' is 'BCPBG Unl TL'; 'noBC' "
          "switches it off ('PBG Unl noBC'). U1 and U2 take no BC. VC "
          "switches the variational-consistency correction on (section "
          "5.3.2) with the correction function V1 (constant), V2 (WLS2 "
          "second derivatives), V3 (MLS1 value), V4 (WLS2 value) or V5 (V3 "
          "with the bond projector); default V3 for PPG, V5 for PBG; and the "
          "boundary option p, s or sn (default sn; V4 needs s). "
          "VC2 adds the second-order correction (section 11.6); it is built "
          "on PPG2, so 'VC2PPG' means PPG2, and it takes the boundary option "
          "s (default correction function V1). The screen and summary.json "
          "show the code with every default written out. UnlP0 (mixed, "
          "eq. 6.9): Unl with a pressure and a dilatation constant per "
          "family, condensed; PBG or PPG, with 'Model = "
          "isochoric-volumetric neo-Hooke' or 'linear elastic' in plane "
          "strain or 3-D; the FE cells of a coupled model are then Q1P0. "
          "IUnlP0: the incompressible UnlP0 (Theta = 1, 'Poisson's ratio = "
          "0.5'), the pressure of every family a global unknown; meshfree "
          "models only, 'Linear solver/Type = direct'. U2P1 (PBG, "
          "condensed linear p and Theta), U2P1C and Unl+P1C (PBG, nodal p "
          "and Theta; direct solver): see the README. "
          "U1SUnl (PBG only, eq. 6.18): U1 stabilised by a pseudo-energy "
          "with nu~ = min(0.49, nu) on the Unl functions of every family "
          "member (BC default, VC corrects both); for nu <= 0.49 it equals "
          "Unl. "
          "FEM uses Q1 elements everywhere (H1 in 3-D; P1 on triangle and "
          "tetrahedron meshes); 'FEM Q1P0' (= 'FEM H1P0') the mixed "
          "Q1P0/H1P0 cells with P0 pressure and dilatation condensed per "
          "cell (refused on triangles and tetrahedra: P1-P0 locks). Examples: 'PBG Unl', 'VCPBG V5sn Unl' (= "
          "'VCBCPBG V5sn Unl TL'), 'VCPPG V3sn Unl' (= 'VCBCPPG V3sn Unl "
          "TL'), 'PBG U1', 'VC2PPG V1s U2', 'VCPPG V3sn UnlP0', 'VCPBG "
          "U1SUnl', 'FEM Q1P0'. CPD: "
          "continuum-kinematics-inspired peridynamics with the constants of "
          "subsection 'CPD' (the meshfree cells' vertices interact within "
          "the horizon; no shape functions).");
        prm.declare_entry("Shape functions",
                          "MTE1",
                          Patterns::Selection("MTE1|MLS1|WLS1|WTE1"),
                          "The first-order base of Unl/U1 (Table 5.1): MTE1 "
                          "(moving Taylor), MLS1 (moving least squares), "
                          "WLS1 (weighted least squares), WTE1 (weighted "
                          "Taylor). At the master MTE1 equals WTE1, so U1 "
                          "with MTE1 is WTE1: classical correspondence.");
        prm.declare_entry(
          "Horizon factor",
          "",
          Patterns::Anything(),
          "Horizon delta^k = factor x local particle spacing h^k, per "
          "particle k (h^k: the mean length of the meshfree cell edges at "
          "the particle), so delta varies with the local spacing on graded "
          "or distorted meshes. Typical values 1.51 ... 3.01. Give either "
          "this or 'Horizon', not both; with both empty the factor is "
          "2.51.");
        prm.declare_entry(
          "Horizon",
          "",
          Patterns::Anything(),
          "Absolute horizon delta, the same for every particle (Peridigm's "
          "'Horizon'). Units: length. Give either this or 'Horizon factor', "
          "not both; empty: use 'Horizon factor'. On a uniform lattice of "
          "spacing h, 'Horizon = 2.51 h' gives the families of 'Horizon "
          "factor = 2.51'; on graded or distorted meshes they differ (the "
          "factor follows the local spacing).");
        prm.declare_entry("Nearest neighbours",
                          "0",
                          Patterns::Integer(0),
                          "If > 0, a family is its master plus the N nearest "
                          "particles, completed to pairwise families; "
                          "'Horizon factor' and 'Horizon' are then ignored.");
        prm.declare_entry("Weight exponent",
                          "1",
                          Patterns::Double(0.),
                          "n in the weight omega = |dX|^(-2n) (eqs. 4.5, "
                          "5.42).");
        prm.declare_entry(
          "Hourglass coefficient",
          "0",
          Patterns::Double(0.),
          "Peridigm's penalty ('hourglass') stabilisation of the classical "
          "correspondence, for the U1 formulations only ('PBG U1'): the "
          "force of Peridigm's 'Elastic Correspondence' material with its "
          "'Hourglass Coefficient' alpha (src/materials/correspondence.cxx, "
          "computeHourglassForce()), with a consistent tangent. Per bond "
          "xi of a master k, with the master's deformation gradient F, "
          "Y = y^j - y^k and z = F xi - Y: t = -C (z . Y) Y / (|xi| |Y|), "
          "C = 18 alpha K / (pi delta^4) (K the bulk modulus, delta the "
          "horizon of k), applied as +V^k V^j t to k and -V^k V^j t to j. "
          "Peridigm's examples use 0.02; 0 (default) switches it off. "
          "Peridigm's deformation gradient has the weight omega = 1: set "
          "'Weight exponent = 0' to reproduce it. doc/element-view.md "
          "explains the differences to U1SUnl.");
        prm.declare_entry(
          "Self-weight distance",
          "0.001",
          Patterns::Double(0.),
          "U1SIG only: the MLS1 second derivatives of its implicit "
          "gradients (eq. 6.28) give the master the weight of a member at "
          "this distance, in units of the family's shortest bond, instead "
          "of the exception 0 (the source's 'modified weight function "
          "exception of 1000 times the particle spacing', read as a "
          "self-bond of 1/1000 of the spacing: nearly interpolating at the "
          "master; doc/ambiguities.md). Must be > 0.");
        prm.declare_entry(
          "Quadrature weights",
          "horizon",
          Patterns::Selection("horizon|particle volumes"),
          "The weights of the PBG Unl family quadrature. horizon: V^k V^j / "
          "V^{H^k} at member j of family k (eq. 4.30, the source's); they "
          "give a particle on the surface about 0.73 of its volume and the "
          "rows inside more, so a coarse beam is soft in bending (the "
          "section's second moment 0.83 of the exact one with 4 particles "
          "through the thickness). particle volumes: each of these weights "
          "divided by the sum of V^{k'} / V^{H^{k'}} over the families k' "
          "that hold j, so that the weights at every particle add up to its "
          "volume (doc/benchmarks/mixed_formulations.md). PBG codes with Unl "
          "points (also UnlP0, Unl+P1C, U1SUnl) only; with a VC code the "
          "patch test stays exact, without VC it is not.");
      }
      prm.leave_subsection();
    }



    void
    Discretization::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      {
        formulation     = prm.get("Formulation");
        shape_functions = prm.get("Shape functions");
        const std::string factor_text =
          Utilities::trim(prm.get("Horizon factor"));
        const std::string horizon_text = Utilities::trim(prm.get("Horizon"));
        AssertThrow(factor_text.empty() || horizon_text.empty(),
                    ExcBadParameter("Discretization/Horizon",
                                    horizon_text,
                                    "'Horizon factor' is set too (to <" +
                                      factor_text +
                                      ">); set exactly one of 'Horizon' "
                                      "(absolute, length) and 'Horizon "
                                      "factor' (x local spacing) in "
                                      "subsection 'Discretization'."));
        const auto positive = [](const std::string &text,
                                 const std::string &entry) {
          double value = 0;
          try
            {
              std::size_t end = 0;
              value           = std::stod(text, &end);
              AssertThrow(Utilities::trim(text.substr(end)).empty(),
                          ExcMessage(""));
            }
          catch (...)
            {
              AssertThrow(false,
                          ExcBadParameter("Discretization/" + entry,
                                          text,
                                          "it must be a number."));
            }
          AssertThrow(value > 0. && std::isfinite(value),
                      ExcBadParameter("Discretization/" + entry,
                                      text,
                                      "it must be positive."));
          return value;
        };
        horizon        = 0.;
        horizon_factor = 0.;
        if (!horizon_text.empty())
          horizon = positive(horizon_text, "Horizon");
        else
          horizon_factor = factor_text.empty() ?
                             2.51 :
                             positive(factor_text, "Horizon factor");
        nearest_neighbours    = prm.get_integer("Nearest neighbours");
        weight_exponent       = prm.get_double("Weight exponent");
        hourglass_coefficient = prm.get_double("Hourglass coefficient");
        self_weight_distance  = prm.get_double("Self-weight distance");
        particle_volume_weights =
          (prm.get("Quadrature weights") == "particle volumes");
      }
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace pg
