#include <pg/base/formulation_code.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

namespace pg
{
  namespace
  {
    const std::string valid_parts =
      "Valid codes read '[VC|VC2][BC]<method> [V<n><b>] <points> [noBC] "
      "[TL]' (Table 7.1) with <method> = PBG, PPG (= PPG1), PPG1 or PPG2, "
      "the VC correction function V1 ... V5 (default V3 for PPG, V5 for "
      "PBG, V1 for VC2) and its boundary option <b> = p, s or sn (default "
      "sn; VC2 takes s), and <points> = Unl (default), U1 (PBG only), U2, "
      "UnlP0 (mixed, PBG or PPG), IUnlP0 (incompressible, nu = 0.5, PBG or "
      "PPG), U2P1, U2P1C or Unl+P1C (mixed, PBG only), U1SUnl or U1SIG "
      "(stabilised U1, PBG only). "
      "The bond correction BC is the default of Unl; 'noBC' switches it "
      "off. E.g. 'VCPPG V3sn Unl' (= 'VCBCPPG V3sn Unl TL'), 'VCPBG Unl' "
      "(= 'VCBCPBG V5sn Unl TL'), 'PBG Unl noBC', 'PBG U1', "
      "'VC2PPG V1s U2', 'VCPPG V3sn UnlP0', 'VCPBG U2P1', 'VCPBG U1SUnl', "
      "'VCPBG U1SIG', 'VCPBG Unl+P1C'; or 'FEM' (Q1/H1; P1 on triangle "
      "and tetrahedron meshes), 'FEM Q1P0' (H1P0 in 3-D; not on triangles "
      "and tetrahedra, where it would be P1-P0, which locks) or 'CPD'.";



    [[noreturn]] void
    reject(const std::string &code, const std::string &reason)
    {
      AssertThrow(false,
                  ExcMessage("The entry 'Formulation' in subsection "
                             "'Discretization' has the value <" +
                             code + ">: " + reason + " " + valid_parts));
      std::abort();
    }



    bool
    starts_with(const std::string &text, const std::string &prefix)
    {
      return text.compare(0, prefix.size(), prefix) == 0;
    }



    /**
     * The code with every default written out. PPG2 under VC2 is written
     * "VC2PPG", as the source does ("based on the PPG2 formulation").
     */
    std::string
    resolved_text(const FormulationCode &code)
    {
      using Method  = FormulationCode::Method;
      const bool p0 = (code.fields == FormulationCode::Fields::condensed_p0);
      if (code.method == Method::fem)
        return p0 ? "FEM Q1P0" : "FEM";
      if (code.method == Method::cpd)
        return code.method_name();
      std::string text = code.second_order_consistency ? "VC2" :
                         code.variational_consistency  ? "VC" :
                                                         "";
      if (code.bond_correction)
        text += "BC";
      text += (code.method == Method::ppg2 && code.second_order_consistency ?
                 std::string("PPG") :
                 code.method_name());
      if (code.variational_consistency)
        {
          using CF = FormulationCode::CorrectionFunction;
          using B  = FormulationCode::VCBoundary;
          text += std::string(" V") +
                  (code.correction_function == CF::v1 ? "1" :
                   code.correction_function == CF::v2 ? "2" :
                   code.correction_function == CF::v3 ? "3" :
                   code.correction_function == CF::v4 ? "4" :
                                                        "5") +
                  (code.vc_boundary == B::p ? "p" :
                   code.vc_boundary == B::s ? "s" :
                                              "sn");
        }
      using Points = FormulationCode::Points;
      text += (p0                    ? " UnlP0" :
               code.incompressible() ? " IUnlP0" :
               code.fields == FormulationCode::Fields::condensed_p1 ?
                                       " U2P1" :
               code.fields == FormulationCode::Fields::nodal_p1 ?
                                       (code.bubble ? " Unl+P1C" : " U2P1C") :
               code.points == Points::unl                           ? " Unl" :
               code.points == Points::u1 && code.implicit_gradients ? " U1SIG" :
               code.points == Points::u1                            ? " U1" :
               code.points == Points::u2                            ? " U2" :
                                                                      " U1SUnl");
      if ((code.points == Points::unl || code.points == Points::u1s_unl) &&
          !code.bond_correction)
        text += " noBC";
      return text + " TL";
    }
  } // namespace



  std::string
  FormulationCode::method_name() const
  {
    switch (method)
      {
        case Method::fem:
          return "FEM";
        case Method::pbg:
          return "PBG";
        case Method::ppg1:
          return "PPG";
        case Method::ppg2:
          return "PPG2";
        case Method::cpd:
          return "CPD";
      }
    Assert(false, ExcInternalError());
    return "";
  }



  std::string
  FormulationCode::notice() const
  {
    if (!bond_correction_by_default)
      return "";
    return "Note: the formulation <" + written + "> is read as <" + text +
           ">: Table 7.1 makes the bond correction BC the default of every "
           "first-order formulation (pg read it without BC before December "
           "2026); write <" +
           written + " noBC> to switch BC off.";
  }



  FormulationCode
  FormulationCode::underintegrated_part() const
  {
    if (points != Points::u1s_unl)
      return *this;
    FormulationCode part            = *this;
    part.points                     = Points::u1;
    part.bond_correction            = false;
    part.bond_correction_by_default = false;
    part.text                       = resolved_text(part);
    return part;
  }



  FormulationCode
  FormulationCode::stabilisation_part() const
  {
    if (points != Points::u1s_unl)
      return *this;
    FormulationCode part = *this;
    part.points          = Points::unl;
    part.text            = resolved_text(part);
    return part;
  }



  FormulationCode
  parse_formulation_code(const std::string &code)
  {
    std::vector<std::string> words;
    for (const std::string &w : Utilities::split_string_list(code, ' '))
      if (!w.empty())
        words.push_back(w);
    if (words.empty())
      reject(code, "it is empty.");

    FormulationCode result;
    for (const std::string &w : words)
      result.written += (result.written.empty() ? "" : " ") + w;
    result.text                       = result.written;
    result.bond_correction            = false;
    result.bond_correction_by_default = false;
    result.points                     = FormulationCode::Points::unl;
    result.variational_consistency    = false;
    result.second_order_consistency   = false;
    result.vc_boundary                = FormulationCode::VCBoundary::sn;
    result.correction_function        = FormulationCode::CorrectionFunction::v1;
    bool have_correction_function     = false;

    // The first word: corrections, then the method.
    std::string head = words[0];
    for (;;)
      {
        if (starts_with(head, "VC"))
          {
            if (result.variational_consistency)
              reject(code, "VC appears twice.");
            result.variational_consistency  = true;
            result.second_order_consistency = starts_with(head, "VC2");
            head = head.substr(result.second_order_consistency ? 3 : 2);
          }
        else if (starts_with(head, "BC"))
          {
            if (result.bond_correction)
              reject(code, "BC appears twice.");
            result.bond_correction = true;
            head                   = head.substr(2);
          }
        else
          break;
      }
    if (head == "PBG")
      result.method = FormulationCode::Method::pbg;
    else if (head == "PPG1" ||
             (head == "PPG" && !result.second_order_consistency))
      result.method = FormulationCode::Method::ppg1;
    else if (head == "PPG" && result.second_order_consistency)
      result.method = FormulationCode::Method::ppg2; // "based on PPG2" (7.1)
    else if (head == "PPG2")
      result.method = FormulationCode::Method::ppg2;
    else if (head == "CPD")
      {
        result.method = FormulationCode::Method::cpd;
        if (result.bond_correction || result.variational_consistency)
          reject(code, "CPD takes no corrections (it has no shape functions).");
        if (words.size() > 1)
          reject(code,
                 "CPD takes no further parts; its constants are in "
                 "subsection 'CPD'.");
        return result;
      }
    else if (head == "FEM")
      {
        result.method = FormulationCode::Method::fem;
        if (result.bond_correction || result.variational_consistency)
          reject(code, "FEM takes no corrections.");
        if (words.size() > 2)
          reject(code,
                 "FEM takes at most one further part, the element: Q1 "
                 "(default; H1 in 3-D) or Q1P0 (H1P0 in 3-D).");
        if (words.size() == 2)
          {
            if (words[1] == "Q1P0" || words[1] == "H1P0")
              result.fields = FormulationCode::Fields::condensed_p0;
            else if (words[1] != "Q1" && words[1] != "H1")
              reject(code,
                     "the element <" + words[1] +
                       "> is unknown; FEM takes Q1 (default; H1 in 3-D) or "
                       "Q1P0 (H1P0 in 3-D).");
          }
        result.text = resolved_text(result);
        return result;
      }
    else
      reject(code, "the method <" + head + "> is unknown.");

    bool have_points = false, have_reference = false, no_bc = false;
    for (unsigned int i = 1; i < words.size(); ++i)
      {
        const std::string &w = words[i];
        if (w == "Unl" || w == "U1" || w == "U2" || w == "UnlP0" ||
            w == "U2P1" || w == "U1SUnl" || w == "U1SIG" || w == "U2P1C" ||
            w == "Unl+P1C" || w == "IUnlP0")
          {
            if (have_points)
              reject(code, "it names two formulations.");
            have_points = true;
            result.points =
              ((w == "U1" || w == "U1SIG") ? FormulationCode::Points::u1 :
               (w == "U2" || w == "U2P1" || w == "U2P1C") ?
                                             FormulationCode::Points::u2 :
               w == "U1SUnl" ? FormulationCode::Points::u1s_unl :
                               FormulationCode::Points::unl);
            if (w == "UnlP0")
              result.fields = FormulationCode::Fields::condensed_p0;
            if (w == "IUnlP0")
              result.fields = FormulationCode::Fields::incompressible_p0;
            if (w == "U2P1")
              result.fields = FormulationCode::Fields::condensed_p1;
            if (w == "U2P1C" || w == "Unl+P1C")
              result.fields = FormulationCode::Fields::nodal_p1;
            result.bubble             = (w == "Unl+P1C");
            result.implicit_gradients = (w == "U1SIG");
          }
        else if (w == "noBC")
          {
            if (no_bc)
              reject(code, "noBC appears twice.");
            if (result.bond_correction)
              reject(code, "it asks for BC and noBC.");
            no_bc = true;
          }
        else if (w == "TL")
          {
            if (have_reference)
              reject(code, "it names the reference configuration twice.");
            have_reference = true;
          }
        else if (w == "UL")
          reject(code,
                 "the updated Lagrangian form (UL) is not yet available; "
                 "use TL.");
        else if (w.size() >= 2 && w[0] == 'V' && w[1] >= '1' && w[1] <= '5')
          {
            if (have_correction_function)
              reject(code, "it names two VC correction functions.");
            have_correction_function   = true;
            using CF                   = FormulationCode::CorrectionFunction;
            result.correction_function = (w[1] == '1' ? CF::v1 :
                                          w[1] == '2' ? CF::v2 :
                                          w[1] == '3' ? CF::v3 :
                                          w[1] == '4' ? CF::v4 :
                                                        CF::v5);
            const std::string option   = w.substr(2);
            if (option == "p")
              result.vc_boundary = FormulationCode::VCBoundary::p;
            else if (option == "s")
              result.vc_boundary = FormulationCode::VCBoundary::s;
            else if (option == "sn" || option.empty())
              result.vc_boundary = FormulationCode::VCBoundary::sn;
            else
              reject(code,
                     "the VC boundary option <" + option +
                       "> is unknown; use p, s or sn.");
          }
        else
          reject(code, "the part <" + w + "> is unknown.");
      }

    if (have_correction_function && !result.variational_consistency)
      reject(code,
             "a correction function (V1 ... V5) needs the VC prefix, e.g. "
             "'VCPPG V3sn Unl'.");
    // Table 7.1: V3 for PPG, V5 for PBG (whatever the points; section 6.1
    // uses V4 for U2, but V4 leaves the VC system singular with the default
    // sn, doc/ambiguities.md item 22); V1 for VC2
    if (result.variational_consistency && !have_correction_function)
      result.correction_function =
        (result.second_order_consistency ?
           FormulationCode::CorrectionFunction::v1 :
         result.method == FormulationCode::Method::pbg ?
           FormulationCode::CorrectionFunction::v5 :
           FormulationCode::CorrectionFunction::v3);
    if (result.second_order_consistency)
      {
        if (result.method != FormulationCode::Method::ppg2)
          reject(code,
                 "the second-order correction VC2 is built on PPG2 (Table "
                 "7.1, section 11.6); write 'VC2PPG' or 'VC2PPG2'.");
        if (!have_correction_function)
          result.vc_boundary = FormulationCode::VCBoundary::s;
        if (result.vc_boundary != FormulationCode::VCBoundary::s)
          reject(code,
                 "VC2 is available with the boundary option s only, e.g. "
                 "'VC2PPG V1s U2'.");
        if (result.correction_function ==
            FormulationCode::CorrectionFunction::v5)
          reject(code,
                 "V5 (the bond projector) belongs to PBG; use V1, V3 or V4 "
                 "with VC2.");
        if (result.correction_function ==
            FormulationCode::CorrectionFunction::v2)
          reject(code,
                 "V2 corrects each direction with its own second "
                 "derivative, and the second-order correction VC2 needs "
                 "one correction function for all; use V1, V3 or V4 with "
                 "VC2.");
      }
    if (result.fields == FormulationCode::Fields::condensed_p0 &&
        result.method == FormulationCode::Method::ppg2)
      reject(code,
             "UnlP0 is defined for PBG and PPG (= PPG1) (eqs. 6.2, 6.3, "
             "6.7): its volumetric point at the master has the test "
             "functions of PPG1, whose VC condition PPG2 does not satisfy. "
             "Write 'VCPPG V3sn UnlP0' or 'VCPBG V5sn UnlP0'.");
    if (result.incompressible() &&
        result.method == FormulationCode::Method::ppg2)
      reject(code,
             "IUnlP0 is the incompressible UnlP0 (section 6.2.1), defined "
             "for PBG and PPG (= PPG1); write 'VCPPG V3sn IUnlP0' or "
             "'VCPBG V5sn IUnlP0'.");
    if (result.fields == FormulationCode::Fields::condensed_p1 &&
        result.method != FormulationCode::Method::pbg)
      reject(code,
             "U2P1 (eq. 6.10) has p and Theta linear per family, fitted to "
             "J at every member; a Petrov-Galerkin family has its "
             "volumetric point at the master only, where a linear field "
             "is undetermined. U2P1 is a PBG formulation: write 'VCPBG "
             "U2P1'.");
    if (result.fields == FormulationCode::Fields::nodal_p1 &&
        result.method != FormulationCode::Method::pbg)
      reject(code,
             std::string(result.bubble ? "Unl+P1C" : "U2P1C") +
               " (sections 6.2.2, 6.2.3) is defined for PBG: its nodal "
               "pressure and dilatation are interpolated at every member of "
               "a family. Write 'VCPBG " +
               (result.bubble ? "V5sn Unl+P1C" : "U2P1C") + "'.");
    if (result.implicit_gradients &&
        result.method != FormulationCode::Method::pbg)
      reject(code,
             "U1SIG (eqs. 6.21-6.28) stabilises the underintegrated PBG U1 "
             "with implicit gradients; use 'VCPBG U1SIG'.");
    if (result.points == FormulationCode::Points::u1 &&
        result.method != FormulationCode::Method::pbg)
      reject(code,
             "U1 (one evaluation point per family) is the underintegrated "
             "PBG; use 'PBG U1'.");
    if (result.points == FormulationCode::Points::u1s_unl &&
        result.method != FormulationCode::Method::pbg)
      reject(code,
             "U1SUnl (eq. 6.18) stabilises the underintegrated PBG U1 with "
             "a PBG Unl pseudo-energy; use 'VCPBG U1SUnl'.");

    // The bond correction (Table 7.1: "default for all first order
    // formulations"). U1 evaluates at the master only, where the bond is
    // zero and eq. (5.55) does nothing; U2 is second order, which BC would
    // destroy (section 5.3.1). doc/ambiguities.md has the reading.
    if (result.points == FormulationCode::Points::u1s_unl)
      result.bond_correction = !no_bc; // BC of its Unl part; no notice
    else if (result.points == FormulationCode::Points::unl)
      {
        // (UnlP0 is newer than that change: no notice)
        if (!result.bond_correction && !no_bc &&
            result.fields == FormulationCode::Fields::displacement)
          result.bond_correction_by_default = true;
        result.bond_correction = !no_bc;
      }
    else if (result.bond_correction)
      reject(code,
             result.points == FormulationCode::Points::u1 ?
               "BC acts on the bonds of the evaluation points (eq. 5.55, "
               "j != k), and U1 has only the master, where the bond is "
               "zero: BC would do nothing. Write the code without BC." :
               "BC (eq. 5.55) keeps linear consistency only; on the "
               "second-order U2 it destroys the quadratic consistency "
               "that U2 is for. Write the code without BC.");

    result.text = resolved_text(result);
    return result;
  }
} // namespace pg
