#include <pg/base/exceptions.h>
#include <pg/materials/material.h>
#include <pg/materials/material_registry.h>

#include <deal.II/base/utilities.h>

#include <cmath>

namespace pg
{
  namespace Materials
  {
    PluginRegistry<MaterialPlugin> &
    material_registry()
    {
      static PluginRegistry<MaterialPlugin> registry;
      return registry;
    }



    template <int dim>
    std::unique_ptr<Material<dim>>
    create_material(const Parameters::Material &parameters)
    {
      AssertThrow(parameters.plane == "strain" || parameters.plane == "stress",
                  ExcBadParameter("Material/Plane",
                                  parameters.plane,
                                  "it must be 'strain' or 'stress'."));
      AssertThrow(dim == 2 || parameters.plane == "strain",
                  ExcBadParameter("Material/Plane",
                                  parameters.plane,
                                  "plane stress exists in 2-D only."));

      // The model's own checks (e.g. no plane stress for neo-Hooke) are in
      // its constructor.
      return material_registry()
        .get(parameters.model, "Material/Model")
        .template create<dim>(parameters);
    }



    template <int dim>
    double
    checked_jacobian(const Tensor<2, dim> &F, const std::string &model)
    {
      const double J = determinant(F);
      AssertThrow(J > 0.,
                  ExcMessage("The deformation gradient has J = det F = " +
                             Utilities::to_string(J) +
                             " <= 0: the element is inverted, and the " +
                             model +
                             " material is undefined there. Reduce the load "
                             "step by increasing 'Load steps' in subsection "
                             "'Loading'."));
      return J;
    }

    template double
    checked_jacobian(const Tensor<2, 2> &, const std::string &);
    template double
    checked_jacobian(const Tensor<2, 3> &, const std::string &);



    double
    von_mises_stress(const Tensor<2, 3> &sigma)
    {
      // sqrt(3/2 dev(sigma) : dev(sigma)).
      const double mean = (sigma[0][0] + sigma[1][1] + sigma[2][2]) / 3.;

      double dev_dev = 0.;
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          {
            const double s = sigma[a][b] - (a == b ? mean : 0.);
            dev_dev += s * s;
          }
      return std::sqrt(1.5 * dev_dev);
    }



    template std::unique_ptr<Material<2>>
    create_material<2>(const Parameters::Material &parameters);
    template std::unique_ptr<Material<3>>
    create_material<3>(const Parameters::Material &parameters);
  } // namespace Materials
} // namespace pg
