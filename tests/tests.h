#ifndef pg_tests_h
#define pg_tests_h

// Our own small test helper (not deal.II's tests.h): a log file named
// 'output' that deal.II's test driver compares with numdiff, a fixed thread
// count, and printing helpers that print only reproducible digits.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/logstream.h>
#include <deal.II/base/multithread_info.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;

namespace pg_tests
{
  inline std::ofstream logfile;
}

inline void
initlog()
{
  pg_tests::logfile.open("output");
  deallog.attach(pg_tests::logfile);
  deallog.depth_console(0);
  MultithreadInfo::set_thread_limit(1);
}

/** "name: yes" if |value| <= bound, else "name: NO (value)". */
inline void
print_bound(const std::string &name, const double value, const double bound)
{
  if (std::abs(value) <= bound)
    deallog << name << " <= " << bound << ": yes" << std::endl;
  else
    deallog << name << " <= " << bound << ": NO (" << value << ")" << std::endl;
}

/**
 * "yes" if @p value <= @p bound, else "NO (value)"; "n/a" for a negative
 * @p value, which the checks use for "does not apply" (their values are
 * norms).
 */
inline std::string
verdict(const double value, const double bound)
{
  std::ostringstream s;
  if (value < 0)
    s << "n/a";
  else if (value <= bound)
    s << "yes";
  else
    s << "NO (" << value << ")";
  return s.str();
}

/**
 * The message of a deal.II exception (its print_info() text) without the
 * trailing blanks and line breaks.
 */
inline std::string
exception_message(const ExceptionBase &e)
{
  std::ostringstream message;
  e.print_info(message);
  std::string text = message.str();
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    text.pop_back();
  return text;
}

/** @p value with @p digits significant digits. */
inline void
print_rounded(const std::string &name, const double value, const int digits)
{
  std::ostringstream s;
  s << std::setprecision(digits) << value;
  deallog << name << " = " << s.str() << std::endl;
}

/**
 * The least-squares slope of log(y) against log(x): the convergence rate of
 * errors y against mesh sizes x (or, with x the DoFs, minus dim times it).
 */
inline double
log_log_slope(const std::vector<double> &x, const std::vector<double> &y)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (unsigned int i = 0; i < x.size(); ++i)
    {
      const double lx = std::log(x[i]), ly = std::log(y[i]);
      sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    }
  const double n = x.size();
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

#endif
