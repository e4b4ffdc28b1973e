#ifndef pg_base_global_reader_h
#define pg_base_global_reader_h

#include <pg/base/linear_algebra.h>

#include <Epetra_BlockMap.h>

#include <string>

namespace pg
{
  namespace LinearAlgebra
  {
    /**
     * Are the global indices of this rank's entries of @p map first, first
     * + 1, ..., last, in this order (always on one rank)? deal.II lists a
     * vector's indices in increasing order, so the count, the first and the
     * last index tell.
     */
    inline bool
    is_index_range(const Epetra_BlockMap &map)
    {
      if (map.LinearMap())
        return true;
      const int n = map.NumMyElements();
      return n > 0 && map.MaxMyGID64() - map.MinMyGID64() + 1 == n &&
             map.GID64(0) == map.MinMyGID64() &&
             map.GID64(n - 1) == map.MaxMyGID64();
    }



    /**
     * Read access by global index to a (ghosted) Vector, for the assembly
     * loops: Vector::operator() is an out-of-line call with a map lookup
     * for every entry. Where this rank's entries are one contiguous range
     * of global indices (is_index_range()) this is plain indexing;
     * otherwise Epetra's LID() (a hash lookup) without deal.II's wrapper.
     * The vector must outlive the reader and keep its layout.
     */
    class GlobalReader
    {
    public:
      explicit GlobalReader(const Vector &u)
        : values(u.trilinos_vector()[0])
        , map(&u.trilinos_vector().Map())
        , linear(is_index_range(u.trilinos_vector().Map()))
        , first(u.trilinos_vector().Map().MinMyGID64())
      {}

      double
      operator[](const types::global_dof_index i) const
      {
        if (linear)
          {
            Assert(map->LID(static_cast<TrilinosWrappers::types::int_type>(
                     i)) == static_cast<long long>(i) - first,
                   ExcInternalError());
            return values[static_cast<long long>(i) - first];
          }
        const int local =
          map->LID(static_cast<TrilinosWrappers::types::int_type>(i));
        Assert(local >= 0,
               ExcMessage("Entry " + std::to_string(i) +
                          " is not in this rank's ghosted vector."));
        return values[local];
      }

    private:
      const double          *values;
      const Epetra_BlockMap *map;
      bool                   linear;
      long long              first;
    };
  } // namespace LinearAlgebra
} // namespace pg

#endif
