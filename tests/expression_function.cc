// ExpressionFunction, the Function of every expression entry of 'data'
// (doc/parameters.md, Expressions): the values of data-like expressions
// with pos(), if(), c ? a : b, comparisons, ^ and unary minus, the user
// constants and pi, _pi, _e, in 2d and 3d; the same bits as
// dealii::FunctionParser where muparser reads the same text; the same bits
// from two threads at once; and the one-paragraph messages for expressions
// that do not parse. A change of the grammar changes this output.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/expressions/expression_function.h>
#include <hemicontact/model/problem_data.h>

#include <iomanip>
#include <thread>

#include "tests.h"

using namespace dealii;
using namespace hemicontact;

namespace
{
  const std::string constants = "P=3, S=2";

  /** The points the 2d expressions are evaluated at. */
  std::vector<Point<2>>
  points_2d()
  {
    std::vector<Point<2>> points;
    for (const double x : {-0.5, 0.25, 0.5, 1.999, 2.0})
      for (const double y : {0.1, 0.5})
        points.emplace_back(x, y);
    return points;
  }

  void
  print_2d(const std::string &text)
  {
    const auto f = parse_function<2>(text, 2, constants, "body force");
    f->set_time(0.3);
    const std::vector<Point<2>> points = points_2d();
    std::vector<Vector<double>> values(points.size(), Vector<double>(2));
    f->vector_value_list(points, values);
    out() << text << ":\n";
    for (unsigned int p = 0; p < points.size(); ++p)
      out() << "  (" << points[p] << "): " << values[p][0] << ' '
            << values[p][1] << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  out() << std::setprecision(17);

  out() << "values at t = 0.3 with " << constants << ":\n";
  for (const std::string &text :
       {"0; -P*pos(x - 0.25)^2",
        "if(x < 0.5, S*t, -1); x > 0.4 ? y : 2*y",
        "-x^2; 2^3^2 - 2^-1",
        "2*t*(x > 1.999); -0.5*(y > 0.499)",
        "S*sin(pi*t)*x/4; -P*sin(2*pi*t)*(0.25 + x/4)",
        "0; -P*sin(2*pi*t)*exp(-4*x^2)",
        "max(x, y) + min(x, y) + abs(x); _pi - pi + _e - exp(1) + sign(x)",
        "x > 0 && y < 0.2 || x == 2; x != 0.25 ? sqrt(x*x) + log(2) : -1"})
    print_2d(text);

  {
    const auto f =
      parse_function<3>("pos(z - 0.5); y; -x*t", 3, constants, "body force");
    f->set_time(2);
    Vector<double> v(3);
    f->vector_value(Point<3>(0.5, 0.25, 0.75), v);
    out() << "3d pos(z - 0.5); y; -x*t at (0.5, 0.25, 0.75), t = 2: " << v[0]
          << ' ' << v[1] << ' ' << v[2] << '\n';
  }

  // the same bits as muparser for the expressions of the shipped files
  const std::map<std::string, double> values = parse_constants(constants);
  bool                                same   = true;
  for (const std::string &text :
       {"S*sin(pi*t)*x/4; -P*sin(2*pi*t)*(0.25 + x/4)",
        "S*sin(pi*t)*x/4*0.8; S*sin(pi*t)*x/4*0.6",
        "2*t*(x > 1.999); -0.5*(y > 0.499)",
        "0; -P*sin(2*pi*t)*exp(-4*x^2)",
        "-x^2 + 2^3^2; if(x < 0.5, S*t, -1)"})
    {
      const auto        f = parse_function<2>(text, 2, constants, "test");
      FunctionParser<2> parser(2);
      parser.initialize("x,y,t", text, values, /*time_dependent=*/true);
      for (const double t : {0.0, 0.3, 0.71})
        {
          f->set_time(t);
          parser.set_time(t);
          for (const Point<2> &p : points_2d())
            for (unsigned int c = 0; c < 2; ++c)
              same = same && f->value(p, c) == parser.value(p, c);
        }
    }
  out() << "the same bits as FunctionParser: " << (same ? "yes" : "NO") << '\n';

  // two threads at once
  {
    const auto f =
      parse_function<2>("S*sin(pi*t)*x/4 + pos(y - 0.2)^3; if(x > 0, y, -y)",
                        2,
                        constants,
                        "test");
    f->set_time(0.4);
    std::vector<Point<2>> points;
    for (unsigned int i = 0; i < 200; ++i)
      points.emplace_back(0.01 * i - 1, 0.005 * i);
    std::vector<Vector<double>> expected(points.size(), Vector<double>(2));
    f->vector_value_list(points, expected);
    bool       equal = true;
    const auto run   = [&]() {
      std::vector<Vector<double>> v(points.size(), Vector<double>(2));
      for (unsigned int k = 0; k < 200; ++k)
        {
          f->vector_value_list(points, v);
          for (unsigned int p = 0; p < points.size(); ++p)
            if (v[p] != expected[p])
              equal = false;
        }
    };
    std::thread a(run), b(run);
    a.join();
    b.join();
    out() << "two threads: " << (equal ? "the same values" : "DIFFERENT")
          << '\n';
  }

  for (const std::string &text : std::vector<std::string>{
         "0; sin(x",
         "0; asin(x)",
         "q*t; 0",
         "if(x, 1); 0",
         "0; 1 +* x",
         std::string(30, '(') + "x" + std::string(30, ')') + "; 0",
         std::string(600, '(') + "x" + std::string(600, ')') + "; 0"})
    try
      {
        parse_function<2>(text, 2, constants, "body force");
        out() << text << ": accepted\n";
      }
    catch (const InputError &e)
      {
        out() << e.what() << '\n';
      }
}
