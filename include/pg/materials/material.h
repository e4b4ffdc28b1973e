#ifndef pg_materials_material_h
#define pg_materials_material_h

#include <pg/base/global.h>
#include <pg/materials/material_parameters.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <vector>

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

      /**
       * Whether A_ABCD = A_CDAB (true for hyperelastic models, the
       * default). The kernel then computes half of a Bubnov-Galerkin
       * tangent and mirrors it; a model whose (algorithmic) tangent lacks
       * the symmetry (damage, non-associative plasticity) must return
       * false.
       */
      virtual bool
      tangent_has_major_symmetry() const
      {
        return true;
      }

      /**
       * @name State (history) variables
       *
       * A material with history (plasticity, damage, viscosity) keeps
       * n_state_variables() numbers per evaluation point, stored by a
       * QuadraturePointHistory in two copies: the committed state of the
       * last accepted load step and the trial state of the current Newton
       * iterate. The contract of evaluate_with_state():
       * - it reads @p committed_state (the state at the end of the last
       *   accepted step) and F, and writes the whole @p trial_state (the
       *   state at F), so that the result depends on (F, committed) only;
       * - it never reads @p trial_state, so a failed Newton iteration or a
       *   step cut needs no clean-up beyond revert() of the history, and
       *   evaluating twice (residual and tangent) gives the same result;
       * - it is const and touches nothing but its two slices, so points
       *   may be evaluated concurrently (WorkStream) without locks;
       * - P and A are consistent: A = dP/dF at fixed committed state (the
       *   algorithmic tangent of the update).
       * The stateless functions above describe a stateful material at its
       * initial state (initialize_state()).
       */
      /** @{ */

      /** Number of state variables per evaluation point (default 0). */
      virtual unsigned int
      n_state_variables() const
      {
        return 0;
      }

      /**
       * Write the initial state (n_state_variables() numbers) to @p state.
       * The default sets every entry to zero.
       */
      virtual void
      initialize_state(const ArrayView<double> &state) const
      {
        AssertDimension(state.size(), n_state_variables());
        for (double &value : state)
          value = 0.;
      }

      /**
       * The stress @p P and, unless @p A is nullptr, the tangent *@p A at
       * @p F from the committed state; writes the trial state (see the
       * contract above; both slices have n_state_variables() entries). The
       * default, for stateless materials, forwards to evaluate(F, P, A) or
       * first_piola_stress(F). (A name of its own, not an overload of
       * evaluate(), so that a stateless material overriding evaluate()
       * does not hide it.)
       */
      virtual void
      evaluate_with_state(const Tensor<2, dim>          &F,
                          const ArrayView<const double> &committed_state,
                          const ArrayView<double>       &trial_state,
                          Tensor<2, dim>                &P,
                          Tensor<4, dim>                *A) const
      {
        (void)committed_state;
        (void)trial_state;
        AssertDimension(committed_state.size(), n_state_variables());
        AssertDimension(trial_state.size(), n_state_variables());
        if (A != nullptr)
          evaluate(F, P, *A);
        else
          P = first_piola_stress(F);
      }

      /**
       * The full 3x3 Cauchy stress at @p F for the state @p state that
       * belongs to F (the committed state after an accepted step: no
       * update is made). Used for output; the default, for stateless
       * materials, is cauchy_stress(F).
       */
      virtual Tensor<2, 3>
      cauchy_stress_with_state(const Tensor<2, dim>          &F,
                               const ArrayView<const double> &state) const
      {
        (void)state;
        return cauchy_stress(F);
      }

      /**
       * Names of the scalar output quantities derived from the state (for
       * VTU and summary.json), e.g. "equivalent_plastic_strain". Default:
       * none.
       */
      virtual std::vector<std::string>
      state_output_names() const
      {
        return {};
      }

      /**
       * The values of the quantities of state_output_names() at @p state
       * into @p values (same length as state_output_names()).
       */
      virtual void
      state_outputs(const ArrayView<const double> &state,
                    const ArrayView<double>       &values) const
      {
        (void)state;
        (void)values;
        AssertDimension(values.size(), 0);
      }

      /**
       * Whether the material dissipates energy (plastic_work_density() is
       * meaningful); false by default.
       */
      virtual bool
      is_dissipative() const
      {
        return false;
      }

      /**
       * The plastic work done per reference volume up to @p state (energy
       * per volume): the integral of tau : d_p over the history, which
       * for J2 plasticity is int_0^alpha sigma_y(a) da. The dynamic energy
       * account reports its integral over the body. Default: 0.
       */
      virtual double
      plastic_work_density(const ArrayView<const double> &state) const
      {
        (void)state;
        return 0.;
      }
      /** @} */
    };

    /**
     * Create the material named by 'Model' in subsection 'Material', looked
     * up in material_registry() (material_registry.h). Throws
     * ExcBadParameter listing the registered names for an unknown name.
     */
    template <int dim>
    std::unique_ptr<Material<dim>>
    create_material(const Parameters::Material &parameters);

    /**
     * J = det F of a finite strain model named @p model (e.g. "neo-Hooke");
     * throws, with advice, if J <= 0 (an inverted element, where the model
     * is undefined).
     */
    template <int dim>
    double
    checked_jacobian(const Tensor<2, dim> &F, const std::string &model);

    /** von Mises stress of a 3x3 Cauchy stress. */
    double
    von_mises_stress(const Tensor<2, 3> &sigma);
  } // namespace Materials
} // namespace pg

#endif
