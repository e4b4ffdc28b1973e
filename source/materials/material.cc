#include <pg/base/exceptions.h>
#include <pg/materials/linear_elastic.h>
#include <pg/materials/material.h>
#include <pg/materials/neo_hooke.h>
#include <pg/materials/saint_venant_kirchhoff.h>

#include <cmath>

namespace pg
{
  namespace Materials
  {
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

      if (parameters.model == "linear elastic")
        return std::make_unique<LinearElastic<dim>>(parameters);
      else if (parameters.model == "saint venant kirchhoff")
        return std::make_unique<SaintVenantKirchhoff<dim>>(parameters);
      else if (parameters.model == "neo-Hooke")
        {
          AssertThrow(parameters.plane == "strain",
                      ExcBadParameter("Material/Plane",
                                      parameters.plane,
                                      "plane stress is not yet available "
                                      "for 'Model = neo-Hooke'; use 'Plane "
                                      "= strain'."));
          return std::make_unique<NeoHooke<dim>>(parameters);
        }

      AssertThrow(false,
                  ExcBadParameter("Material/Model",
                                  parameters.model,
                                  "it must be one of 'linear elastic', "
                                  "'saint venant kirchhoff' or "
                                  "'neo-Hooke'."));
      return nullptr;
    }



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
