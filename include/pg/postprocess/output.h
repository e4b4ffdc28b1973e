#ifndef pg_postprocess_output_h
#define pg_postprocess_output_h

#include <pg/base/global.h>
#include <pg/materials/material.h>
#include <pg/postprocess/problem_view.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <functional>
#include <string>
#include <vector>

namespace pg
{
  struct RunSummary;

  /**
   * The field names of stress output, shared by cells and particles:
   * F_ij (dim x dim), the Cauchy stress components sigma_xx, sigma_yy,
   * sigma_zz, sigma_xy[, sigma_yz, sigma_xz] and von Mises.
   */
  template <int dim>
  std::vector<std::string>
  stress_field_names();

  /**
   * The Cauchy stress of @p material at @p F (3 x 3, plane strain in 2-D),
   * or NaN in every entry where it is undefined (J <= 0: an inverted
   * element, or the correspondence F of a CPD particle, which is only a
   * visual aid): output shows the hole instead of stopping a run whose
   * solution is already computed. With a (committed) material @p state:
   * Material::cauchy_stress_with_state(F, state).
   */
  template <int dim>
  Tensor<2, 3>
  cauchy_stress_or_nan(const Materials::Material<dim> &material,
                       const Tensor<2, dim>           &F,
                       const ArrayView<const double>  &state = {});

  /**
   * The values belonging to stress_field_names() at @p F, with the
   * hydrostatic Cauchy stress @p pressure I added (IUnlP0, whose material is
   * the isochoric part and whose volumetric stress p J F^-T is p I in
   * Cauchy's measure; the von Mises stress does not change), from the
   * material's committed @p state where it has one.
   */
  template <int dim>
  void
  stress_field_values(const Materials::Material<dim> &material,
                      const Tensor<2, dim>           &F,
                      std::vector<double>            &values,
                      const double                    pressure = 0.,
                      const ArrayView<const double>  &state    = {});

  /**
   * DataPostprocessor for the cells: deformation gradient, Cauchy stress
   * and von Mises stress. On finite element cells they come from the Q1
   * displacement gradient. On meshfree cells (if @p particle_F is given)
   * they are the particles' own values, F at the master point of each
   * family, at the cell's vertices, which ParaView interpolates linearly:
   * the PG solution, not the Q1 gradient of the particle displacements
   * (which is not what PG computes and shows a checkerboard).
   */
  template <int dim>
  class StressPostprocessor : public DataPostprocessor<dim>
  {
  public:
    /**
     * @p particle_F(v) is the deformation gradient of the particle at
     * vertex v, or nullptr if vertex v is no particle; cells all of whose
     * vertices are particles and that are flagged in @p meshfree_cell
     * (indexed by active cell index) take those values, and the
     * pressure @p particle_pressure(v) if it is given (IUnlP0).
     */
    StressPostprocessor(
      const Materials::Material<dim>                            &material,
      const std::vector<bool>                                   &meshfree_cell,
      const std::function<const Tensor<2, dim> *(unsigned int)> &particle_F,
      const std::function<double(unsigned int)> &particle_pressure = {});

    /** The Q1 gradient on every cell. */
    explicit StressPostprocessor(const Materials::Material<dim> &material);

    /**
     * A material with history: the stresses from its committed state
     * @p states (kept by the caller): on an FE cell the state of the Gauss
     * point at the corner of the vertex nearest the evaluation point (one
     * point per cell: that one), on a meshfree cell that of the particle
     * at that vertex, whose index is @p particle_at(v) (-1: none).
     */
    void
    set_states(const Postprocess::CommittedStates     *states,
               const std::function<int(unsigned int)> &particle_at);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const Materials::Material<dim>                           &material;
    const std::vector<bool>                                   meshfree_cell;
    const std::function<const Tensor<2, dim> *(unsigned int)> particle_F;
    /**
     * IUnlP0: the pressure of the particle at vertex v, added to its
     * stress (stress_field_values()); empty for the other formulations.
     */
    const std::function<double(unsigned int)> particle_pressure;
    /** The committed states (set_states()), or nullptr. */
    const Postprocess::CommittedStates *states = nullptr;
    std::function<int(unsigned int)>    particle_at;
  };

  /**
   * A point cloud of particle data for ParaView: one VTU point per particle
   * with named scalar fields, vectors grouped by their names.
   */
  template <int dim>
  class ParticleOutput : public DataOutInterface<0, dim>
  {
  public:
    /**
     * @p names: one name per data value; consecutive equal names form a
     * vector field of dim components.
     */
    explicit ParticleOutput(const std::vector<std::string> &names);

    void
    add_particle(const Point<dim> &position, const std::vector<double> &data);

  private:
    const std::vector<DataOutBase::Patch<0, dim>> &
    get_patches() const override;

    std::vector<std::string>
    get_dataset_names() const override;

    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override;

    std::vector<std::string>                names;
    std::vector<DataOutBase::Patch<0, dim>> patches;
  };

  /** Write @p summary as JSON to @p filename. */
  void
  write_summary_json(const RunSummary &summary, const std::string &filename);
} // namespace pg

#endif
