#ifndef pg_materials_small_matrix_h
#define pg_materials_small_matrix_h

#include <pg/base/global.h>

#include <array>
#include <cmath>
#include <type_traits>

namespace pg
{
  namespace Materials
  {
    /**
     * Dense 3x3 matrices of an arbitrary number type (double or a Sacado
     * forward AD type), for the local plasticity update, where deal.II's
     * Tensor would need the AD product traits. Only what J2Plasticity
     * needs: products, transpose, determinant, inverse and the exponential.
     */
    namespace SmallMatrix
    {
      template <typename Number>
      using Matrix3 = std::array<std::array<Number, 3>, 3>;

      /** The value part of @p x (x itself for double). */
      inline double
      value_of(const double x)
      {
        return x;
      }

      /** The value part of a Sacado Fad number. */
      template <typename Number>
      inline auto
      value_of(const Number &x) -> decltype(x.val())
      {
        return x.val();
      }

      /** The zero matrix. */
      template <typename Number>
      Matrix3<Number>
      zero()
      {
        Matrix3<Number> M;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            M[a][b] = 0.;
        return M;
      }

      /** The identity. */
      template <typename Number>
      Matrix3<Number>
      identity()
      {
        Matrix3<Number> M = zero<Number>();
        for (unsigned int a = 0; a < 3; ++a)
          M[a][a] = 1.;
        return M;
      }

      /**
       * A B; either factor may be double and the other an AD type (the
       * product has the AD type).
       */
      template <typename Number, typename Number2>
      Matrix3<
        std::conditional_t<std::is_same_v<Number, double>, Number2, Number>>
      multiply(const Matrix3<Number> &A, const Matrix3<Number2> &B)
      {
        using Product =
          std::conditional_t<std::is_same_v<Number, double>, Number2, Number>;
        Matrix3<Product> C;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            {
              Product c = A[a][0] * B[0][b];
              c += A[a][1] * B[1][b];
              c += A[a][2] * B[2][b];
              C[a][b] = c;
            }
        return C;
      }

      /** A^T. */
      template <typename Number>
      Matrix3<Number>
      transpose(const Matrix3<Number> &A)
      {
        Matrix3<Number> T;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            T[a][b] = A[b][a];
        return T;
      }

      /** det A. */
      template <typename Number>
      Number
      determinant(const Matrix3<Number> &A)
      {
        return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
               A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
               A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
      }

      /** A^{-1} (by cofactors; A must be regular). */
      template <typename Number>
      Matrix3<Number>
      invert(const Matrix3<Number> &A)
      {
        const Number    det = determinant(A);
        Matrix3<Number> B;
        B[0][0] = (A[1][1] * A[2][2] - A[1][2] * A[2][1]) / det;
        B[0][1] = (A[0][2] * A[2][1] - A[0][1] * A[2][2]) / det;
        B[0][2] = (A[0][1] * A[1][2] - A[0][2] * A[1][1]) / det;
        B[1][0] = (A[1][2] * A[2][0] - A[1][0] * A[2][2]) / det;
        B[1][1] = (A[0][0] * A[2][2] - A[0][2] * A[2][0]) / det;
        B[1][2] = (A[0][2] * A[1][0] - A[0][0] * A[1][2]) / det;
        B[2][0] = (A[1][0] * A[2][1] - A[1][1] * A[2][0]) / det;
        B[2][1] = (A[0][1] * A[2][0] - A[0][0] * A[2][1]) / det;
        B[2][2] = (A[0][0] * A[1][1] - A[0][1] * A[1][0]) / det;
        return B;
      }

      /** tr A. */
      template <typename Number>
      Number
      trace(const Matrix3<Number> &A)
      {
        return A[0][0] + A[1][1] + A[2][2];
      }

      /** A : A. */
      template <typename Number>
      Number
      squared_norm(const Matrix3<Number> &A)
      {
        Number s = A[0][0] * A[0][0];
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            if (a + b > 0)
              s += A[a][b] * A[a][b];
        return s;
      }

      /**
       * exp(X) by scaling and squaring: the Taylor series of X / 2^s with
       * |X / 2^s| <= 1/4 (Frobenius norm of the values), of the lowest order
       * m >= 1 with |X / 2^s|^m / m! <= 1e-17 (at most 13), squared s
       * times. The truncation error of the value and of its first
       * derivatives is then below round-off. It needs no eigenvalues, so
       * repeated eigenvalues (uniaxial states) are no special case, and it
       * works for AD types: their derivatives are those of the same
       * polynomial. s and m depend on the values only.
       */
      template <typename Number>
      Matrix3<Number>
      exponential(const Matrix3<Number> &X)
      {
        double norm_squared = 0.;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            norm_squared += value_of(X[a][b]) * value_of(X[a][b]);
        const double norm    = std::sqrt(norm_squared);
        unsigned int squares = 0;
        if (norm > 0.25)
          squares =
            static_cast<unsigned int>(std::ceil(std::log2(norm / 0.25)));
        const double scale = std::ldexp(1., -static_cast<int>(squares));

        Matrix3<Number> Y = X;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            Y[a][b] *= scale;

        // The order m: |Y|^m / m! <= 1e-17, m >= 1 (|Y| <= 1/4: m <= 13).
        const double norm_Y = norm * scale;
        unsigned int order  = 1;
        for (double term = norm_Y; term > 1e-17 && order < 13;)
          {
            ++order;
            term *= norm_Y / order;
          }

        // Horner: exp(Y) ~ 1 + Y (1 + Y/2 (1 + Y/3 (... (1 + Y/m)))).
        Matrix3<Number> E = identity<Number>();
        for (unsigned int k = order; k >= 1; --k)
          {
            E = multiply(Y, E);
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                E[a][b] /= static_cast<double>(k);
            for (unsigned int a = 0; a < 3; ++a)
              E[a][a] += 1.;
          }
        for (unsigned int i = 0; i < squares; ++i)
          E = multiply(E, E);
        return E;
      }
    } // namespace SmallMatrix
  }   // namespace Materials
} // namespace pg

#endif
