#ifndef pg_base_formulation_code_h
#define pg_base_formulation_code_h

#include <pg/base/global.h>

#include <string>

namespace pg
{
  /**
   * A formulation code of the dissertation (Table 7.1), e.g.
   * "VCPBG Unl", parsed into its parts (architecture.md section 5) with the
   * table's defaults: BC for every first-order formulation (Unl; U1 has no
   * bond to correct, U2 is second order), V3 for PPG, V5 for PBG, the
   * boundary option sn, TL. "noBC" switches the bond correction
   * off. Parts that are not built yet (UL) are rejected with a "not yet
   * available" message, never ignored. The readings where the table is silent
   * are in doc/ambiguities.md.
   */
  struct FormulationCode
  {
    /** How the family residual is formed (pg-methods.md section 7.4). */
    enum class Method
    {
      fem,  //!< Q1 finite elements everywhere
      pbg,  //!< Bubnov-Galerkin, eq. (4.30)
      ppg1, //!< Petrov-Galerkin, eq. (4.21) ("PPG")
      ppg2, //!< Petrov-Galerkin, eq. (4.22)
      cpd   //!< continuum-kinematics-inspired peridynamics (Javili et al.)
    };

    /** Which evaluation points a family has. */
    enum class Points
    {
      unl, //!< every family member (PBG) or every bond (PPG)
      u1,  //!< the master only (underintegrated PBG = classical correspondence)
      u2,  //!< every member, quadratic WTE2 shape functions (section 6.5)
      /**
       * U1SUnl (eqs. 6.18-6.20, pg-methods.md section 12.3.2): the real
       * material at the master (U1) plus a pseudo-material with nu <= 0.49
       * on every member (Unl) minus the same pseudo-material at the master
       * (PBG only)
       */
      u1s_unl
    };

    /**
     * The fields besides the displacement (Table 7.1, pg-methods.md section
     * 12.2).
     */
    enum class Fields
    {
      displacement, //!< u only (Unl, U1, U2; FEM = Q1 in 2-D, H1 in 3-D)
      /**
       * u with the pressure p and the dilatation Theta constant per element
       * and condensed: UnlP0 (eq. 6.9, per family) and, for FEM and the
       * FE cells of a coupled model, Q1P0 (2-D) / H1P0 (3-D) per cell
       */
      condensed_p0,
      /**
       * U2P1 (eq. 6.10, pg-methods.md section 12.2.2): u (WTE2) with p and
       * Theta linear per family (p^k + grad p^k . (X - X^k)) and condensed;
       * the FE cells of a coupled model are Q1P0/H1P0
       */
      condensed_p1,
      /**
       * U2P1C (eq. 6.11, pg-methods.md section 12.2.2) and Unl+P1C (eqs.
       * 6.12-6.16, section 12.2.3): p and Theta are nodal unknowns of the
       * particles (two extra global DoFs each, dofs/field_layout.h), linear
       * in each family with the gradient of the family's shape functions
       * at the master; Unl+P1C adds a condensed bubble (#bubble). The FE
       * cells of a coupled model are Q1P0/H1P0.
       */
      nodal_p1,
      /**
       * IUnlP0 (pg-methods.md section 12.2.1, Table 7.1): the
       * incompressible UnlP0, Theta = 1 and p^k constant per family; p^k
       * cannot be condensed (K_pp = 0), so it is a global DoF, the one
       * extra nodal field of particle k (dofs/field_layout.h). Meshfree
       * models only (no FE counterpart), nu = 0.5.
       */
      incompressible_p0
    };

    /** The VC correction function (eqs. 5.60-5.64). */
    enum class CorrectionFunction
    {
      v1, //!< constant, eq. (5.60)
      v2, //!< diagonal WLS2 second derivatives, eq. (5.61)
      v3, //!< MLS1 value at the master minus delta, eq. (5.62)
      v4, //!< WLS2 value at the master minus delta, eq. (5.63)
      v5  //!< V3 with the bond projector, eq. (5.64)
    };

    /** Boundary treatment of the VC system (section 11.5). */
    enum class VCBoundary
    {
      p, //!< correction factors fixed at d+1 particles, geometric targets
      s, //!< correction factors fixed at all surface particles
      sn //!< normal component fixed at surface particles (default)
    };

    Method method;
    Points points;
    /**
     * U1SIG (eqs. 6.21-6.28, pg-methods.md section 12.3.3): the U1 families
     * (points = u1) with the implicit-gradient stabilisation
     */
    bool implicit_gradients = false;
    /**
     * The mixed fields. They also decide the FE cells of a coupled model:
     * Q1P0/H1P0 cells with UnlP0 families, Q1 cells otherwise.
     */
    Fields fields = Fields::displacement;
    /**
     * Unl+P1C: the displacement of every family is enriched with a bubble
     * u_b (eqs. 6.12-6.16), condensed per family.
     */
    bool bubble = false;
    /** First-order variational consistency (section 11). */
    bool variational_consistency;
    /**
     * Also second-order variational consistency, "VC2" (section 11.6);
     * implies variational_consistency and Method::ppg2.
     */
    bool               second_order_consistency;
    CorrectionFunction correction_function;
    VCBoundary         vc_boundary;
    /** Bond correction (eq. 5.55) of the trial functions. */
    bool bond_correction;
    /**
     * True if the bond correction is on only because Table 7.1 makes it the
     * default of every first-order formulation (Unl): the user wrote
     * neither "BC" nor "noBC". Such a code meant "without BC" before pg
     * followed the table, hence the notice of notice().
     */
    bool bond_correction_by_default;
    /** The code as the user wrote it, normalised to single spaces. */
    std::string written;
    /**
     * The resolved code with every default written out, e.g.
     * "VCBCPPG V3sn Unl TL" for the user's "VCPPG Unl"; "PBG Unl noBC TL"
     * when the bond correction is switched off. Parsing it again gives the
     * same formulation.
     */
    std::string text;

    /**
     * A one-line notice if the code relies on a default that changed its
     * meaning (the bond correction of Table 7.1), else an empty string.
     */
    std::string
    notice() const;

    /**
     * True for every mixed (u, p, Theta) code: UnlP0, U2P1, U2P1C, Unl+P1C
     * and FEM Q1P0/H1P0. Their FE cells are Q1P0/H1P0 and their material
     * needs the isochoric/volumetric split.
     */
    bool
    mixed() const
    {
      return fields != Fields::displacement;
    }
    /**
     * True for the mixed codes whose p and Theta are condensed per family
     * (UnlP0, U2P1, FEM Q1P0/H1P0); false for U2P1C and Unl+P1C, whose p
     * and Theta are nodal unknowns.
     */
    bool
    condensed_fields() const
    {
      return fields == Fields::condensed_p0 || fields == Fields::condensed_p1;
    }
    /**
     * The number of extra nodal fields of the particles: 2 (p and Theta)
     * for U2P1C and Unl+P1C, 1 (p of the particle's family) for IUnlP0,
     * else 0.
     */
    unsigned int
    n_nodal_fields() const
    {
      return fields == Fields::nodal_p1          ? 2 :
             fields == Fields::incompressible_p0 ? 1 :
                                                   0;
    }

    /** True for IUnlP0: exactly incompressible, nu = 0.5. */
    bool
    incompressible() const
    {
      return fields == Fields::incompressible_p0;
    }

    /**
     * The polynomial degree of the condensed p and Theta of the families:
     * 0 (UnlP0, and the FE cells of every mixed code) or 1 (U2P1).
     */
    unsigned int
    condensed_pressure_degree() const
    {
      return fields == Fields::condensed_p1 ? 1 : 0;
    }

    /** "PBG", "PPG", "PPG2", "CPD" or "FEM". */
    std::string
    method_name() const;

    /**
     * The two formulations U1SUnl is made of: its underintegrated part
     * (this code with U1 and without BC: the real material at the master)
     * and its stabilisation (this code with Unl: the pseudo-energy on every
     * member). Each has its own VC correction (section 12.3.2: "VC must be
     * performed twice"). For the other codes both return this code.
     */
    FormulationCode
    underintegrated_part() const;
    FormulationCode
    stabilisation_part() const;
  };

  /**
   * Parse @p code. Throws with a message that lists the valid parts if the
   * code is unknown, contradictory or not yet available.
   */
  FormulationCode
  parse_formulation_code(const std::string &code);
} // namespace pg

#endif
