// 'Linear solver/AMG operator': solve_linear_system() builds ML's hierarchy
// from the matrix that its amg_operator returns, and still solves with the
// given matrix. On a scalar Laplace-plus-mass matrix A (Q1, 48 x 48 cells,
// 2,401 DoFs), against the plain solve (0):
//  1. operator = A itself: the iterations of the plain solve, one call;
//  2. a second solve with the cache: the hierarchy is reused, no call;
//  3. operator = the Laplacian L alone (close to A in energy, like a Q1
//     tangent to a PG tangent): CG on A converges, in at most twice the
//     iterations of A's own hierarchy;
//  4. operator returns nullptr (pg: a Q1 cell failed): built from A;
//  5. operator = D A D with D_ii = 10^(4 frac(0.618 i)) (scattered over
//     four decades, far from A in energy): CG on A does not reach the
//     tolerance within 1000 iterations, so the hierarchy is rebuilt from A
//     and the solve repeated (its count is the 1000 failed iterations plus
//     those of case 1; 2 hierarchies).
//  6. operator = D A D over 0.6 decades with 'Q1 cells': CG converges in
//     more than operator_trial_iterations (250) iterations; kept.
//  7. the same with 'automatic': the solve is repeated with A's hierarchy
//     (a trial), which is faster and kept; the count is case 6's plus
//     case 0's; later solves and new hierarchies use A without calling the
//     operator.
// Every solution is checked against its residual |b - M x| <= 1e-10 |b|.

#include "../tests.h"
#include "laplace_fixture.h"


using namespace pg;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  LaplaceFixture problem;
  const auto    &A = problem.matrix;
  const auto    &L = problem.laplace;
  // D A D with D_ii = 10^(4 frac(0.618 i))
  pg::LinearAlgebra::SparseMatrix scaled;
  scaled.copy_from(A);
  const auto d = [](const types::global_dof_index i, const double decades) {
    const double x = 0.618034 * i;
    return std::pow(10., decades * (x - std::floor(x)));
  };
  for (auto entry = scaled.begin(); entry != scaled.end(); ++entry)
    entry->value() *= d(entry->row(), 4.) * d(entry->column(), 4.);
  // the same over 0.6 decades: CG on A converges, slowly
  pg::LinearAlgebra::SparseMatrix mildly_scaled;
  mildly_scaled.copy_from(A);
  for (auto entry = mildly_scaled.begin(); entry != mildly_scaled.end();
       ++entry)
    entry->value() *= d(entry->row(), 0.6) * d(entry->column(), 0.6);

  const auto               &rhs        = problem.rhs;
  const auto               &parameters = problem.parameters;
  pg::LinearAlgebra::Vector x(rhs);

  unsigned int calls = 0;
  const auto   solve = [&](const pg::LinearAlgebra::SparseMatrix &M,
                         AMGCache                              &cache,
                         const pg::LinearAlgebra::SparseMatrix *hierarchy,
                         const bool                             with_operator,
                         const Parameters::LinearSolver *other = nullptr) {
    x = 0;
    std::function<const pg::LinearAlgebra::SparseMatrix *()> amg_operator;
    if (with_operator)
      amg_operator = [&calls, hierarchy]() {
        ++calls;
        return hierarchy;
      };
    const unsigned int its = solve_linear_system(other ? *other : parameters,
                                                 problem.dof_handler,
                                                 M,
                                                 x,
                                                 rhs,
                                                 &cache,
                                                 amg_operator);
    print_bound("  |b - M x| / |b|", problem.relative_residual(M, x), 1e-10);
    return its;
  };

  deallog << "0. A without an operator" << std::endl;
  AMGCache           plain_cache;
  const unsigned int plain = solve(A, plain_cache, nullptr, false);

  deallog << "1. A with operator A" << std::endl;
  AMGCache           cache;
  const unsigned int first = solve(A, cache, &A, true);
  deallog << "  iterations as without the operator: "
          << (first == plain ? "yes" : "NO") << ", operator calls " << calls
          << ", hierarchies " << cache.n_builds << std::endl;

  deallog << "2. again, reusing the hierarchy" << std::endl;
  const unsigned int second = solve(A, cache, &A, true);
  deallog << "  iterations as solve 1: " << (second == first ? "yes" : "NO")
          << ", operator calls " << calls << ", hierarchies " << cache.n_builds
          << std::endl;

  deallog << "3. A with operator L (the Laplacian alone)" << std::endl;
  AMGCache           laplace_cache;
  const unsigned int third = solve(A, laplace_cache, &L, true);
  deallog << "  at most twice the iterations of A's hierarchy: "
          << (third <= 2 * plain ? "yes" : "NO") << ", operator calls " << calls
          << ", hierarchies " << laplace_cache.n_builds << std::endl;

  deallog << "4. A with an operator that returns nullptr" << std::endl;
  AMGCache           null_cache;
  const unsigned int fourth = solve(A, null_cache, nullptr, true);
  deallog << "  iterations as without the operator: "
          << (fourth == plain ? "yes" : "NO") << ", operator calls " << calls
          << ", hierarchies " << null_cache.n_builds << std::endl;

  deallog << "5. A with operator D A D" << std::endl;
  AMGCache           fallback_cache;
  const unsigned int fifth = solve(A, fallback_cache, &scaled, true);
  deallog << "  iterations = 1000 failed + those of A's hierarchy: "
          << (fifth == 1000 + plain ? "yes" : "NO") << ", operator calls "
          << calls << ", hierarchies " << fallback_cache.n_builds << std::endl;

  deallog << "6. 'Q1 cells' with operator D A D over 0.6 decades" << std::endl;
  Parameters::LinearSolver q1_cells = parameters;
  q1_cells.amg_operator             = "Q1 cells";
  AMGCache           slow_cache;
  const unsigned int slow =
    solve(A, slow_cache, &mildly_scaled, true, &q1_cells);
  deallog << "  more than 250 iterations, kept: "
          << (slow > operator_trial_iterations &&
                  !slow_cache.operator_rejected ?
                "yes" :
                "NO")
          << ", hierarchies " << slow_cache.n_builds << std::endl;

  deallog << "7. 'automatic' with the same operator" << std::endl;
  Parameters::LinearSolver automatic = parameters;
  automatic.amg_operator             = "automatic";
  AMGCache           trial_cache;
  const unsigned int seventh =
    solve(A, trial_cache, &mildly_scaled, true, &automatic);
  deallog << "  repeated with A's hierarchy, which is kept: iterations = "
             "those of case 6 + those of A's hierarchy: "
          << (seventh == slow + plain && trial_cache.operator_rejected ? "yes" :
                                                                         "NO")
          << ", hierarchies " << trial_cache.n_builds << std::endl;
  const unsigned int calls_before = calls;
  const unsigned int eighth =
    solve(A, trial_cache, &mildly_scaled, true, &automatic);
  trial_cache.clear();
  const unsigned int ninth =
    solve(A, trial_cache, &mildly_scaled, true, &automatic);
  deallog << "  the next solves (reused, then a new hierarchy) use A's "
             "without calling the operator: "
          << (eighth == plain && ninth == plain && calls == calls_before ?
                "yes" :
                "NO")
          << ", hierarchies " << trial_cache.n_builds << std::endl;
}
