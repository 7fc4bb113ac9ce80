#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/normal/piecewise_linear_law.h>

#include <algorithm>
#include <cmath>

namespace hemicontact
{
  namespace
  {
    std::vector<std::pair<double, double>>
    parse_breakpoints(const std::string &text)
    {
      std::vector<std::pair<double, double>> result;
      for (const std::string &item : Utilities::split_string_list(text, ','))
        {
          const std::vector<std::string> rp =
            Utilities::split_string_list(item, ':');
          require(rp.size() == 2,
                  "normal law 'piecewise linear': the breakpoint '" + item +
                    "' is not of the form r:p (expected a list such as "
                    "'0:1, 0.1:1.5, 0.3:0.5').");
          try
            {
              result.emplace_back(Utilities::string_to_double(rp[0]),
                                  Utilities::string_to_double(rp[1]));
            }
          catch (...)
            {
              throw InputError(
                "normal law 'piecewise linear': the breakpoint '" + item +
                "' does not hold two numbers r:p.");
            }
          require(std::isfinite(result.back().first) &&
                    std::isfinite(result.back().second),
                  "normal law 'piecewise linear': the breakpoint '" + item +
                    "' of 'subgradient breakpoints' holds a value that is "
                    "not a finite number.");
        }
      return result;
    }
  } // namespace

  void
  PiecewiseLinearLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    prm.declare_entry(
      "subgradient breakpoints",
      "0:1, 0.05:1.5, 0.2:0.4",
      Patterns::Anything(),
      "Breakpoints r:p of the response p(r) for r > 0, comma separated, "
      "with r strictly increasing from r = 0 and p >= 0. p at r = 0 is the "
      "jump a (dj(0) = [0,a]); the response is linear between breakpoints "
      "and constant after the last one.");
    prm.leave_subsection();
  }

  PiecewiseLinearLaw::PiecewiseLinearLaw(ParameterHandler &prm)
    : PiecewiseLinearLaw([&prm]() {
      prm.enter_subsection(law_name);
      const std::string text = prm.get("subgradient breakpoints");
      prm.leave_subsection();
      return parse_breakpoints(text);
    }())
  {}

  PiecewiseLinearLaw::PiecewiseLinearLaw(
    const std::vector<std::pair<double, double>> &breakpoints)
    : points(breakpoints)
  {
    require(!points.empty(),
            "normal law 'piecewise linear': the list of subgradient "
            "breakpoints is empty.");
    require(points.front().first == 0.,
            "normal law 'piecewise linear': the first breakpoint must be at "
            "r = 0 (it gives the jump a of dj(0) = [0,a]), not at r = " +
              std::to_string(points.front().first) + ".");
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        require(points[k].second >= 0,
                "normal law 'piecewise linear': the response p = " +
                  std::to_string(points[k].second) +
                  " at r = " + std::to_string(points[k].first) +
                  " is negative; the foundation can only resist penetration.");
        if (k > 0)
          require(points[k].first > points[k - 1].first,
                  "normal law 'piecewise linear': the breakpoints must have "
                  "strictly increasing r, but r = " +
                    std::to_string(points[k].first) + " follows r = " +
                    std::to_string(points[k - 1].first) + ".");
      }
  }

  double
  PiecewiseLinearLaw::response(const double r) const
  {
    if (r >= points.back().first)
      return points.back().second;
    const auto upper =
      std::upper_bound(points.begin(),
                       points.end(),
                       r,
                       [](const double x, const std::pair<double, double> &p) {
                         return x < p.first;
                       });
    const auto   lower = upper - 1;
    const double theta = (r - lower->first) / (upper->first - lower->first);
    return (1 - theta) * lower->second + theta * upper->second;
  }

  double
  PiecewiseLinearLaw::remainder(const double r) const
  {
    return r > 0 ? response(r) - jump() : 0.;
  }

  double
  PiecewiseLinearLaw::remainder_derivative(const double r) const
  {
    if (r <= 0 || r >= points.back().first)
      return 0.;
    const auto upper =
      std::upper_bound(points.begin(),
                       points.end(),
                       r,
                       [](const double x, const std::pair<double, double> &p) {
                         return x < p.first;
                       });
    const auto lower = upper - 1;
    return (upper->second - lower->second) / (upper->first - lower->first);
  }

  double
  PiecewiseLinearLaw::remainder_primitive(const double r) const
  {
    if (r <= 0)
      return 0.;
    // exact integral of the piecewise-linear response minus a
    double integral = 0;
    for (unsigned int k = 0; k + 1 < points.size() && points[k].first < r; ++k)
      {
        const double r1 = std::min(r, points[k + 1].first);
        integral +=
          0.5 * (points[k].second + response(r1)) * (r1 - points[k].first);
      }
    if (r > points.back().first)
      integral += points.back().second * (r - points.back().first);
    return integral - jump() * r;
  }

  double
  PiecewiseLinearLaw::relaxed_monotonicity_constant() const
  {
    double alpha = 0;
    for (unsigned int k = 0; k + 1 < points.size(); ++k)
      alpha = std::max(alpha,
                       -(points[k + 1].second - points[k].second) /
                         (points[k + 1].first - points[k].first));
    return alpha;
  }
} // namespace hemicontact
