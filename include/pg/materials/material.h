#ifndef pg_materials_material_h
#define pg_materials_material_h

#include <pg/base/global.h>
#include <pg/base/parameters.h>

#include <deal.II/base/tensor.h>

#include <memory>

namespace pg
{
  /**
   * Constitutive models. A material maps a deformation gradient F to the
   * first Piola-Kirchhoff stress P and its consistent tangent
   * A_ABCD = dP_AB / dF_CD. It never knows whether it is evaluated at a Gauss
   * point of a Q1 cell or at an evaluation point of a PG family (one kernel
   * for both, architecture.md section 2).
   *
   * In 2-D the tensors are the in-plane parts: plane strain (F_33 = 1) or,
   * where a model supports it, plane stress (P_33 = 0, F_33 eliminated).
   */
  namespace Materials
  {
    template <int dim>
    class Material
    {
    public:
      virtual ~Material() = default;

      /**
       * First Piola-Kirchhoff stress @p P (force per reference area) and
       * tangent @p A = dP/dF at the deformation gradient @p F.
       */
      virtual void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const = 0;

      /** The stress alone (cheaper where no tangent is needed). */
      virtual Tensor<2, dim>
      first_piola_stress(const Tensor<2, dim> &F) const = 0;

      /**
       * The full 3x3 Cauchy stress sigma = P F^T / J, including the
       * out-of-plane normal stress in 2-D plane strain (zero in plane
       * stress). Used for output (von Mises).
       */
      virtual Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &F) const = 0;

      /** Strain energy per reference volume W(F). */
      virtual double
      strain_energy_density(const Tensor<2, dim> &F) const = 0;
    };

    /**
     * Create the material named by 'Model' in subsection 'Material'.
     */
    template <int dim>
    std::unique_ptr<Material<dim>>
    create_material(const Parameters::Material &parameters);

    /** von Mises stress of a 3x3 Cauchy stress. */
    double
    von_mises_stress(const Tensor<2, 3> &sigma);
  } // namespace Materials
} // namespace pg

#endif
