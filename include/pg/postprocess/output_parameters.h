#ifndef pg_postprocess_output_parameters_h
#define pg_postprocess_output_parameters_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <string>
#include <utility>
#include <vector>

// What a run writes (subsection "Output"): VTU files, reference points,
// boundary stresses and line samples.

namespace pg
{
  namespace Parameters
  {
    /** Subsection "Output". */
    struct Output
    {
      std::string directory;
      bool        vtu;
      /** Named reference points, each with dim coordinates. */
      std::vector<std::pair<std::string, std::vector<double>>> points;
      /** Boundary ids whose vertex stresses go to a table. */
      std::vector<types::boundary_id> stress_boundaries;
      /** A named segment for displacement_along_lines.txt. */
      struct Line
      {
        std::string         name;
        std::vector<double> start, end;
      };
      std::vector<Line> lines;
      /** Points per line, both ends included. */
      unsigned int line_samples;
      /**
       * A checkpoint after every this many accepted load or time steps (0:
       * only when SIGINT or SIGTERM stops the run).
       */
      unsigned int checkpoint_interval = 0;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };
  } // namespace Parameters
} // namespace pg

#endif
