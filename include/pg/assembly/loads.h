#ifndef pg_assembly_loads_h
#define pg_assembly_loads_h

#include <pg/base/global.h>
#include <pg/base/parameters.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace pg
{
  /**
   * The dead loads of subsection 'Boundary conditions' and the body force,
   * as seen by the finite element cells: which boundary ids are loaded, the
   * traction at a boundary point, and their FE-consistent contributions to
   * an element residual (node-major, f_int - f_ext: loads are subtracted).
   * The functions' time is the load factor (set by the problem).
   */
  template <int dim>
  class Loads
  {
  public:
    explicit Loads(const Parameters::AllParameters<dim> &parameters);

    /**
     * Does any load act: a body force other than the literal 0, or a
     * boundary in 'Neumann' or 'Neumann stress'? Without one the loads
     * need not be assembled.
     */
    bool
    any() const;

    /** Is @p id in 'Neumann' or in 'Neumann stress'? */
    bool
    is_neumann(const types::boundary_id id) const;

    /** The ids of 'Neumann' and 'Neumann stress', ascending, each once. */
    std::vector<types::boundary_id>
    neumann_ids() const;

    /**
     * The load factor t of the traction functions (their time, set by
     * AllParameters::set_load_factor()).
     */
    double
    load_factor() const;

    /**
     * The prescribed traction (force per reference area) on boundary @p id
     * at @p point with the outward unit normal @p normal: the 'Traction'
     * function, or sigma . n from 'Boundary stress' for 'Neumann stress'.
     */
    Tensor<1, dim>
    prescribed_traction(const types::boundary_id id,
                        const Point<dim>        &point,
                        const Tensor<1, dim>    &normal) const;

    bool
    has_neumann_face(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /**
     * Subtract the FE-consistent traction load of the Neumann faces of
     * @p cell from @p residual.
     */
    void
    add_face_tractions(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      FEFaceValues<dim>                                    &fe_face_values,
      Vector<double>                                       &residual) const;

    /**
     * Subtract the body force rho_0 b integrated against the shape
     * functions of @p fe_values (reinit'ed on the cell) from @p residual.
     */
    void
    add_body_force(const FEValues<dim> &fe_values,
                   Vector<double>      &residual) const;

    /** The body force b(@p point), dim components. */
    void
    body_force(const Point<dim> &point, Vector<double> &values) const;

  private:
    const Parameters::AllParameters<dim> &parameters;
  };
} // namespace pg

#endif
