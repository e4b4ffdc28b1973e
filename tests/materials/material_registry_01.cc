// The material registry: the registered names in their listing order, the
// 'Model' selection and documentation built from them (those of before the
// registry, plus the isochoric-volumetric neo-Hooke and J2 plasticity),
// creating each material
// by name in 2-D and 3-D, the model's own checks in its constructor, and the
// message for an unknown name, which lists the registered names.

#include <pg/base/parameters.h>
#include <pg/materials/isochoric_volumetric_neo_hooke.h>
#include <pg/materials/j2_plasticity.h>
#include <pg/materials/linear_elastic.h>
#include <pg/materials/material_registry.h>
#include <pg/materials/neo_hooke.h>
#include <pg/materials/saint_venant_kirchhoff.h>

#include "../tests.h"

#include <sstream>

using namespace pg;

Parameters::Material
make_parameters(const std::string &model, const std::string &plane)
{
  Parameters::Material parameters;
  parameters.model          = model;
  parameters.youngs_modulus = 100.;
  parameters.poissons_ratio = 0.3;
  parameters.density        = 1.;
  parameters.plane          = plane;
  return parameters;
}



std::string
message_of(const std::function<void()> &f)
{
  try
    {
      f();
    }
  catch (const ExceptionBase &e)
    {
      const std::string text = exception_message(e);
      return text.substr(text.find_first_not_of(' '));
    }
  return "(no exception)";
}



template <int dim>
void
check_create()
{
  using namespace Materials;
  AssertThrow(dynamic_cast<LinearElastic<dim> *>(
                create_material<dim>(
                  make_parameters("linear elastic", "strain"))
                  .get()) != nullptr,
              ExcInternalError());
  AssertThrow(dynamic_cast<SaintVenantKirchhoff<dim> *>(
                create_material<dim>(
                  make_parameters("saint venant kirchhoff", "strain"))
                  .get()) != nullptr,
              ExcInternalError());
  AssertThrow(
    dynamic_cast<NeoHooke<dim> *>(
      create_material<dim>(make_parameters("neo-Hooke", "strain")).get()) !=
      nullptr,
    ExcInternalError());
  AssertThrow(dynamic_cast<IsochoricVolumetricNeoHooke<dim> *>(
                create_material<dim>(
                  make_parameters("isochoric-volumetric neo-Hooke", "strain"))
                  .get()) != nullptr,
              ExcInternalError());
  AssertThrow(
    dynamic_cast<J2Plasticity<dim> *>(
      create_material<dim>(make_parameters("J2 plasticity", "strain")).get()) !=
      nullptr,
    ExcInternalError());
  // Only J2 plasticity has state (C_p^-1, alpha, the yield flag).
  for (const std::string &name : material_registry().names())
    AssertThrow(create_material<dim>(make_parameters(name, "strain"))
                    ->n_state_variables() == (name == "J2 plasticity" ? 8 : 0),
                ExcInternalError());
  deallog << dim << "-D: each registered material created by name" << std::endl;
}



int
main()
{
  initlog();
  const PluginRegistry<Materials::MaterialPlugin> &registry =
    Materials::material_registry();

  const std::vector<std::string> expected = {"linear elastic",
                                             "saint venant kirchhoff",
                                             "neo-Hooke",
                                             "isochoric-volumetric neo-Hooke",
                                             "J2 plasticity"};
  AssertThrow(registry.names() == expected, ExcInternalError());
  AssertThrow(registry.selection() ==
                "linear elastic|saint venant kirchhoff|neo-Hooke|"
                "isochoric-volumetric neo-Hooke|J2 plasticity",
              ExcInternalError());
  AssertThrow(
    registry.documentation() ==
      "'linear elastic' (small strain, P = sigma(eps)), 'saint "
      "venant kirchhoff' (S = lambda tr(E) 1 + 2 mu E, eq. 2.45), "
      "'neo-Hooke' (compressible, eq. 2.42), 'isochoric-volumetric "
      "neo-Hooke' (mu/2 (tr b_iso - 3) + K/4 (J^2 - 1 - 2 ln J), eqs. "
      "2.43-2.44) or 'J2 plasticity' (finite von Mises plasticity, F = Fe "
      "Fp, with nonlinear isotropic hardening, eqs. 2.46-2.54, 4.41)",
    ExcInternalError());
  for (const std::string &name : registry.names())
    deallog << "registered: " << name << " ("
            << registry.find(name)->description << ")" << std::endl;
  AssertThrow(registry.find("mooney rivlin") == nullptr, ExcInternalError());

  // A plugin of its own kind: the listing order is (position, name).
  struct Dummy
  {
    std::string  name, description;
    unsigned int listing_position;
  };
  PluginRegistry<Dummy> dummies;
  dummies.add({"b", "", 5});
  dummies.add({"c", "", 1});
  dummies.add({"a", "", 5});
  AssertThrow(dummies.selection() == "c|a|b", ExcInternalError());
  AssertThrow(dummies.listing() == "'c', 'a' or 'b'", ExcInternalError());
  const std::string twice = message_of([&]() { dummies.add({"a", "", 0}); });
  AssertThrow(twice.find("registered twice") != std::string::npos,
              ExcInternalError());
  deallog << "twice: " << twice << std::endl;

  check_create<2>();
  check_create<3>();

  // The 'Model' entry: the parser rejects a name that is not registered,
  // and accepts a registered one.
  {
    ParameterHandler prm;
    Parameters::Material::declare_parameters(prm);
    AssertThrow(message_of([&]() {
                  prm.parse_input_from_string(
                    "subsection Material\n set Model = mooney rivlin\nend\n");
                }) != "(no exception)",
                ExcInternalError());
    prm.parse_input_from_string(
      "subsection Material\n set Model = saint venant kirchhoff\nend\n");
    Parameters::Material parameters;
    parameters.parse_parameters(prm);
    AssertThrow(parameters.model == "saint venant kirchhoff" &&
                  parameters.model_entries.empty(),
                ExcInternalError());
    deallog << "Model = " << parameters.model << " parsed" << std::endl;
  }

  const std::string unknown = message_of([]() {
    Materials::create_material<2>(make_parameters("mooney rivlin", "strain"));
  });
  AssertThrow(unknown ==
                "The entry 'Material/Model' has the value <mooney rivlin>, "
                "but it must be one of 'linear elastic', 'saint venant "
                "kirchhoff', 'neo-Hooke', 'isochoric-volumetric neo-Hooke' or "
                "'J2 plasticity'.",
              ExcInternalError());
  deallog << "unknown model: " << unknown << std::endl;

  const std::string neo_hooke_stress = message_of([]() {
    Materials::create_material<2>(make_parameters("neo-Hooke", "stress"));
  });
  AssertThrow(neo_hooke_stress ==
                "The entry 'Material/Plane' has the value <stress>, but plane "
                "stress is not yet available for 'Model = neo-Hooke'; use "
                "'Plane = strain'.",
              ExcInternalError());
  deallog << "neo-Hooke in plane stress: " << neo_hooke_stress << std::endl;
}
