#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/normal/exponential_law.h>
#include <hemicontact/laws/normal/linear_damping_law.h>
#include <hemicontact/laws/normal/no_normal_resistance.h>
#include <hemicontact/laws/normal/penalised_softening_compliance.h>
#include <hemicontact/laws/normal/piecewise_linear_law.h>
#include <hemicontact/laws/normal_law.h>

#include <algorithm>
#include <cmath>

namespace hemicontact
{
  double
  NormalLaw::potential(const double r) const
  {
    return jump() * std::max(r, 0.) + remainder_primitive(r);
  }

  std::pair<double, double>
  NormalLaw::subdifferential(const double r) const
  {
    if (r < 0)
      return {0., 0.};
    if (r == 0)
      return {0., jump()};
    const double xi = jump() + remainder(r);
    return {xi, xi};
  }

  double
  NormalLaw::subgradient(const double r) const
  {
    return r > 0 ? jump() + remainder(r) : 0.;
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
