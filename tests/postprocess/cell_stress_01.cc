// The cell output of solution.pvd (issue 11, item 5): on a finite element
// cell F is the Q1 gradient of the displacement; on a meshfree cell it is
// the particles' own F at the cell's vertices, not the Q1 gradient of the
// particle displacements. Two cells [0,1] x [0,1] and [1,2] x [0,1], the
// right one meshfree, a displacement u = (0.1 x^2, 0) (Q1 gradient on the
// left cell: F_xx = 1 + 0.1 (x0 + x1) = 1.1 at every point), and particle
// values F_xx = 1 + 0.01 v at vertex v.

#include <pg/materials/linear_elastic.h>
#include <pg/postprocess/output.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include "../tests.h"

using namespace pg;

int
main()
{
  initlog();
  constexpr int      dim = 2;
  Triangulation<dim> triangulation;
  GridGenerator::subdivided_hyper_rectangle(triangulation,
                                            {2, 1},
                                            Point<dim>(0, 0),
                                            Point<dim>(2, 1));
  FESystem<dim>   fe(FE_Q<dim>(1), dim);
  DoFHandler<dim> dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  Vector<double>      u(dof_handler.n_dofs());
  FunctionParser<dim> displacement(dim);
  displacement.initialize("x,y", "0.1*x^2; 0", {});
  VectorTools::interpolate(dof_handler, displacement, u);

  Parameters::Material parameters;
  parameters.model          = "linear elastic";
  parameters.youngs_modulus = 100;
  parameters.poissons_ratio = 0.25;
  parameters.density        = 1;
  parameters.plane          = "strain";
  const Materials::LinearElastic<dim> material(parameters);

  std::vector<bool>           meshfree(triangulation.n_active_cells(), false);
  std::vector<Tensor<2, dim>> F(triangulation.n_vertices());
  std::vector<bool>           is_particle(triangulation.n_vertices(), false);
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->center()[0] > 1)
      {
        meshfree[cell->active_cell_index()] = true;
        for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int i = cell->vertex_index(v);
            is_particle[i]       = true;
            F[i]                 = unit_symmetric_tensor<dim>();
            F[i][0][0] += 0.01 * i;
          }
      }
  const StressPostprocessor<dim> stress(
    material,
    meshfree,
    [&](const unsigned int v) -> const Tensor<2, dim> * {
      return is_particle[v] ? &F[v] : nullptr;
    });

  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler);
  data_out.add_data_vector(u, stress);
  data_out.build_patches();
  // F_xx is the first field of the postprocessor, after no other data
  for (const auto &patch : data_out.get_patches())
    {
      const bool right = patch.vertices[0][0] + patch.vertices[1][0] > 2;
      bool       ok    = true;
      for (unsigned int p = 0; p < patch.data.n_cols(); ++p)
        {
          // the vertex of the mesh at point p of the patch
          const Point<dim> &x      = patch.vertices[p];
          unsigned int      vertex = 0;
          for (unsigned int i = 0; i < triangulation.n_vertices(); ++i)
            if (triangulation.get_vertices()[i].distance(x) <
                triangulation.get_vertices()[vertex].distance(x))
              vertex = i;
          const double expected = right ? F[vertex][0][0] : 1.1;
          // patch data are floats
          ok = ok && std::abs(patch.data(0, p) - expected) < 1e-6;
        }
      deallog << (right ? "meshfree cell: F_xx = the particles' F: " :
                          "Q1 cell: F_xx = the Q1 gradient: ")
              << (ok ? "yes" : "NO") << std::endl;
    }
}
