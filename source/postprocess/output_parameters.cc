#include <pg/base/exceptions.h>
#include <pg/base/parameter_utilities.h>
#include <pg/postprocess/output_parameters.h>

#include <string>

namespace pg
{
  namespace Parameters
  {
    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        prm.declare_entry("Directory",
                          "results",
                          Patterns::Anything(),
                          "Where VTU/PVD files, statistics.txt, timing.txt "
                          "and summary.json go. Created if missing.");
        prm.declare_entry("VTU",
                          "true",
                          Patterns::Bool(),
                          "Write VTU/PVD files for ParaView after every "
                          "load step.");
        prm.declare_entry("Points",
                          "",
                          Patterns::Anything(),
                          "Named reference points whose displacement is "
                          "reported: 'name: x, y[, z]; name: ...', e.g. "
                          "'tip: 48, 60'.");
        prm.declare_entry("Stress along boundaries",
                          "",
                          Patterns::Anything(),
                          "Boundary ids whose vertices get a row in "
                          "stress_along_boundaries.txt at the end of the run: "
                          "position, Cauchy stress (particle value at "
                          "particles, the average of the adjacent Q1 cells "
                          "elsewhere) and, with 'Compute errors', the exact "
                          "stress. E.g. the symmetry lines of the plate with "
                          "a hole: '1, 2'.");
        prm.declare_entry(
          "Lines",
          "",
          Patterns::Anything(),
          "Named straight lines along which the displacement is written to "
          "displacement_along_lines.txt after every step: 'name: x0, y0 : x1, "
          "y1; name: ...' (dim coordinates per end). The displacement is the "
          "Q1 interpolant of the nodal values (particles included) at 'Line "
          "samples' equally spaced points; points outside the mesh (in a "
          "hole) are left out. E.g. the upper edge of the unit square: 'BB: "
          "0, 1 : 1, 1'.");
        prm.declare_entry("Line samples",
                          "101",
                          Patterns::Integer(2),
                          "Number of equally spaced points on each of the "
                          "'Lines', both ends included.");
        prm.declare_entry(
          "Checkpoint interval",
          "0",
          Patterns::Integer(0),
          "Write a checkpoint to <Directory>/checkpoint after every this "
          "many accepted load steps (static) or time steps (dynamic); 0: "
          "only when SIGINT (Ctrl-C) or SIGTERM stops the run, which always "
          "writes one after the step it is in. 'pg_solve --restart "
          "file.prm' continues from the checkpoint with the same parameter "
          "file on the same number of MPI ranks and gives the results of a "
          "run without interruption.");
      }
      prm.leave_subsection();
    }



    void
    Output::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      prm.enter_subsection("Output");
      {
        directory = prm.get("Directory");
        vtu       = prm.get_bool("VTU");
        points.clear();
        stress_boundaries      = parse_ids(prm.get("Stress along boundaries"),
                                      "Output/Stress along boundaries");
        const std::string text = prm.get("Points");
        for (const auto &parts :
             parse_items(text,
                         ';',
                         2,
                         "Output/Points",
                         "each point must read 'name: x, y'."))
          points.emplace_back(parts[0],
                              parse_coordinates(parts[1],
                                                dim,
                                                "Output/Points",
                                                text,
                                                "each point"));
        lines.clear();
        const std::string line_text = prm.get("Lines");
        for (const auto &parts :
             parse_items(line_text,
                         ';',
                         3,
                         "Output/Lines",
                         "each line must read 'name: x0, y0 : x1, y1'."))
          {
            const Line line{parts[0],
                            parse_coordinates(parts[1],
                                              dim,
                                              "Output/Lines",
                                              line_text,
                                              "each end of a line"),
                            parse_coordinates(parts[2],
                                              dim,
                                              "Output/Lines",
                                              line_text,
                                              "each end of a line")};
            AssertThrow(line.start != line.end,
                        ExcBadParameter("Output/Lines",
                                        line_text,
                                        "the line '" + line.name +
                                          "' has equal ends."));
            lines.push_back(line);
          }
        line_samples        = prm.get_integer("Line samples");
        checkpoint_interval = prm.get_integer("Checkpoint interval");
      }
      prm.leave_subsection();
      AssertThrow(!directory.empty(),
                  ExcBadParameter("Output/Directory",
                                  directory,
                                  "it must name a directory."));
    }
  } // namespace Parameters
} // namespace pg
