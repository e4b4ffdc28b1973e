#include <pg/base/parameter_file.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace pg
{
  namespace Parameters
  {
    namespace
    {
      /** Edit distance of @p a and @p b, ignoring case. */
      unsigned int
      distance(const std::string &a, const std::string &b)
      {
        std::vector<unsigned int> row(b.size() + 1);
        for (unsigned int j = 0; j <= b.size(); ++j)
          row[j] = j;
        for (unsigned int i = 1; i <= a.size(); ++i)
          {
            unsigned int diagonal = row[0];
            row[0]                = i;
            for (unsigned int j = 1; j <= b.size(); ++j)
              {
                const unsigned int above = row[j];
                const bool         same =
                  std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                  std::tolower(static_cast<unsigned char>(b[j - 1]));
                row[j] = std::min(
                  {row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0u : 1u)});
                diagonal = above;
              }
          }
        return row[b.size()];
      }



      /** "a/b" of the subsection @p path ("" at the top). */
      std::string
      joined(const std::vector<std::string> &path)
      {
        std::string text;
        for (const auto &s : path)
          text += (text.empty() ? "" : "/") + s;
        return text;
      }



      /** The subsection path of every declared entry name. */
      std::multimap<std::string, std::string>
      declared_entries(const ParameterHandler &prm)
      {
        std::ostringstream listing;
        prm.print_parameters(listing, ParameterHandler::ShortPRM);
        std::multimap<std::string, std::string> entries;
        std::vector<std::string>                path;
        std::istringstream                      lines(listing.str());
        for (std::string line; std::getline(lines, line);)
          {
            line = Utilities::trim(line);
            if (line.rfind("subsection ", 0) == 0)
              path.push_back(Utilities::trim(line.substr(11)));
            else if (line == "end" && !path.empty())
              path.pop_back();
            else if (line.rfind("set ", 0) == 0)
              entries.emplace(Utilities::trim(
                                line.substr(4, line.find('=') - 4)),
                              joined(path));
          }
        return entries;
      }



      /**
       * The subsection path open at line @p n of @p filename (1-based):
       * 'subsection' and 'end' before it, comments ignored.
       */
      std::string
      subsection_at(const std::string &filename, const unsigned int n)
      {
        std::ifstream            file(filename);
        std::vector<std::string> path;
        std::string              line;
        for (unsigned int i = 1; i < n && std::getline(file, line); ++i)
          {
            line = Utilities::trim(line.substr(0, line.find('#')));
            if (line.rfind("subsection ", 0) == 0)
              path.push_back(Utilities::trim(line.substr(11)));
            else if (line == "end" && !path.empty())
              path.pop_back();
          }
        return joined(path);
      }



      /** The text between @p open and the next '>' after @p key. */
      std::string
      bracketed(const std::string &text, const std::string &key)
      {
        const auto start = text.find(key);
        if (start == std::string::npos)
          return "";
        const auto end = text.find('>', start + key.size());
        return end == std::string::npos ?
                 "" :
                 text.substr(start + key.size(), end - start - key.size());
      }
    } // namespace



    void
    parse_parameter_file(ParameterHandler &prm, const std::string &filename)
    {
      try
        {
          prm.parse_input(filename);
        }
      catch (const ExceptionBase &exc)
        {
          std::ostringstream info;
          exc.print_info(info);
          const std::string message = Utilities::trim(info.str());
          const std::string name = bracketed(message, "No entry with name <");
          const std::string line = bracketed(message, "Line <");
          const std::string file = bracketed(message, "of file <");
          if (name.empty() || line.empty())
            throw;
          const std::string subsection =
            subsection_at(file.empty() ? filename : file,
                          Utilities::string_to_int(line));
          const auto               entries = declared_entries(prm);
          std::string              best;
          unsigned int             best_distance = name.size() / 3 + 1;
          std::vector<std::string> elsewhere;
          for (const auto &[entry, path] : entries)
            {
              if (path == subsection)
                {
                  const unsigned int d = distance(name, entry);
                  if (d < best_distance)
                    {
                      best          = entry;
                      best_distance = d;
                    }
                }
              else if (distance(name, entry) == 0)
                elsewhere.push_back(path.empty() ? "(top level)" : path);
            }
          std::string hint =
            " The entry is read in subsection '" +
            (subsection.empty() ? std::string("(top level)") : subsection) +
            "'.";
          if (!best.empty())
            hint += " Did you mean '" + best + "'?" +
                    (best_distance == 0 ? " (Names are case sensitive.)" : "");
          else if (!elsewhere.empty())
            {
              hint += " An entry of this name is declared in subsection";
              for (unsigned int i = 0; i < elsewhere.size(); ++i)
                hint += (i == 0 ? " '" : ", '") + elsewhere[i] + "'";
              hint += ".";
            }
          hint += " 'pg_solve --print-parameters' lists every entry.";
          AssertThrow(false, ExcMessage(message + hint));
        }
    }
  } // namespace Parameters
} // namespace pg
