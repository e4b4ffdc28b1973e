#include <pg/elements/kernel_cost.h>

namespace pg
{
  template <int dim>
  double
  tangent_entries(const QuadratureTable<dim> &table)
  {
    const double n_dofs = double(table.n_nodes) * dim;
    return n_dofs * n_dofs;
  }



  template <int dim>
  double
  tangent_flops(const QuadratureTable<dim> &table)
  {
    constexpr double d2 = dim * dim, d4 = d2 * d2;
    const double     n  = table.n_nodes;
    const double     nq = table.n_points();
    // F_q = sum_b y^b (x) B^{qb} and the weighted tangent w_q A_q
    double flops = nq * (2 * n * d2 + d4);
    if (table.test_is_trial)
      {
        // residual: P_q B^{qa} for every node; tangent: for every pair of
        // components i <= k, X = [B_q C_q^{ik}] (n x nq dim, inner sum over
        // dim) and the product X Y^T (n x n, inner dimension nq dim)
        const double pairs = dim * (dim + 1) / 2;
        flops +=
          nq * n * 2 * d2 + pairs * (nq * n * 2 * d2 + 2 * n * n * nq * dim);
      }
    else
      {
        // w A_q B^{qb} for every node, then per test vector the residual
        // P_q T^{qa} and one row block T^{qa} (w A_q B^{qb}) for every b
        const double n_test = table.test_vectors.size();
        flops += nq * n * 2 * d4 + n_test * (2 * d2 + 2 * n * d2 * dim);
      }
    return flops;
  }



  template double
  tangent_entries<2>(const QuadratureTable<2> &);
  template double
  tangent_entries<3>(const QuadratureTable<3> &);
  template double
  tangent_flops<2>(const QuadratureTable<2> &);
  template double
  tangent_flops<3>(const QuadratureTable<3> &);
} // namespace pg
