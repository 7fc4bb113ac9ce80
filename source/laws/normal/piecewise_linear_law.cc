#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/normal/piecewise_linear_law.h>

#include <algorithm>
#include <cmath>
#include <limits>

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
      "with r increasing from r = 0 and p >= 0. p at r = 0 is the jump a "
      "(dj(0) = [0,a]); the response is linear between breakpoints and "
      "constant after the last one. Two breakpoints at the same r > 0 are "
      "the values left and right of a jump (e.g. '0:0, 0.1:2, 0.1:0': p = "
      "20 r up to r = 0.1, then 0).");
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
        if (k == 0)
          continue;
        const bool repeated = points[k].first == points[k - 1].first;
        require(points[k].first > points[k - 1].first ||
                  (repeated && k >= 2 && points[k - 2].first < points[k].first),
                "normal law 'piecewise linear': the breakpoints of "
                "'subgradient breakpoints' must have increasing r, with at "
                "most two at the same r > 0 (the response's values left and "
                "right of a jump), but r = " +
                  std::to_string(points[k].first) +
                  " follows r = " + std::to_string(points[k - 1].first) + ".");
        if (repeated && points[k].second > points[k - 1].second)
          upward_jumps.push_back(
            {points[k].first, points[k].second - points[k - 1].second});
      }
  }

  double
  PiecewiseLinearLaw::response(const double r) const
  {
    if (r >= points.back().first)
      return points.back().second;
    // the segment [lower, upper) of positive length that holds r: lower is
    // the last breakpoint at or left of r, so the value right of a jump
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
    return r > 0 ? response(r) - staircase(r) : 0.;
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
    // exact integral of the piecewise-linear response, segment by segment
    // (a jump is a segment of length zero), minus that of the staircase
    double integral = 0;
    for (unsigned int k = 0; k + 1 < points.size() && points[k].first < r; ++k)
      {
        const double r0 = points[k].first, r1 = points[k + 1].first;
        if (r1 == r0)
          continue;
        const double end = std::min(r, r1);
        const double value_at_end =
          points[k].second +
          (points[k + 1].second - points[k].second) * (end - r0) / (r1 - r0);
        integral += 0.5 * (points[k].second + value_at_end) * (end - r0);
      }
    if (r > points.back().first)
      integral += points.back().second * (r - points.back().first);
    double staircase_integral = jump() * r;
    for (const Kink &kink : upward_jumps)
      staircase_integral += kink.jump * std::max(r - kink.position, 0.);
    return integral - staircase_integral;
  }

  double
  PiecewiseLinearLaw::relaxed_monotonicity_constant() const
  {
    double alpha = 0;
    for (unsigned int k = 0; k + 1 < points.size(); ++k)
      {
        const double dr = points[k + 1].first - points[k].first;
        const double dp = points[k + 1].second - points[k].second;
        if (dr == 0 && dp < 0)
          return std::numeric_limits<double>::infinity();
        if (dr > 0)
          alpha = std::max(alpha, -dp / dr);
      }
    return alpha;
  }
} // namespace hemicontact
