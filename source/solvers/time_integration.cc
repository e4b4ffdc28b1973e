#include <pg/solvers/time_integration.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdint>

namespace pg
{
  namespace TimeIntegration
  {
    namespace
    {
      /** A fixed pseudo-random number in [-1, 1] for index @p i. */
      double
      hash_to_unit(const types::global_dof_index i)
      {
        std::uint64_t x = static_cast<std::uint64_t>(i) + 0x9E3779B97F4A7C15ull;
        x               = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
        x               = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
        x               = x ^ (x >> 31);
        return 2. * static_cast<double>(x >> 11) / 9007199254740992. - 1.;
      }
    } // namespace



    double
    largest_eigenvalue(const LinearAlgebra::SparseMatrix &K,
                       const LinearAlgebra::Vector       &inverse_mass,
                       const unsigned int                 max_iterations,
                       const double                       tolerance)
    {
      LinearAlgebra::Vector x(inverse_mass), y(inverse_mass),
        mass(inverse_mass);
      const IndexSet     owned   = inverse_mass.locally_owned_elements();
      const unsigned int n_local = owned.n_elements();
      for (unsigned int i = 0; i < n_local; ++i)
        {
          const double w  = inverse_mass.begin()[i];
          mass.begin()[i] = (w > 0 ? 1. / w : 0.);
          x.begin()[i] = (w > 0 ? hash_to_unit(owned.nth_index_in_set(i)) : 0.);
        }
      // |x|_M^2 = x . M x
      const auto m_norm = [&](const LinearAlgebra::Vector &v) {
        double s = 0;
        for (unsigned int i = 0; i < n_local; ++i)
          s += mass.begin()[i] * v.begin()[i] * v.begin()[i];
        return std::sqrt(Utilities::MPI::sum(s, x.get_mpi_communicator()));
      };
      const double x_norm = m_norm(x);
      AssertThrow(x_norm > 0,
                  ExcMessage("The stable time step estimate needs at least "
                             "one free DoF with a positive mass: check "
                             "'Density' in subsection 'Material' and the "
                             "boundary conditions."));
      x /= x_norm;
      double estimate = 0;
      for (unsigned int it = 0; it < max_iterations; ++it)
        {
          K.vmult(y, x);
          for (unsigned int i = 0; i < n_local; ++i)
            y.begin()[i] *= inverse_mass.begin()[i];
          const double norm = m_norm(y);
          if (norm == 0)
            return 0;
          x = y;
          x /= norm;
          const bool converged =
            (it > 10 && std::abs(norm - estimate) <= tolerance * norm);
          estimate = norm;
          if (converged)
            break;
        }
      return estimate;
    }



    template <int dim>
    double
    rms_about_mean(const std::vector<Tensor<1, dim>> &u,
                   const std::vector<double>         &V)
    {
      AssertDimension(u.size(), V.size());
      double         volume = 0;
      Tensor<1, dim> mean;
      for (unsigned int k = 0; k < u.size(); ++k)
        {
          volume += V[k];
          mean += V[k] * u[k];
        }
      if (volume <= 0)
        return 0;
      mean /= volume;
      double s = 0;
      for (unsigned int k = 0; k < u.size(); ++k)
        s += V[k] * (u[k] - mean).norm_square();
      return std::sqrt(s / volume);
    }



    template <int dim>
    double
    local_fit_deviation(
      const std::vector<Point<dim>>                &X,
      const std::vector<Tensor<1, dim>>            &u,
      const std::vector<double>                    &V,
      const std::vector<std::vector<unsigned int>> &neighbours)
    {
      AssertDimension(X.size(), u.size());
      AssertDimension(X.size(), V.size());
      AssertDimension(X.size(), neighbours.size());
      double sum = 0, volume = 0;
      for (unsigned int k = 0; k < X.size(); ++k)
        {
          // normal equations of the fit in the basis (1, (X - X^k)/h)
          double h = 0;
          for (const unsigned int j : neighbours[k])
            h = std::max(h, (X[j] - X[k]).norm());
          if (neighbours[k].size() < dim + 1 || h == 0)
            continue;
          Eigen::Matrix<double, dim + 1, dim + 1> G =
            Eigen::Matrix<double, dim + 1, dim + 1>::Zero();
          Eigen::Matrix<double, dim + 1, dim> rhs =
            Eigen::Matrix<double, dim + 1, dim>::Zero();
          for (const unsigned int j : neighbours[k])
            {
              Eigen::Matrix<double, dim + 1, 1> p;
              p[0] = 1;
              for (unsigned int d = 0; d < dim; ++d)
                p[d + 1] = (X[j][d] - X[k][d]) / h;
              G.noalias() += p * p.transpose();
              for (unsigned int c = 0; c < dim; ++c)
                rhs.col(c) += p * u[j][c];
            }
          if (std::abs(G.determinant()) < 1e-10 * std::pow(G(0, 0), dim + 1))
            continue;
          // the fit at X^k is the constant coefficient a = (G^-1 rhs)_0
          const Eigen::Matrix<double, dim + 1, dim> a = G.inverse() * rhs;
          Tensor<1, dim>                            fit;
          for (unsigned int c = 0; c < dim; ++c)
            fit[c] = a(0, c);
          sum += V[k] * (u[k] - fit).norm_square();
          volume += V[k];
        }
      return volume > 0 ? std::sqrt(sum / volume) : 0.;
    }



    template double
    rms_about_mean<2>(const std::vector<Tensor<1, 2>> &,
                      const std::vector<double> &);
    template double
    rms_about_mean<3>(const std::vector<Tensor<1, 3>> &,
                      const std::vector<double> &);
    template double
    local_fit_deviation<2>(const std::vector<Point<2>> &,
                           const std::vector<Tensor<1, 2>> &,
                           const std::vector<double> &,
                           const std::vector<std::vector<unsigned int>> &);
    template double
    local_fit_deviation<3>(const std::vector<Point<3>> &,
                           const std::vector<Tensor<1, 3>> &,
                           const std::vector<double> &,
                           const std::vector<std::vector<unsigned int>> &);
  } // namespace TimeIntegration
} // namespace pg
