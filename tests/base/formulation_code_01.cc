// Formulation codes mean what the dissertation's Table 7.1 says, defaults
// included (issue 11, item 1): BC is the default of every first-order
// formulation (Unl), V3 of PPG, V5 of PBG, sn and TL. Printed for each
// code: the resolved code (which must parse to itself), the bond
// correction, and whether the one-line notice of a changed default is
// given. Then the codes that must be refused, with their reasons. The
// mixed codes UnlP0, U2P1 and FEM Q1P0 / H1P0 (issue 13) are among both.

#include <pg/base/formulation_code.h>

#include "../tests.h"

using namespace pg;

int
main()
{
  initlog();
  for (const std::string code : {"PPG Unl",
                                 "PBG Unl",
                                 "PPG2 Unl",
                                 "VCPPG Unl",
                                 "VCPBG Unl",
                                 "VCPPG V3sn Unl",
                                 "VCPBG V5sn Unl TL",
                                 "VCPPG V1s Unl",
                                 "VCPBG V3p Unl",
                                 "BCPBG Unl TL",
                                 "VCBCPPG V3sn Unl",
                                 "PBG Unl noBC",
                                 "VCPPG V3sn Unl noBC",
                                 "VC2PPG V1s Unl",
                                 "VC2PPG U2",
                                 "VC2PPG V1s U2",
                                 "PPG2 U2",
                                 "PBG U2",
                                 "PBG U1",
                                 "VCPBG U1",
                                 "PBG U1 noBC",
                                 "PBG",
                                 "FEM",
                                 "CPD",
                                 "VCPPG V3sn UnlP0",
                                 "VCPBG UnlP0",
                                 "PBG UnlP0 noBC",
                                 "VCPPG V1sn UnlP0",
                                 "FEM Q1",
                                 "FEM H1",
                                 "FEM Q1P0",
                                 "FEM H1P0",
                                 "VCPBG U1SUnl",
                                 "PBG U1SUnl noBC",
                                 "VCPBG V3s U1SUnl",
                                 "VCPPG V2sn Unl",
                                 "VCPPG V2sn UnlP0",
                                 "VCPBG U2",
                                 "VCPPG U2",
                                 "VC2PPG V4s U2",
                                 "VCPBG U2P1",
                                 "PBG U2P1",
                                 "VCPBG U1SIG",
                                 "PBG U1SIG",
                                 "VCPBG U2P1C",
                                 "PBG U2P1C",
                                 "VCPBG Unl+P1C",
                                 "VCPBG V5sn Unl+P1C noBC",
                                 "VCPBG IUnlP0",
                                 "VCPPG IUnlP0",
                                 "PBG IUnlP0 noBC"})
    {
      const FormulationCode f     = parse_formulation_code(code);
      const FormulationCode again = parse_formulation_code(f.text);
      const bool            same =
        again.implicit_gradients == f.implicit_gradients &&
        again.text == f.text && again.bond_correction == f.bond_correction &&
        again.method == f.method && again.points == f.points &&
        again.variational_consistency == f.variational_consistency &&
        again.correction_function == f.correction_function &&
        again.vc_boundary == f.vc_boundary && again.fields == f.fields &&
        again.bubble == f.bubble && !again.bond_correction_by_default;
      deallog << std::left << std::setw(20) << code << " -> " << std::setw(22)
              << f.text << " BC " << (f.bond_correction ? "on " : "off")
              << (f.notice().empty() ? "" : ", notice")
              << (same ? "" : ", RESOLVED CODE PARSES DIFFERENTLY")
              << std::endl;
    }

  deallog << "Refused:" << std::endl;
  for (const std::string code :
       {"BCPBG U1",          "BCPBG U2",       "BCPBG Unl noBC",
        "PBG Unl noBC noBC", "BCBCPBG Unl",    "VCPBG V2sn Unl",
        "PBG V5sn Unl",      "VC2PPG V1sn U2", "PPG U1",
        "VCPPG Unl UL",      "PBG Unl U2",     "XPBG Unl",
        "VCPPG2 V3sn UnlP0", "PBG UnlP0 Unl",  "VCPPG2 IUnlP0",
        "VCPPG U2P1",        "FEM Q2",         "FEM Q1P0 H1P0",
        "BCPBG U2P1",        "PBG U2P1 U2",    "VCPPG U1SUnl",
        "VCPPG U1SIG",       "VC2PPG V2s U2",  "BCPBG U1SIG",
        "VCPPG Unl+P1C",     "PPG U2P1C",      "BCPBG U2P1C",
        "PBG Unl+P1C U2P1C"})
    try
      {
        parse_formulation_code(code);
        deallog << "  " << code << ": ACCEPTED" << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        // the reason, without the list of valid codes that follows it
        std::string reason = exception_message(e);
        reason             = reason.substr(reason.find(">: ") + 3);
        reason             = reason.substr(0, reason.find(" Valid codes"));
        deallog << "  " << code << ": " << reason << std::endl;
      }
}
