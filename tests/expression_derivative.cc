// Expression::derivative() against forward automatic differentiation
// (Sacado) of the same expression: first and second derivatives of
// expressions using every rule of the grammar (+ - * / ^ with integer and
// real exponents, unary minus, every function, pos/abs/max/min on both sides
// of their kinks, the comparisons, && || and c ? a : b), at points of a grid,
// agree to round-off. The same expressions and derivatives on one
// ExpressionTape, evaluated for all points of the grid at once with the time
// uniform, give the values of the trees.
#include <hemicontact/expressions/expression.h>
#include <hemicontact/expressions/expression_tape.h>

#include <Sacado.hpp>

#include <cmath>
#include <iomanip>

#include "tests.h"

using namespace hemicontact;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>           variables = {"x", "y", "t"};
  const std::map<std::string, double>      constants = {{"c", 0.7}};
  const std::vector<std::string>           cases     = {
                  "x^3*y - 2*x/(1 + y^2) + c*t",
                  "sin(x)*cos(2*y) + tan(0.3*x) - exp(-t*x)",
                  "log(2 + x*y) + sqrt(3 + y) + tanh(x - y) + sinh(t) * cosh(x)",
                  "atan(x*y) + pow(1.5 + x, 2.5) + pow(2 + y, x) + (2 + x)^0.5",
                  "pos(x - 0.1)^3 + abs(y - 0.2)*x + max(x, y)*t + min(x*x, y)",
                  "-(x - y)^2 + step(x)*y + sign(y - 0.3)*x^2 + pos(t - x)",
                  "(x < y)*x^2 + (x >= 0.15 && y != 0.05)*t*x + (x > y || t <= 0.5)*y^2 - "
                                "(x == 0.45)*t*y",
                  "(x < y ? x^2*t : sin(y)*x) + (t > 0.5 ? y : 0)"};

  using AD       = Sacado::Fad::SFad<double, 3>;
  using AD2      = Sacado::Fad::SFad<AD, 3>;
  double largest = 0;
  for (const std::string &text : cases)
    {
      const Expression        f(text, variables, constants, "test");
      std::vector<Expression> first, second;
      for (unsigned int i = 0; i < 3; ++i)
        first.push_back(f.derivative(i));
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          second.push_back(first[i].derivative(j));

      double error = 0;
      for (const double x : {-0.35, 0.15, 0.45})
        for (const double y : {-0.25, 0.05, 0.6})
          for (const double t : {0.1, 0.9})
            {
              const std::vector<double> at = {x, y, t};
              std::vector<AD2>          ad(3);
              for (unsigned int i = 0; i < 3; ++i)
                ad[i] = AD2(3, i, AD(3, i, at[i]));
              const AD2 r = f.evaluate(ad);
              for (unsigned int i = 0; i < 3; ++i)
                {
                  const double exact = r.val().dx(i);
                  error              = std::max(error,
                                   std::abs(first[i].evaluate(at) - exact) /
                                     (1 + std::abs(exact)));
                  for (unsigned int j = 0; j < 3; ++j)
                    {
                      const double exact2 = r.dx(j).dx(i);
                      error               = std::max(error,
                                       std::abs(second[3 * i + j].evaluate(at) -
                                                exact2) /
                                         (1 + std::abs(exact2)));
                    }
                }
            }
      out() << text << ": " << (error < 1e-13 ? "agrees" : "DIFFERS") << "\n";
      largest = std::max(largest, error);

      // one tape, one batch per time
      std::vector<const Expression *> all = {&f};
      for (const auto *list : {&first, &second})
        for (const Expression &e : *list)
          all.push_back(&e);
      const ExpressionTape tape(all, /*uniform_variables=*/{2});
      double               batch_error = 0;
      for (const double t : {0.1, 0.9})
        {
          std::vector<double> at;
          for (const double x : {-0.35, 0.15, 0.45})
            for (const double y : {-0.25, 0.05, 0.6})
              at.insert(at.end(), {x, y, t});
          const unsigned int  n_points = at.size() / 3;
          std::vector<double> results(n_points * tape.n_outputs());
          tape.evaluate(at.data(), 3, n_points, results.data());
          for (unsigned int p = 0; p < n_points; ++p)
            for (unsigned int k = 0; k < all.size(); ++k)
              {
                const double tree =
                  all[k]->evaluate(std::vector<double>(at.begin() + 3 * p,
                                                       at.begin() + 3 * p + 3));
                batch_error =
                  std::max(batch_error,
                           std::abs(results[p * tape.n_outputs() + k] - tree) /
                             (1 + std::abs(tree)));
              }
        }
      out() << "  tape, 9 points per batch: "
            << (batch_error < 1e-14 ? "equal to the trees" : "DIFFERS") << "\n";
      largest = std::max(largest, batch_error);
    }
  out() << "largest relative difference below 1e-13: "
        << (largest < 1e-13 ? "yes" : "NO") << "\n";
}
