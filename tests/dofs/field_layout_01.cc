// pg::FieldLayout: a dummy scalar nodal field p on the particles (vertices
// of a meshfree region) beside the displacement u on all vertices, in one hp
// DoFHandler, one sparsity pattern and one linear system:
//   u: linear elasticity on all cells, u = u_exact on the whole boundary;
//   p: screened Poisson on the meshfree cells, coupled to u,
//        int (grad p . grad q + p q + beta div(u) q)
//          = int (p_exact + beta div(u_exact)) q + int_{boundary of the
//            meshfree region} grad(p_exact) . n q,
//      p = p_exact on the bottom face only, so the interface vertices keep
//      free p DoFs.
// Both exact solutions are linear and must be reproduced to round-off. Also:
// the DoF counts, the constraints the layout makes (none on a conforming
// mesh), the numbering with 0 extra fields against a plain DoFHandler, and a
// VTU through DataOut with the values the FE cells show for p.

#include <pg/dofs/field_layout.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include "../tests.h"

#include <fstream>
#include <string>
#include <vector>


namespace
{
  constexpr double lambda = 2.0, mu = 1.0, beta = 1.0;

  /** u_exact = A X + b with a fixed non-symmetric A. */
  template <int dim>
  Tensor<2, dim>
  gradient_u()
  {
    Tensor<2, dim> A;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        A[i][j] = 0.1 * (1 + i) - 0.03 * (j + 1) * (j + 1) + (i == j ? 0.2 : 0);
    return A;
  }



  template <int dim>
  Tensor<1, dim>
  u_exact(const Point<dim> &X)
  {
    Tensor<1, dim> u = gradient_u<dim>() * X;
    for (unsigned int i = 0; i < dim; ++i)
      u[i] += 0.01 * (i + 1);
    return u;
  }



  /** p_exact = 1 + 2 x - 3 y (+ 0.5 z). */
  template <int dim>
  Tensor<1, dim>
  gradient_p()
  {
    Tensor<1, dim> g;
    g[0] = 2;
    g[1] = -3;
    if (dim == 3)
      g[2] = 0.5;
    return g;
  }



  template <int dim>
  double
  p_exact(const Point<dim> &X)
  {
    return 1 + gradient_p<dim>() * X;
  }



  /** (u_exact, p_exact, ...) as a function of all components. */
  template <int dim>
  class ExactSolution : public Function<dim>
  {
  public:
    explicit ExactSolution(const unsigned int n_components)
      : Function<dim>(n_components)
    {}

    double
    value(const Point<dim> &X, const unsigned int c) const override
    {
      return c < dim ? u_exact(X)[c] : p_exact(X);
    }
  };



  /** The meshfree region: cells with centre x in (0.25, 0.75), y < 0.75. */
  template <int dim>
  std::vector<bool>
  meshfree_cells(const Triangulation<dim> &tria)
  {
    std::vector<bool> meshfree(tria.n_active_cells(), false);
    for (const auto &cell : tria.active_cell_iterators())
      {
        const Point<dim> c = cell->center();
        meshfree[cell->active_cell_index()] =
          (c[0] > 0.25 && c[0] < 0.75 && c[1] < 0.75);
      }
    return meshfree;
  }



  /** 0 extra fields: the numbering of a plain FESystem(FE_Q(1), dim). */
  template <int dim>
  void
  check_numbering_without_extra_fields(const Triangulation<dim> &tria,
                                       const std::vector<bool>  &meshfree)
  {
    pg::FieldLayout<dim> layout(0);
    DoFHandler<dim>      dof_handler(tria);
    layout.distribute_dofs(dof_handler, meshfree);

    const FESystem<dim> fe(FE_Q<dim>(1), dim);
    DoFHandler<dim>     plain(tria);
    plain.distribute_dofs(fe);

    AssertThrow(dof_handler.n_dofs() == plain.n_dofs(), ExcInternalError());
    AssertThrow(layout.fe_collection().size() == 1 &&
                  layout.fe_collection()[0] == fe,
                ExcInternalError());
    std::vector<types::global_dof_index> a(fe.n_dofs_per_cell()),
      b(fe.n_dofs_per_cell());
    unsigned int n_compared = 0;
    auto         cell       = dof_handler.begin_active();
    for (const auto &plain_cell : plain.active_cell_iterators())
      {
        cell->get_dof_indices(a);
        plain_cell->get_dof_indices(b);
        AssertThrow(a == b, ExcInternalError());
        for (const unsigned int v : plain_cell->vertex_indices())
          for (unsigned int c = 0; c < dim; ++c)
            {
              AssertThrow(layout.displacement_dof(plain_cell->vertex_index(v),
                                                  c) ==
                            plain_cell->vertex_dof_index(v, c),
                          ExcInternalError());
              ++n_compared;
            }
        ++cell;
      }
    AssertThrow(layout.n_extra_field_dofs() == 0 &&
                  layout.n_displacement_dofs() == plain.n_dofs(),
                ExcInternalError());
    deallog << "0 extra fields: " << dof_handler.n_dofs()
            << " DoFs, cell and vertex DoF indices equal to the plain "
               "DoFHandler's ("
            << n_compared << " vertex DoFs compared): yes" << std::endl;
  }



  template <int dim>
  void
  test(const unsigned int refinements)
  {
    deallog << "--- " << dim << "-D, unit cube refined " << refinements
            << " times" << std::endl;
    Triangulation<dim> tria;
    GridGenerator::hyper_cube(tria, 0, 1, true);
    tria.refine_global(refinements);
    const std::vector<bool> meshfree = meshfree_cells(tria);

    check_numbering_without_extra_fields(tria, meshfree);

    // Two extra fields: only the counts.
    {
      pg::FieldLayout<dim> layout(2);
      DoFHandler<dim>      dof_handler(tria);
      layout.distribute_dofs(dof_handler, meshfree);
      AssertThrow(dof_handler.n_dofs() == dim * tria.n_vertices() +
                                            2 * layout.field_vertices().size(),
                  ExcInternalError());
      deallog << "2 extra fields: " << dof_handler.n_dofs() << " DoFs"
              << std::endl;
    }

    // One extra field p.
    pg::FieldLayout<dim> layout(1);
    DoFHandler<dim>      dof_handler(tria);
    layout.distribute_dofs(dof_handler, meshfree);
    const unsigned int n_components = layout.n_components();

    // Expected counts: n_u = dim * n_vertices, n_p = vertices of meshfree
    // cells; interface vertices = those also on a finite element cell.
    std::vector<bool> on_meshfree(tria.n_vertices(), false),
      on_fe(tria.n_vertices(), false);
    unsigned int n_meshfree_cells = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        const bool m = meshfree[cell->active_cell_index()];
        n_meshfree_cells += m;
        for (const unsigned int v : cell->vertex_indices())
          (m ? on_meshfree : on_fe)[cell->vertex_index(v)] = true;
      }
    unsigned int n_particles = 0, n_interface = 0;
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      {
        n_particles += on_meshfree[v];
        n_interface += (on_meshfree[v] && on_fe[v]);
        AssertThrow(layout.carries_extra_fields(v) == on_meshfree[v] &&
                      (layout.extra_field_dof(v, 0) !=
                       numbers::invalid_dof_index) == on_meshfree[v],
                    ExcInternalError());
      }
    const std::vector<types::global_dof_index> per_component =
      DoFTools::count_dofs_per_fe_component(dof_handler);
    types::global_dof_index n_u = 0;
    for (unsigned int c = 0; c < dim; ++c)
      n_u += per_component[c];
    AssertThrow(n_u == dim * tria.n_vertices() &&
                  n_u == layout.n_displacement_dofs() &&
                  per_component[dim] == n_particles &&
                  layout.n_extra_field_dofs() == n_particles &&
                  layout.field_vertices().size() == n_particles &&
                  dof_handler.n_dofs() == n_u + n_particles,
                ExcInternalError());
    deallog << "cells: " << tria.n_active_cells() << " (" << n_meshfree_cells
            << " meshfree), vertices: " << tria.n_vertices()
            << ", particles: " << n_particles << " (" << n_interface
            << " on the interface)" << std::endl;
    deallog << "DoFs: " << dof_handler.n_dofs() << " = n_u " << n_u << " + n_p "
            << per_component[dim] << std::endl;

    // Constraints: the layout's own, then Dirichlet u on the whole boundary
    // and p on the bottom face (boundary id 2) of the meshfree region.
    AffineConstraints<double> constraints;
    layout.make_constraints(dof_handler, constraints);
    const unsigned int n_layout_constraints = constraints.n_constraints();
    AssertThrow(n_layout_constraints == 0, ExcInternalError());
    deallog << "constraints made by the layout: " << n_layout_constraints
            << std::endl;
    const ExactSolution<dim> exact(n_components);
    for (unsigned int id = 0; id < 2 * dim; ++id)
      VectorTools::interpolate_boundary_values(dof_handler,
                                               id,
                                               exact,
                                               constraints,
                                               layout.displacement_mask());
    VectorTools::interpolate_boundary_values(dof_handler,
                                             2,
                                             exact,
                                             constraints,
                                             layout.extra_field_mask(0));
    constraints.close();

    unsigned int n_p_constrained = 0, n_free_interface = 0;
    for (const unsigned int v : layout.field_vertices())
      {
        const bool constrained =
          constraints.is_constrained(layout.extra_field_dof(v, 0));
        const bool bottom = std::abs(tria.get_vertices()[v][1]) < 1e-12;
        AssertThrow(constrained == bottom, ExcInternalError());
        n_p_constrained += constrained;
        n_free_interface += (on_fe[v] && !constrained);
      }
    AssertThrow(n_free_interface > 0, ExcInternalError());
    deallog << "p constrained at " << n_p_constrained
            << " bottom particles; interface particles with a free p: "
            << n_free_interface << std::endl;

    // One sparsity pattern and one matrix for u and p.
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    SparseMatrix<double> matrix(sparsity);
    Vector<double>       rhs(dof_handler.n_dofs());

    const hp::QCollection<dim>     q(QGauss<dim>(2), QGauss<dim>(2));
    const hp::QCollection<dim - 1> q_face(QGauss<dim - 1>(2),
                                          QGauss<dim - 1>(2));
    hp::FEValues<dim>              hp_fe_values(layout.fe_collection(),
                                   q,
                                   update_values | update_gradients |
                                     update_quadrature_points |
                                     update_JxW_values);
    hp::FEFaceValues<dim>          hp_face_values(layout.fe_collection(),
                                         q_face,
                                         update_values |
                                           update_quadrature_points |
                                           update_normal_vectors |
                                           update_JxW_values);
    const auto                     u      = layout.displacement();
    const auto                     p      = layout.extra_field(0);
    const Tensor<2, dim>           grad_u = gradient_u<dim>();
    const double                   div_u  = trace(grad_u);
    const Tensor<1, dim>           grad_p = gradient_p<dim>();

    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        hp_fe_values.reinit(cell);
        const FEValues<dim> &fv = hp_fe_values.get_present_fe_values();
        const unsigned int   n  = cell->get_fe().n_dofs_per_cell();
        const bool           m  = meshfree[cell->active_cell_index()];
        FullMatrix<double>   local(n, n);
        Vector<double>       local_rhs(n);
        for (unsigned int qp = 0; qp < fv.n_quadrature_points; ++qp)
          {
            const double JxW = fv.JxW(qp);
            for (unsigned int i = 0; i < n; ++i)
              {
                const auto eps_i = fv[u].symmetric_gradient(i, qp);
                const auto div_i = fv[u].divergence(i, qp);
                for (unsigned int j = 0; j < n; ++j)
                  local(i, j) +=
                    (lambda * div_i * fv[u].divergence(j, qp) +
                     2 * mu *
                       scalar_product(eps_i, fv[u].symmetric_gradient(j, qp))) *
                    JxW;
                if (!m)
                  continue;
                const double         q_i      = fv[p].value(i, qp);
                const Tensor<1, dim> grad_q_i = fv[p].gradient(i, qp);
                for (unsigned int j = 0; j < n; ++j)
                  local(i, j) += (grad_q_i * fv[p].gradient(j, qp) +
                                  q_i * fv[p].value(j, qp) +
                                  beta * fv[u].divergence(j, qp) * q_i) *
                                 JxW;
                local_rhs(i) +=
                  (p_exact(fv.quadrature_point(qp)) + beta * div_u) * q_i * JxW;
              }
          }
        // Neumann data on the boundary of the meshfree region: domain
        // boundary faces and faces to finite element cells.
        if (m)
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f) ||
                !meshfree[cell->neighbor(f)->active_cell_index()])
              {
                hp_face_values.reinit(cell, f);
                const FEFaceValues<dim> &fv_face =
                  hp_face_values.get_present_fe_values();
                for (unsigned int qp = 0; qp < fv_face.n_quadrature_points;
                     ++qp)
                  for (unsigned int i = 0; i < n; ++i)
                    local_rhs(i) += grad_p * fv_face.normal_vector(qp) *
                                    fv_face[p].value(i, qp) * fv_face.JxW(qp);
              }
        dofs.resize(n);
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(local,
                                               local_rhs,
                                               dofs,
                                               matrix,
                                               rhs);
      }

    Vector<double>      solution(dof_handler.n_dofs());
    SparseDirectUMFPACK direct;
    direct.initialize(matrix);
    direct.vmult(solution, rhs);
    constraints.distribute(solution);

    double error_u = 0, error_p = 0;
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      {
        const Point<dim> &X = tria.get_vertices()[v];
        for (unsigned int c = 0; c < dim; ++c)
          error_u = std::max(error_u,
                             std::abs(solution(layout.displacement_dof(v, c)) -
                                      u_exact(X)[c]));
        if (layout.carries_extra_fields(v))
          error_p = std::max(error_p,
                             std::abs(solution(layout.extra_field_dof(v, 0)) -
                                      p_exact(X)));
      }
    AssertThrow(error_u < 1e-10 && error_p < 1e-10,
                ExcMessage("errors " + std::to_string(error_u) + ", " +
                           std::to_string(error_p)));
    print_bound("max nodal error of u", error_u, 1e-10);
    print_bound("max nodal error of p", error_p, 1e-10);

    // DataOut on the hp DoFHandler: FE cells show p = 0 (FE_Nothing).
    std::vector<std::string> names(dim, "displacement");
    names.emplace_back("p");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution,
                             names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.build_patches();
    double       max_p_on_fe = 0, error_p_on_meshfree = 0;
    unsigned int patch_index = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        const auto &patch = data_out.get_patches()[patch_index++];
        for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
          {
            const double value = patch.data(dim, v);
            if (meshfree[cell->active_cell_index()])
              error_p_on_meshfree =
                std::max(error_p_on_meshfree,
                         std::abs(value - p_exact(patch.vertices[v])));
            else
              max_p_on_fe = std::max(max_p_on_fe, std::abs(value));
          }
      }
    AssertThrow(patch_index == data_out.get_patches().size() &&
                  max_p_on_fe == 0 && error_p_on_meshfree < 1e-10,
                ExcInternalError());
    deallog << "DataOut: p on finite element cells = 0 exactly: yes"
            << std::endl;
    print_bound("DataOut: max error of p on meshfree cells",
                error_p_on_meshfree,
                1e-10);

    const std::string file_name =
      "field_layout_01_" + std::to_string(dim) + "d.vtu";
    {
      std::ofstream out(file_name);
      data_out.write_vtu(out);
    }
    std::ifstream written(file_name, std::ios::binary | std::ios::ate);
    AssertThrow(written && written.tellg() > 0, ExcInternalError());
    deallog << "wrote " << file_name << ": non-empty" << std::endl;
  }
} // namespace



int
main()
{
  initlog();
  test<2>(3);
  test<3>(2);
}
