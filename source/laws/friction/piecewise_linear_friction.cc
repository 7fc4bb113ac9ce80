#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/friction/piecewise_linear_friction.h>

#include <algorithm>
#include <cmath>

namespace hemicontact
{
  namespace
  {
    const std::string law_prefix = "friction law 'piecewise linear': ";

    std::vector<std::pair<double, double>>
    parse_breakpoints(const std::string &text)
    {
      std::vector<std::pair<double, double>> result;
      for (const std::string &item : Utilities::split_string_list(text, ','))
        {
          const std::vector<std::string> sg =
            Utilities::split_string_list(item, ':');
          require(sg.size() == 2,
                  law_prefix + "the breakpoint '" + item +
                    "' is not of the form s:g (expected a list such as "
                    "'0:1, 0.05:0.6, 0.5:0.8').");
          try
            {
              result.emplace_back(Utilities::string_to_double(sg[0]),
                                  Utilities::string_to_double(sg[1]));
            }
          catch (...)
            {
              throw InputError(law_prefix + "the breakpoint '" + item +
                               "' does not hold two numbers s:g.");
            }
          require(std::isfinite(result.back().first) &&
                    std::isfinite(result.back().second),
                  law_prefix + "the breakpoint '" + item +
                    "' of 'response breakpoints' holds a value that is not "
                    "a finite number.");
        }
      return result;
    }
  } // namespace

  void
  PiecewiseLinearFrictionLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    prm.declare_entry(
      "response breakpoints",
      "0:1, 0.05:0.6, 0.5:0.8",
      Patterns::Anything(),
      "Breakpoints s:g of the friction force F(s) = g F_b at slip speed s, "
      "comma separated, s strictly increasing, g >= 0. g = 1 at s = 0 (the "
      "static bound; 0:1 is added if the list does not start at s = 0). "
      "Linear between breakpoints, constant after the last one.");
    prm.leave_subsection();
  }

  PiecewiseLinearFrictionLaw::PiecewiseLinearFrictionLaw(ParameterHandler &prm)
    : PiecewiseLinearFrictionLaw([&prm]() {
      prm.enter_subsection(law_name);
      const std::string text = prm.get("response breakpoints");
      prm.leave_subsection();
      return parse_breakpoints(text);
    }())
  {}

  PiecewiseLinearFrictionLaw::PiecewiseLinearFrictionLaw(
    const std::vector<std::pair<double, double>> &breakpoints)
    : points(breakpoints)
  {
    require(!points.empty(),
            law_prefix + "the list of response breakpoints is empty.");
    if (points.front().first != 0.)
      points.insert(points.begin(), {0., 1.});
    require(points.front().second == 1.,
            law_prefix +
              "the ratio at s = 0 must be 1 (the friction bound "
              "itself), not " +
              std::to_string(points.front().second) + ".");
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        require(points[k].first >= 0,
                law_prefix + "the slip speed s = " +
                  std::to_string(points[k].first) + " is negative.");
        require(points[k].second >= 0,
                law_prefix +
                  "the ratio g = " + std::to_string(points[k].second) +
                  " at s = " + std::to_string(points[k].first) +
                  " is negative; friction opposes slip, so g >= 0.");
        if (k > 0)
          require(points[k].first > points[k - 1].first,
                  law_prefix +
                    "the breakpoints must have strictly "
                    "increasing s, but s = " +
                    std::to_string(points[k].first) + " follows s = " +
                    std::to_string(points[k - 1].first) + ".");
      }
  }

  double
  PiecewiseLinearFrictionLaw::ratio(const double s) const
  {
    if (s >= points.back().first)
      return points.back().second;
    const auto upper =
      std::upper_bound(points.begin(),
                       points.end(),
                       s,
                       [](const double x, const std::pair<double, double> &p) {
                         return x < p.first;
                       });
    const auto   lower = upper - 1;
    const double theta = (s - lower->first) / (upper->first - lower->first);
    return (1 - theta) * lower->second + theta * upper->second;
  }

  double
  PiecewiseLinearFrictionLaw::remainder(const double bound,
                                        const double s) const
  {
    return s > 0 ? bound * (ratio(s) - 1.) : 0.;
  }

  double
  PiecewiseLinearFrictionLaw::remainder_derivative(const double bound,
                                                   const double s) const
  {
    if (s >= points.back().first)
      return 0.;
    const auto upper =
      std::upper_bound(points.begin(),
                       points.end(),
                       std::max(s, 0.),
                       [](const double x, const std::pair<double, double> &p) {
                         return x < p.first;
                       });
    const auto lower = upper - 1;
    return bound * (upper->second - lower->second) /
           (upper->first - lower->first);
  }

  double
  PiecewiseLinearFrictionLaw::remainder_primitive(const double bound,
                                                  const double s) const
  {
    if (s <= 0)
      return 0.;
    // exact integral of g - 1, trapezoids up to s
    double integral = 0;
    for (unsigned int k = 0; k + 1 < points.size() && points[k].first < s; ++k)
      {
        const double s1 = std::min(s, points[k + 1].first);
        integral +=
          0.5 * (points[k].second + ratio(s1)) * (s1 - points[k].first);
      }
    if (s > points.back().first)
      integral += points.back().second * (s - points.back().first);
    return bound * (integral - s);
  }

  double
  PiecewiseLinearFrictionLaw::relaxed_monotonicity_constant(
    const double bound) const
  {
    double steepest = 0;
    for (unsigned int k = 0; k + 1 < points.size(); ++k)
      steepest = std::max(steepest,
                          -(points[k + 1].second - points[k].second) /
                            (points[k + 1].first - points[k].first));
    return bound * steepest;
  }
} // namespace hemicontact
