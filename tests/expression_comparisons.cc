// The comparisons < > <= >= == !=, the logical && || and c ? a : b of
// Expression (the grammar of every expression entry, doc/parameters.md)
// give the values muparser gives for the same text, at points on both
// sides of each switch and on it: the same precedence, 1 for true and 0 for
// false. A '?' without its ':' is refused.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/expressions/expression.h>

#include "tests.h"

using namespace dealii;
using namespace hemicontact;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>           variables = {"x", "y", "t"};
  const std::map<std::string, double>      constants = {{"c", 0.15}};
  const std::vector<std::string>           cases     = {
                  "x < y",
                  "x <= c",
                  "x > y",
                  "x >= 0.15",
                  "x == c",
                  "x != 0.15",
                  "x < 0.2 && y > 0",
                  "x < 0.2 || y > 0.5",
                  "x > 0 || y > 0 && t > 0.5",
                  "1 + x < y * 2 - t",
                  "x < y == t > 0.5",
                  "2^x > 1.1 && -x < 0",
                  "0.3*(x < 0.4) + 0.2*(x >= 0.4)",
                  "max(x, y) > t || x*y != 0",
                  "x < 0.2 ? y : t",
                  "x < y ? x + 1 : y*2 - t",
                  "x > 0 ? y > 0 ? 1 : 2 : 3",
                  "x > 0 && t > 0.5 ? sin(x) : 0.2 + (x < 0.4 ? 0 : 0.1)"};

  bool all_equal = true;
  for (const std::string &text : cases)
    {
      const Expression  f(text, variables, constants, "test");
      FunctionParser<2> parser(1);
      parser.initialize("x,y,t", text, constants, /*time_dependent=*/true);
      unsigned int n_points = 0, n_equal = 0, n_true = 0;
      for (const double x : {-0.35, 0.15, 0.4, 0.45})
        for (const double y : {-0.25, 0.05, 0.15, 0.6})
          for (const double t : {0.1, 0.5, 0.9})
            {
              parser.set_time(t);
              const double expected = parser.value(Point<2>(x, y));
              const double value    = f.evaluate(std::vector<double>{x, y, t});
              ++n_points;
              n_equal += value == expected;
              n_true += value != 0;
            }
      out() << text << ": " << n_equal << " of " << n_points
            << " points as muparser (" << n_true << " nonzero)\n";
      all_equal = all_equal && n_equal == n_points;
    }
  out() << "all as muparser: " << (all_equal ? "yes" : "NO") << "\n";

  try
    {
      const Expression f("x < 0.5 ? 0.3",
                         variables,
                         constants,
                         "friction bound");
      out() << "'?' without ':' accepted: NO\n";
    }
  catch (const InputError &e)
    {
      out() << e.what() << "\n";
    }
}
