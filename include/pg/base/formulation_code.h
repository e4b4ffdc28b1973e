#ifndef pg_base_formulation_code_h
#define pg_base_formulation_code_h

#include <pg/base/global.h>

#include <string>

namespace pg
{
  /**
   * A formulation code of the dissertation (Table 7.1), e.g.
   * "BCPBG Unl TL", parsed into its parts (architecture.md section 5).
   * Parts that are not built yet (VC, VC2, V1..V5, U2, the mixed
   * formulations, UL) are rejected with a "not yet available" message,
   * never ignored.
   */
  struct FormulationCode
  {
    /** How the family residual is formed (pg-methods.md section 7.4). */
    enum class Method
    {
      fem,  //!< Q1 finite elements everywhere
      pbg,  //!< Bubnov-Galerkin, eq. (4.30)
      ppg1, //!< Petrov-Galerkin, eq. (4.21) ("PPG")
      ppg2  //!< Petrov-Galerkin, eq. (4.22)
    };

    /** Which evaluation points a family has. */
    enum class Points
    {
      unl, //!< every family member (PBG) or every bond (PPG)
      u1   //!< the master only (underintegrated PBG = classical correspondence)
    };

    Method method;
    Points points;
    /** Bond correction (eq. 5.55) of the trial functions. */
    bool bond_correction;
    /** The code as the user wrote it, normalised to single spaces. */
    std::string text;

    /** "PBG", "PPG", "PPG2" or "FEM". */
    std::string
    method_name() const;
  };

  /**
   * Parse @p code. Throws with a message that lists the valid parts if the
   * code is unknown, contradictory or not yet available.
   */
  FormulationCode
  parse_formulation_code(const std::string &code);
} // namespace pg

#endif
