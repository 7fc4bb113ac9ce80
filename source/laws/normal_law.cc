#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/normal/exponential_law.h>
#include <hemicontact/laws/normal/finite_penetration_law.h>
#include <hemicontact/laws/normal/linear_damping_law.h>
#include <hemicontact/laws/normal/no_normal_resistance.h>
#include <hemicontact/laws/normal/penalised_softening_compliance.h>
#include <hemicontact/laws/normal/piecewise_linear_law.h>
#include <hemicontact/laws/normal/signorini_law.h>
#include <hemicontact/laws/normal_law.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hemicontact
{
  const std::vector<NormalLaw::Kink> &
  NormalLaw::kinks() const
  {
    static const std::vector<Kink> none;
    return none;
  }

  double
  NormalLaw::penetration_limit() const
  {
    return std::numeric_limits<double>::infinity();
  }

  double
  NormalLaw::potential(const double r) const
  {
    double kinks_part = 0;
    for (const Kink &kink : kinks())
      kinks_part += kink.jump * std::max(r - kink.position, 0.);
    return jump() * std::max(r, 0.) + kinks_part + remainder_primitive(r);
  }

  double
  NormalLaw::staircase(const double r) const
  {
    if (r <= 0)
      return 0.;
    double s = jump();
    for (const Kink &kink : kinks())
      if (kink.position <= r)
        s += kink.jump;
    return s;
  }

  std::pair<double, double>
  NormalLaw::subdifferential(const double r) const
  {
    if (r < 0)
      return {0., 0.};
    if (r == 0)
      return {0., jump()};
    const double right = subgradient(r);
    for (const Kink &kink : kinks())
      if (kink.position == r)
        return {right - kink.jump, right};
    return {right, right};
  }

  double
  NormalLaw::subgradient(const double r) const
  {
    return r > 0 ? staircase(r) + remainder(r) : 0.;
  }

  namespace
  {
    LawRegistry<NormalLaw> &
    registry()
    {
      static LawRegistry<NormalLaw> laws(
        "normal law",
        "exponential",
        "Normal damped response law -sigma_nu in dj(w_nu) on the contact "
        "boundary. Each law has its own subsection below.",
        {
          normal_law_entry<ExponentialLaw>(),
          normal_law_entry<PiecewiseLinearLaw>(),
          normal_law_entry<LinearDampingLaw>(),
          normal_law_entry<NoNormalResistance>(),
          normal_law_entry<SignoriniLaw>(),
          normal_law_entry<FinitePenetrationLaw>(),
          normal_law_entry<PenalisedSofteningCompliance>(),
        });
      return laws;
    }
  } // namespace

  const std::vector<NormalLawEntry> &
  normal_law_registry()
  {
    return registry().entries();
  }

  void
  register_normal_law(const NormalLawEntry &entry)
  {
    registry().add(entry);
  }

  void
  declare_normal_law_parameters(ParameterHandler &prm)
  {
    registry().declare(prm);
  }

  std::unique_ptr<NormalLaw>
  create_normal_law(ParameterHandler &prm)
  {
    return registry().create(prm);
  }
} // namespace hemicontact
