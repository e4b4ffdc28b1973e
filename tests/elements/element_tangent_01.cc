// The consistent tangent of every element agrees with central finite
// differences of its residual, and rigid motions give zero residual:
// for PBG, PPG1 and PPG2 with Unl (with and without the bond correction)
// and PBG U1, for each base (MTE1, MLS1, WLS1, WTE1), PBG and PPG2 with
// U2 (WTE2), each material
// (linear elastic, Saint Venant-Kirchhoff, neo-Hooke), on an interior and a
// corner family of a distorted particle set, in 2-D and 3-D; and for the
// Q1 cell. Rigid rotations (0.7 rad) are checked for the finite-strain
// materials only (linear elasticity is not rotation invariant).

#include <pg/base/formulation_code.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/q1_cell.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include "../particle_fixture.h"
#include "../tests.h"

using namespace pg;

/**
 * Checks one element table at the relative nodal positions @p X (node 0
 * at the origin); returns {tangent error, translation residual, rotation
 * residual}, all relative.
 */
template <int dim>
std::array<double, 3>
check_table(const QuadratureTable<dim>        &table,
            const std::vector<Tensor<1, dim>> &X,
            const Materials::Material<dim>    &material,
            const double                       h,
            std::mt19937                      &rng)
{
  std::uniform_real_distribution<double> random(-1., 1.);
  const unsigned int                     n = X.size();
  std::vector<Tensor<1, dim>>            y(X);
  for (auto &v : y)
    for (unsigned int c = 0; c < dim; ++c)
      v[c] += 0.05 * h * random(rng);

  Vector<double>     r, rp, rm;
  FullMatrix<double> K;
  assemble_element(table, y, material, r, &K);

  double       error = 0, scale = 0;
  const double eps = 1e-6 * h;
  for (unsigned int b = 0; b < n; ++b)
    for (unsigned int c = 0; c < dim; ++c)
      {
        y[b][c] += eps;
        assemble_element(table, y, material, rp, nullptr);
        y[b][c] -= 2 * eps;
        assemble_element(table, y, material, rm, nullptr);
        y[b][c] += eps;
        for (unsigned int i = 0; i < n * dim; ++i)
          {
            const double fd = (rp[i] - rm[i]) / (2 * eps);
            error           = std::max(error, std::abs(fd - K(i, b * dim + c)));
            scale           = std::max(scale, std::abs(K(i, b * dim + c)));
          }
      }

  // rigid translation and rotation
  const double                force_scale = 100. * std::pow(h, dim - 1);
  std::vector<Tensor<1, dim>> rigid(n);
  Tensor<1, dim>              shift;
  for (unsigned int c = 0; c < dim; ++c)
    shift[c] = 0.3 * (c + 1) * h;
  for (unsigned int b = 0; b < n; ++b)
    rigid[b] = X[b] + shift;
  assemble_element(table, rigid, material, r, nullptr);
  const double         translation = r.linfty_norm() / force_scale;
  const Tensor<2, dim> R           = rotation<dim>(0.7);
  for (unsigned int b = 0; b < n; ++b)
    rigid[b] = R * X[b] + shift;
  assemble_element(table, rigid, material, r, nullptr);
  const double rotated = r.linfty_norm() / force_scale;
  return {{error / scale, translation, rotated}};
}



template <int dim>
void
test()
{
  const ParticleFixture<dim> fixture(dim == 2 ? 6 : 4,
                                     0.25,
                                     dim == 2 ? 2.51 : 2.01);
  const double                   h = 1. / (dim == 2 ? 6 : 4);
  std::mt19937                   rng(42);
  const std::vector<std::string> models = {"linear elastic",
                                           "saint venant kirchhoff",
                                           "neo-Hooke"};
  std::vector<std::unique_ptr<Materials::Material<dim>>> materials;
  for (const auto &m : models)
    materials.push_back(make_material<dim>(m));
  const std::vector<unsigned int> masters = fixture.interior_and_corner();

  const auto report = [&](const std::string           &name,
                          const std::array<double, 3> &worst) {
    deallog << dim << "d " << name
            << ": tangent = FD: " << verdict(worst[0], 1e-6)
            << ", translation: " << verdict(worst[1], 1e-12)
            << ", rotation: " << verdict(worst[2], 1e-12) << std::endl;
  };

  for (const std::string code : {"PBG Unl noBC",
                                 "BCPBG Unl",
                                 "PPG Unl noBC",
                                 "BCPPG Unl",
                                 "PPG2 Unl noBC",
                                 "BCPPG2 Unl",
                                 "PBG U1",
                                 "PBG U2",
                                 "PPG2 U2"})
    for (const std::string base :
         (code.find("U2") != std::string::npos ?
            std::vector<std::string>{"WTE1"} :
            std::vector<std::string>{"MTE1", "MLS1", "WLS1", "WTE1"}))
      {
        FamilyElements<dim> elements(fixture.particles,
                                     fixture.families,
                                     parse_formulation_code(code),
                                     ShapeFunctions::parse_base(base),
                                     1.);
        elements.initialize();
        std::array<double, 3> worst{{0, 0, 0}};
        for (const unsigned int k : masters)
          {
            QuadratureTable<dim> table;
            elements.build(k, table);
            const auto geometry = elements.geometry(k);
            for (unsigned int m = 0; m < materials.size(); ++m)
              {
                const auto e =
                  check_table(table, geometry.bonds, *materials[m], h, rng);
                worst[0] = std::max(worst[0], e[0]);
                worst[1] = std::max(worst[1], e[1]);
                if (m > 0)
                  worst[2] = std::max(worst[2], e[2]);
              }
          }
        // U2 uses WTE2 whatever the base
        report(code + " " +
                 (code.find("U2") != std::string::npos ? "WTE2" : base),
               worst);
      }

  // The Q1 cell: the same kernel with Gauss points.
  {
    const FE_Q<dim>       fe(1);
    FEValues<dim>         fe_values(fe,
                            QGauss<dim>(2),
                            update_gradients | update_JxW_values);
    std::array<double, 3> worst{{0, 0, 0}};
    for (const auto &cell : fixture.tria.active_cell_iterators())
      if (cell->active_cell_index() % 7 == 0)
        {
          fe_values.reinit(cell);
          QuadratureTable<dim> table;
          fill_q1_table(fe_values, table);
          std::vector<Tensor<1, dim>> X(cell->n_vertices());
          for (const unsigned int v : cell->vertex_indices())
            X[v] = cell->vertex(v) - cell->vertex(0);
          for (unsigned int m = 0; m < materials.size(); ++m)
            {
              const auto e = check_table(table, X, *materials[m], h, rng);
              worst[0]     = std::max(worst[0], e[0]);
              worst[1]     = std::max(worst[1], e[1]);
              if (m > 0)
                worst[2] = std::max(worst[2], e[2]);
            }
        }
    report("Q1 cell", worst);
  }
}



int
main()
{
  initlog();
  test<2>();
  test<3>();
}
