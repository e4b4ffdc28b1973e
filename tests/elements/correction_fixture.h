// Shared by the correction_system tests: one CorrectionSystem::reinit() +
// solve() on a ParticleFixture, with d^k before and after; checks that
// FamilyElements::correct() of the uncorrected tables equals a new build().
#ifndef pg_tests_elements_correction_fixture_h
#define pg_tests_elements_correction_fixture_h

#include <pg/elements/correction_system.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/unit_stress_residual.h>

#include "../particle_fixture.h"

using namespace pg;

/** The factors, d^k and the tables after one reinit() + solve(). */
template <int dim>
struct Corrected
{
  CorrectionFactors<dim>            factors;
  std::vector<QuadratureTable<dim>> tables;
  std::vector<Tensor<1, dim>>       unit_stress;
  std::size_t                       matrix_nonzeros;
};

template <int dim>
inline Corrected<dim>
correct(const ParticleFixture<dim> &fixture,
        const FormulationCode      &code,
        CorrectionSystem<dim>      &system)
{
  const unsigned int        n = fixture.particles.n_particles();
  std::vector<unsigned int> owned_families(n);
  for (unsigned int k = 0; k < n; ++k)
    owned_families[k] = k;
  FamilyElements<dim> elements(fixture.particles,
                               fixture.families,
                               code,
                               ShapeFunctions::Base::mte1,
                               1.);
  elements.initialize();
  Corrected<dim> result;
  result.tables.resize(n);
  for (unsigned int k = 0; k < n; ++k)
    elements.build(k, result.tables[k]);
  const auto d0 = unit_stress_residual(fixture.families,
                                       owned_families,
                                       result.tables,
                                       fixture.particles,
                                       MPI_COMM_WORLD);

  system.reinit(fixture.particles,
                fixture.families,
                elements,
                owned_families,
                complete_index_set(fixture.dof_handler.n_dofs()));
  result.factors         = system.solve(d0);
  result.matrix_nonzeros = code.second_order_consistency ?
                             0 :
                             system.system_matrix().n_nonzero_elements();
  elements.set_correction_factors(result.factors.alpha,
                                  result.factors.second_order_alpha);
  // FamilyElements::correct() of the uncorrected tables must give bitwise
  // the tables that build() gives now
  std::vector<QuadratureTable<dim>> corrected = result.tables;
  elements.correct(owned_families, corrected);
  for (unsigned int k = 0; k < n; ++k)
    elements.build(k, result.tables[k]);
  for (unsigned int k = 0; k < n; ++k)
    AssertThrow(corrected[k].trial == result.tables[k].trial &&
                  corrected[k].test_vectors == result.tables[k].test_vectors &&
                  corrected[k].test_nodes == result.tables[k].test_nodes &&
                  corrected[k].weights == result.tables[k].weights,
                ExcMessage("FamilyElements::correct() differs from build() "
                           "in family " +
                           std::to_string(k)));
  result.unit_stress = unit_stress_residual(fixture.families,
                                            owned_families,
                                            result.tables,
                                            fixture.particles,
                                            MPI_COMM_WORLD);
  return result;
}

#endif
