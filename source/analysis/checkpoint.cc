#include <pg/analysis/checkpoint.h>
#include <pg/base/exceptions.h>

#include <boost/archive/archive_exception.hpp>
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <vector>

namespace pg
{
  namespace
  {
    /** The file of this rank in @p directory. */
    std::string
    rank_file(const std::string &directory, const MPI_Comm comm)
    {
      return directory + "/rank-" +
             std::to_string(Utilities::MPI::this_mpi_process(comm)) + ".bin";
    }

    /**
     * The first non-empty @p error of the ranks (by rank), the same on
     * every rank.
     */
    std::string
    first_error(const std::string &error, const MPI_Comm comm)
    {
      for (const std::string &e : Utilities::MPI::all_gather(comm, error))
        if (!e.empty())
          return e;
      return "";
    }
  } // namespace



  Checkpoint::Checkpoint(const std::string &output_directory,
                         const MPI_Comm     comm)
    : output_directory(output_directory)
    , checkpoint_directory(output_directory + "/checkpoint")
    , comm(comm)
  {}



  const std::string &
  Checkpoint::directory() const
  {
    return checkpoint_directory;
  }



  void
  Checkpoint::write(const Signature   &signature,
                    const unsigned int step,
                    const double       t,
                    const Writer      &write) const
  {
    namespace fs         = std::filesystem;
    const bool  root     = Utilities::MPI::this_mpi_process(comm) == 0;
    const auto  fresh    = checkpoint_directory + ".new";
    const auto  previous = checkpoint_directory + ".old";
    std::string error;
    if (root)
      try
        {
          fs::remove_all(fresh);
          fs::create_directories(fresh);
        }
      catch (const fs::filesystem_error &exc)
        {
          error = exc.code().message();
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (error.empty())
      try
        {
          std::ofstream file(rank_file(fresh, comm), std::ios::binary);
          AssertThrow(file,
                      ExcMessage("cannot open " + rank_file(fresh, comm)));
          {
            boost::archive::binary_oarchive archive(file);
            archive << signature << step << t;
            write(archive);
          }
          file.close();
          AssertThrow(file,
                      ExcMessage("cannot write " + rank_file(fresh, comm)));
        }
      catch (const std::exception &exc)
        {
          error = one_line(user_message(exc));
        }
    error = first_error(error, comm);
    // every rank's file is complete: replace the old checkpoint
    if (root && error.empty())
      try
        {
          fs::remove_all(previous);
          if (fs::exists(checkpoint_directory))
            fs::rename(checkpoint_directory, previous);
          fs::rename(fresh, checkpoint_directory);
          fs::remove_all(previous);
          std::ofstream info(checkpoint_directory + "/info.txt");
          info << std::setprecision(17) << "step " << step << "\ntime " << t
               << "\n";
          for (const auto &[name, value] : signature)
            info << name << " " << value << "\n";
        }
      catch (const fs::filesystem_error &exc)
        {
          error = exc.code().message();
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(),
                ExcMessage("The checkpoint of step " + std::to_string(step) +
                           " could not be written to '" + checkpoint_directory +
                           "': " + error +
                           ". Free disk space or choose another 'Directory' "
                           "in subsection 'Output'."));
  }



  unsigned int
  Checkpoint::read(const Signature &signature,
                   double          &t,
                   const Reader    &read) const
  {
    const std::string file_name = rank_file(checkpoint_directory, comm);
    std::string       error;
    unsigned int      step = 0;
    if (!std::filesystem::exists(file_name))
      error = "pg_solve --restart found no checkpoint '" + file_name +
              "'. A checkpoint is written every 'Checkpoint interval' steps "
              "(subsection 'Output') and when SIGINT or SIGTERM stops a "
              "run, with as many files as MPI ranks. Run on the number of "
              "ranks that wrote it, or without --restart to start from the "
              "beginning.";
    else
      try
        {
          std::ifstream                   file(file_name, std::ios::binary);
          boost::archive::binary_iarchive archive(file);
          Signature                       written;
          archive >> written >> step >> t;
          for (const auto &[name, value] : signature)
            {
              const auto        w = written.find(name);
              const std::string old =
                (w == written.end() ? std::string("(none)") : w->second);
              AssertThrow(old == value,
                          ExcMessage(
                            "The checkpoint in '" + checkpoint_directory +
                            "' was written by another run: its '" + name +
                            "' is " + old + ", this run's is " + value +
                            ". Restart with the parameter file (and the "
                            "number of MPI ranks) that wrote it, or run "
                            "without --restart."));
            }
          read(archive);
        }
      catch (const boost::archive::archive_exception &exc)
        {
          error = "The checkpoint '" + file_name + "' cannot be read (" +
                  exc.what() +
                  "). Run without --restart to start from the beginning.";
        }
      catch (const std::exception &exc)
        {
          error = one_line(user_message(exc));
        }
    error = first_error(error, comm);
    AssertThrow(error.empty(), ExcMessage(error));
    return step;
  }



  namespace CheckpointData
  {
    void
    save(boost::archive::binary_oarchive &archive,
         const LinearAlgebra::Vector     &v)
    {
      const std::vector<double> values(v.begin(), v.end());
      archive << values;
    }



    void
    load(boost::archive::binary_iarchive &archive,
         LinearAlgebra::Vector           &v,
         const std::string               &name)
    {
      std::vector<double> values;
      archive >> values;
      AssertThrow(values.size() == v.locally_owned_size(),
                  ExcMessage("The checkpoint holds " +
                             std::to_string(values.size()) + " entries of " +
                             name + " on this rank, this run has " +
                             std::to_string(v.locally_owned_size()) +
                             ". Restart with the parameter file and the "
                             "number of MPI ranks that wrote it."));
      std::copy(values.begin(), values.end(), v.begin());
    }
  } // namespace CheckpointData
} // namespace pg
