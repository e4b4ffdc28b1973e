#include <pg/analysis/analysis_parameters.h>
#include <pg/base/exceptions.h>
#include <pg/base/parameter_utilities.h>

namespace pg
{
  namespace Parameters
  {
    void
    Analysis::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Analysis");
      {
        prm.declare_entry(
          "Type",
          "static",
          Patterns::Selection("static|eigenmodes|inf-sup"),
          "static: quasi-static load stepping with Newton's method. "
          "eigenmodes: the eigenvalues of the tangent in the undeformed "
          "state (with the given constraints; none for a free body), by a "
          "dense LAPACK solve (at most 6000 unknowns, one MPI rank). Zero "
          "eigenvalues beyond the rigid-body motions, or many small ones, "
          "reveal spurious modes (dissertation section 7.2.1). With "
          "global pressure unknowns (U2P1C, Unl+P1C: nodal p and Theta; "
          "IUnlP0: the family pressures) the eigenvalues are those of the "
          "stiffness the displacements see: p and Theta eliminated (Schur "
          "complement), or for IUnlP0 the displacements restricted to "
          "those the incompressibility admits. "
          "inf-sup: the numerical inf-sup test of Chapelle and Bathe "
          "(section 7.2.5, eqs. 7.10-7.15) on the unit square meshed with "
          "'Inf-sup subdivisions' (the entries 'Mesh', corners, "
          "'Subdivisions' and 'Global refinement' of subsection 'Geometry' "
          "are replaced; 'Distortion', 'Random seed' and 'Meshfree region' "
          "are kept), held by 'Dirichlet' (clamp all four sides). PBG and "
          "FEM formulations only; dense LAPACK (at most 6000 free unknowns, "
          "one MPI rank). Writes inf_sup.txt.");
        prm.declare_entry("Number of eigenvalues",
                          "200",
                          Patterns::Integer(1),
                          "How many of the smallest eigenvalues go to "
                          "summary.json and eigenvalues.txt.");
        prm.declare_entry(
          "Pressure space",
          "displacement",
          Patterns::Selection("displacement|P0|P1|P1C|P1C+bubble"),
          "inf-sup: the pressure space of T_h. displacement: the "
          "displacement-based formulation as it is (T_h from the full "
          "div-div term, K = 1, mu = 0, at every evaluation point). P0: one "
          "constant pressure per element (Q1 cell or PG family), condensed "
          "exactly; Q1P0 for FEM, UnlP0 for PBG families. P1: a linear "
          "pressure per PBG family (U2P1 with 'Formulation = PBG U2'), "
          "constant per Q1 cell. P1C: a nodal pressure at every particle, "
          "linear in each family with the gradient of its functions at the "
          "master (U2P1C with 'Formulation = PBG U2', eq. 6.11). "
          "P1C+bubble: the same with the bubble of eqs. 6.12-6.16 added to "
          "every family's displacement (Unl+P1C with 'Formulation = BCPBG "
          "Unl'). With P1C, T_h = B^T M^-1 B is dense.");
        prm.declare_entry("Inf-sup subdivisions",
                          "2, 4, 8, 16, 32",
                          Patterns::List(Patterns::Integer(1)),
                          "inf-sup: the refinement series, N cells (or "
                          "particle spacings) per side of the unit square.");
        prm.declare_entry("Inf-sup zero tolerance",
                          "1e-10",
                          Patterns::Double(0.),
                          "inf-sup: eigenvalues below this times the "
                          "largest count as zero (k - 1 in eq. 7.14). "
                          "Measured for N <= 32 (doc/benchmarks/inf_sup.md): "
                          "the zero eigenvalues are round-off, below 3e-13 "
                          "lambda_max, the non-zero ones above 5e-6 "
                          "lambda_max.");
      }
      prm.leave_subsection();
    }



    void
    Analysis::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Analysis");
      {
        type           = prm.get("Type");
        n_eigenvalues  = prm.get_integer("Number of eigenvalues");
        pressure_space = prm.get("Pressure space");
        inf_sup_subdivisions.clear();
        for (const double n : parse_doubles(prm.get("Inf-sup subdivisions"),
                                            "Analysis/Inf-sup subdivisions"))
          inf_sup_subdivisions.push_back(static_cast<unsigned int>(n));
        inf_sup_zero_tolerance = prm.get_double("Inf-sup zero tolerance");
      }
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace pg
