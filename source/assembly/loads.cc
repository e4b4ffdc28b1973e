#include <pg/assembly/loads.h>

#include <algorithm>

namespace pg
{
  template <int dim>
  Loads<dim>::Loads(const Parameters::AllParameters<dim> &parameters)
    : parameters(parameters)
  {}



  template <int dim>
  bool
  Loads<dim>::any() const
  {
    const auto &bc = parameters.boundary_conditions;
    return !parameters.zero_body_force || !bc.neumann.empty() ||
           !bc.neumann_stress.empty();
  }



  template <int dim>
  bool
  Loads<dim>::is_neumann(const types::boundary_id id) const
  {
    const auto &bc = parameters.boundary_conditions;
    return std::find(bc.neumann.begin(), bc.neumann.end(), id) !=
             bc.neumann.end() ||
           std::find(bc.neumann_stress.begin(), bc.neumann_stress.end(), id) !=
             bc.neumann_stress.end();
  }



  template <int dim>
  std::vector<types::boundary_id>
  Loads<dim>::neumann_ids() const
  {
    const auto                     &bc = parameters.boundary_conditions;
    std::vector<types::boundary_id> ids(bc.neumann.begin(), bc.neumann.end());
    ids.insert(ids.end(), bc.neumann_stress.begin(), bc.neumann_stress.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
  }



  template <int dim>
  double
  Loads<dim>::load_factor() const
  {
    return parameters.traction.get_time();
  }



  template <int dim>
  Tensor<1, dim>
  Loads<dim>::prescribed_traction(const types::boundary_id id,
                                  const Point<dim>        &point,
                                  const Tensor<1, dim>    &normal) const
  {
    const auto    &stress_ids = parameters.boundary_conditions.neumann_stress;
    Tensor<1, dim> t;
    if (std::find(stress_ids.begin(), stress_ids.end(), id) == stress_ids.end())
      {
        for (unsigned int c = 0; c < dim; ++c)
          t[c] = parameters.traction.value(point, c);
        return t;
      }
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        t[i] +=
          parameters.boundary_stress.value(point, i * dim + j) * normal[j];
    return t;
  }



  template <int dim>
  bool
  Loads<dim>::has_neumann_face(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() &&
          is_neumann(cell->face(f)->boundary_id()))
        return true;
    return false;
  }



  template <int dim>
  void
  Loads<dim>::add_face_tractions(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEFaceValues<dim>                                    &fe_face_values,
    Vector<double>                                       &residual) const
  {
    for (const unsigned int face : cell->face_indices())
      if (cell->face(face)->at_boundary() &&
          is_neumann(cell->face(face)->boundary_id()))
        {
          fe_face_values.reinit(
            typename Triangulation<dim>::active_cell_iterator(cell),
            face);
          for (const unsigned int q : fe_face_values.quadrature_point_indices())
            {
              const Tensor<1, dim> f =
                prescribed_traction(cell->face(face)->boundary_id(),
                                    fe_face_values.quadrature_point(q),
                                    fe_face_values.normal_vector(q));
              for (unsigned int b = 0; b < cell->n_vertices(); ++b)
                for (unsigned int c = 0; c < dim; ++c)
                  residual(b * dim + c) -= f[c] *
                                           fe_face_values.shape_value(b, q) *
                                           fe_face_values.JxW(q);
            }
        }
  }



  template <int dim>
  void
  Loads<dim>::add_body_force(const FEValues<dim> &fe_values,
                             Vector<double>      &residual) const
  {
    if (parameters.zero_body_force)
      return;
    Vector<double>     f(dim);
    const unsigned int n = fe_values.get_fe().n_dofs_per_cell();
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        parameters.body_force.vector_value(fe_values.quadrature_point(q), f);
        for (unsigned int b = 0; b < n; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            residual(b * dim + c) -=
              f(c) * fe_values.shape_value(b, q) * fe_values.JxW(q);
      }
  }



  template <int dim>
  void
  Loads<dim>::body_force(const Point<dim> &point, Vector<double> &values) const
  {
    parameters.body_force.vector_value(point, values);
  }



  template class Loads<2>;
  template class Loads<3>;
} // namespace pg
