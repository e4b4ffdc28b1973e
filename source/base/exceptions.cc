#include <pg/base/exceptions.h>

#include <deal.II/base/utilities.h>

#include <cctype>
#include <sstream>

namespace pg
{
  std::string
  user_message(const std::exception &exc)
  {
    if (const auto *deal_ii = dynamic_cast<const ExceptionBase *>(&exc))
      {
        std::ostringstream info;
        deal_ii->print_info(info);
        const std::string message = Utilities::trim(info.str());
        // an exception without arguments (ExcInternalError, say) has no
        // message of its own: its name and condition are all there is
        if (!message.empty() && message != "(none)")
          return message;
      }
    return Utilities::trim(exc.what());
  }



  std::string
  one_line(const std::string &message)
  {
    std::string line;
    for (const char c : message)
      if (!std::isspace(static_cast<unsigned char>(c)))
        line += c;
      else if (!line.empty() && line.back() != ' ')
        line += ' ';
    if (!line.empty() && line.back() == ' ')
      line.pop_back();
    return line;
  }
} // namespace pg
