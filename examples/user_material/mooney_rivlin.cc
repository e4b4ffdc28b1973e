// A user's material in its own shared library: a compressible
// Mooney-Rivlin model, registered with pg's material registry when the
// library is loaded (pg_solve: 'set Additional shared libraries =
// ./libmooney_rivlin.so'; a program of your own: link the library). See
// README.md next to this file for the walk-through.
//
// Strain energy per reference volume, with C = F^T F, J = det F,
// I1 = tr C, I2 = (I1^2 - tr C^2) / 2:
//   W = mu/2 (I1 - 3 - 2 ln J) + lambda/4 (J^2 - 1 - 2 ln J)
//       + c2 (I2 - 3 - 4 ln J),
// which is pg's neo-Hooke (eq. 2.42) plus the second invariant term; W and
// P vanish at F = I, and c2 = 0 gives neo-Hooke exactly. Its small-strain
// shear modulus is mu + 2 c2.

#include <pg/base/exceptions.h>
#include <pg/materials/material.h>
#include <pg/materials/material_registry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <cmath>

namespace MyMaterials
{
  using namespace dealii;

  template <int dim>
  class MooneyRivlin : public pg::Materials::Material<dim>
  {
  public:
    MooneyRivlin(const pg::Parameters::Material &parameters)
      : mu(parameters.mu())
      , lambda(parameters.lambda())
      , c2(parameters.model_double("Second constant"))
    {
      AssertThrow(dim == 3 || parameters.plane == "strain",
                  pg::ExcBadParameter("Material/Plane",
                                      parameters.plane,
                                      "plane stress is not available for "
                                      "'Model = Mooney-Rivlin'; use 'Plane = "
                                      "strain'."));
    }

    /** The own entry, in subsection "Material/Mooney-Rivlin". */
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Second constant",
                        "0",
                        Patterns::Double(0),
                        "c2 of the term c2 (I2 - 3 - 4 ln J). Units: force "
                        "per area.");
    }

    static void
    parse_parameters(ParameterHandler &prm, pg::Parameters::Material &p)
    {
      p.model_entries["Second constant"] = prm.get("Second constant");
    }

    void
    evaluate(const Tensor<2, dim> &F,
             Tensor<2, dim>       &P,
             Tensor<4, dim>       &A) const override
    {
      Tensor<4, 3> A3;
      P = in_plane(stress(embed(F), &A3));
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int d = 0; d < dim; ++d)
              A[a][b][c][d] = A3[a][b][c][d];
    }

    Tensor<2, dim>
    first_piola_stress(const Tensor<2, dim> &F) const override
    {
      return in_plane(stress(embed(F), nullptr));
    }

    Tensor<2, 3>
    cauchy_stress(const Tensor<2, dim> &F) const override
    {
      const Tensor<2, 3> F3 = embed(F);
      return stress(F3, nullptr) * transpose(F3) / determinant(F3);
    }

    double
    strain_energy_density(const Tensor<2, dim> &F) const override
    {
      const Tensor<2, 3> F3 = embed(F);
      const double       J  = pg::Materials::checked_jacobian(F, name);
      const Tensor<2, 3> C  = transpose(F3) * F3;
      const double       I1 = trace(C);
      const double       I2 = 0.5 * (I1 * I1 - scalar_product(C, C));
      return 0.5 * mu * (I1 - 3. - 2. * std::log(J)) +
             0.25 * lambda * (J * J - 1. - 2. * std::log(J)) +
             c2 * (I2 - 3. - 4. * std::log(J));
    }

  private:
    static constexpr const char *name = "Mooney-Rivlin";
    const double                 mu, lambda, c2;

    /** F in 3-D: in 2-D plane strain F_33 = 1. */
    static Tensor<2, 3>
    embed(const Tensor<2, dim> &F)
    {
      Tensor<2, 3> F3;
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          F3[a][b] = (a < dim && b < dim) ? F[a][b] : (a == b ? 1. : 0.);
      return F3;
    }

    static Tensor<2, dim>
    in_plane(const Tensor<2, 3> &T)
    {
      Tensor<2, dim> t;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          t[a][b] = T[a][b];
      return t;
    }

    /**
     * P = mu (F - F^-T) + lambda/2 (J^2 - 1) F^-T
     *     + c2 (2 (I1 F - F C) - 4 F^-T)
     * and, unless @p A is nullptr, A_aBcD = dP_aB / dF_cD. In plane strain
     * the in-plane block of the 3-D tangent is the 2-D tangent (F is block
     * diagonal).
     */
    Tensor<2, 3>
    stress(const Tensor<2, 3> &F, Tensor<4, 3> *A) const
    {
      const double       J    = pg::Materials::checked_jacobian(F, name);
      const Tensor<2, 3> Finv = invert(F);
      const Tensor<2, 3> C    = transpose(F) * F;
      const Tensor<2, 3> b    = F * transpose(F);
      const double       I1   = trace(C);
      const Tensor<2, 3> P =
        mu * (F - transpose(Finv)) +
        0.5 * lambda * (J * J - 1.) * transpose(Finv) +
        c2 * (2. * (I1 * F - F * C) - 4. * transpose(Finv));
      if (A != nullptr)
        {
          const double k = mu - 0.5 * lambda * (J * J - 1.) + 4. * c2;
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int B = 0; B < 3; ++B)
              for (unsigned int c = 0; c < 3; ++c)
                for (unsigned int D = 0; D < 3; ++D)
                  {
                    const double ac = (a == c), BD = (B == D);
                    (*A)[a][B][c][D] =
                      mu * ac * BD + k * Finv[B][c] * Finv[D][a] +
                      lambda * J * J * Finv[B][a] * Finv[D][c] +
                      2. * c2 *
                        (2. * F[c][D] * F[a][B] + I1 * ac * BD - ac * C[D][B] -
                         F[a][D] * F[c][B] - b[a][c] * BD);
                  }
        }
      return P;
    }
  };

  template class MooneyRivlin<2>;
  template class MooneyRivlin<3>;

  PG_REGISTER_MATERIAL(MooneyRivlin,
                       "Mooney-Rivlin",
                       "compressible, neo-Hooke plus c2 (I2 - 3 - 4 ln J); "
                       "a user's plugin, examples/user_material")
} // namespace MyMaterials
