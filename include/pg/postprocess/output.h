#ifndef pg_postprocess_output_h
#define pg_postprocess_output_h

#include <pg/base/global.h>
#include <pg/materials/material.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_postprocessor.h>

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

  /** The values belonging to stress_field_names() at @p F. */
  template <int dim>
  void
  stress_field_values(const Materials::Material<dim> &material,
                      const Tensor<2, dim>           &F,
                      std::vector<double>            &values);

  /**
   * DataPostprocessor for Q1 cells: deformation gradient, Cauchy stress
   * and von Mises stress from the displacement gradient.
   */
  template <int dim>
  class StressPostprocessor : public DataPostprocessor<dim>
  {
  public:
    explicit StressPostprocessor(const Materials::Material<dim> &material);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const Materials::Material<dim> &material;
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
