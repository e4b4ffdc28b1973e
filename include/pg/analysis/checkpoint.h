#ifndef pg_analysis_checkpoint_h
#define pg_analysis_checkpoint_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <functional>
#include <map>
#include <string>

namespace boost
{
  namespace archive
  {
    class binary_oarchive;
    class binary_iarchive;
  } // namespace archive
} // namespace boost

namespace pg
{
  /**
   * The checkpoint of a run ('Output/Checkpoint interval', SIGINT and
   * SIGTERM; read back by `pg_solve --restart`): the directory
   * <Output/Directory>/checkpoint with one boost binary archive per MPI
   * rank (rank-<r>.bin: the run's signature, then what the problem and
   * its analysis save: displacement, material history, summary,
   * statistics, PVD records, and velocity, acceleration, forces and
   * energies of a dynamic run) and info.txt for people.
   *
   * A checkpoint is written into checkpoint.new and then renamed, so an
   * interruption while writing leaves the previous checkpoint intact. It
   * can be read only by the same run on the same number of ranks: the
   * signature (dimension, ranks, DoFs, formulation, analysis and its step
   * parameters) must match, else the restart stops and names the
   * difference.
   */
  class Checkpoint
  {
  public:
    /** What the problem and the analysis write and read. */
    using Writer = std::function<void(boost::archive::binary_oarchive &)>;
    using Reader = std::function<void(boost::archive::binary_iarchive &)>;
    /** name -> value of what identifies the run (see above). */
    using Signature = std::map<std::string, std::string>;

    Checkpoint(const std::string &output_directory, const MPI_Comm comm);

    /** <Output/Directory>/checkpoint */
    const std::string &
    directory() const;

    /**
     * Write the checkpoint of step @p step at time or load factor @p t
     * (collective): @p signature, then @p write, on every rank; throws
     * if any rank cannot write.
     */
    void
    write(const Signature   &signature,
          const unsigned int step,
          const double       t,
          const Writer      &write) const;

    /**
     * Read the checkpoint (collective): throws with a clear message if
     * there is none or its signature differs from @p signature; then
     * @p read. Returns the step.
     */
    unsigned int
    read(const Signature &signature, double &t, const Reader &read) const;

  private:
    const std::string output_directory;
    const std::string checkpoint_directory;
    const MPI_Comm    comm;
  };

  namespace CheckpointData
  {
    /** This rank's entries of @p v. */
    void
    save(boost::archive::binary_oarchive &archive,
         const LinearAlgebra::Vector     &v);

    /**
     * Read what save() wrote into @p v (same layout; throws naming @p name
     * if the sizes differ).
     */
    void
    load(boost::archive::binary_iarchive &archive,
         LinearAlgebra::Vector           &v,
         const std::string               &name);
  } // namespace CheckpointData
} // namespace pg

#endif
