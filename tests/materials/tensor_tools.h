#ifndef pg_tests_materials_tensor_tools_h
#define pg_tests_materials_tensor_tools_h

// Small tensors for the material tests (material_tangent_01, _02,
// j2_plasticity_01): pseudo-random entries with a fixed sequence, the
// largest entry, a fixed rotation.

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <random>

// Entries uniform in [-1, 1] from std::mt19937, whose sequence the standard
// fixes (unlike that of std::uniform_real_distribution).
template <int dim>
dealii::Tensor<2, dim>
random_tensor(std::mt19937 &generator)
{
  dealii::Tensor<2, dim> H;
  for (unsigned int a = 0; a < dim; ++a)
    for (unsigned int b = 0; b < dim; ++b)
      H[a][b] = 2. * (generator() / 4294967295.) - 1.;
  return H;
}

/** max |T_i...| over the entries of @p T. */
template <int dim, int rank>
double
max_abs(const dealii::Tensor<rank, dim> &T)
{
  double m = 0.;
  for (unsigned int i = 0;
       i < dealii::Tensor<rank, dim>::n_independent_components;
       ++i)
    m = std::max(m, std::abs(T[T.unrolled_to_component_indices(i)]));
  return m;
}

/**
 * The rotation by @p angle (radians): in 2-D about the normal, in 3-D
 * about the axis (1, 2, 3) / sqrt(14) (Rodrigues: Q = cos 1 + sin [n]x +
 * (1 - cos) n n^T).
 */
template <int dim>
dealii::Tensor<2, dim>
rotation(const double angle)
{
  dealii::Tensor<2, dim> Q;
  const double           c = std::cos(angle), s = std::sin(angle);
  if (dim == 2)
    {
      Q[0][0] = c;
      Q[0][1] = -s;
      Q[1][0] = s;
      Q[1][1] = c;
    }
  else
    {
      const double n[3] = {1. / std::sqrt(14.),
                           2. / std::sqrt(14.),
                           3. / std::sqrt(14.)};
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          Q[a][b] = (a == b ? c : 0.) + (1. - c) * n[a] * n[b];
      Q[0][1] -= s * n[2];
      Q[1][0] += s * n[2];
      Q[0][2] += s * n[1];
      Q[2][0] -= s * n[1];
      Q[1][2] -= s * n[0];
      Q[2][1] += s * n[0];
    }
  return Q;
}

#endif
