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
     * Read access by global index to a (ghosted) Vector, for the assembly
     * loops: Vector::operator() is an out-of-line call with a map lookup
     * for every entry. On a contiguous map (one rank) this is plain
     * indexing; otherwise Epetra's LID() (a hash lookup) without deal.II's
     * wrapper. The vector must outlive the reader and keep its layout.
     */
    class GlobalReader
    {
    public:
      explicit GlobalReader(const Vector &u)
        : values(u.trilinos_vector()[0])
        , map(&u.trilinos_vector().Map())
        , linear(u.trilinos_vector().Map().LinearMap())
        , first(u.trilinos_vector().Map().MinMyGID64())
      {}

      double
      operator[](const types::global_dof_index i) const
      {
        if (linear)
          return values[static_cast<long long>(i) - first];
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
