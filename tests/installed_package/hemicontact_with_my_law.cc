// hemicontact with one more friction law, defined and registered here:
// velocity-strengthening friction F(s) = F_b (1 + c s), the remainder
// r(s) = F_b c s (monotone, so alpha_tau = 0). Everything else, the
// parameter file, the output and the exit codes, is hemicontact's.
#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/law_parameters.h>
#include <hemicontact/simulation/command_line.h>

#include <string>

class VelocityStrengtheningLaw : public hemicontact::FrictionLaw
{
public:
  static constexpr const char *law_name = "velocity strengthening";

  static void
  declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    prm.declare_entry("coefficient",
                      "1",
                      dealii::Patterns::Double(),
                      "c >= 0 in F(s) = F_b (1 + c s).");
    prm.leave_subsection();
  }

  explicit VelocityStrengtheningLaw(dealii::ParameterHandler &prm)
    : c(hemicontact::get_law_double(prm, law_name, "coefficient"))
  {
    hemicontact::require(c >= 0,
                         std::string("friction law '") + law_name +
                           "': the coefficient must not be negative.");
  }

  std::string
  name() const override
  {
    return law_name;
  }
  double
  remainder(const double bound, const double s) const override
  {
    return bound * c * s;
  }
  double
  remainder_derivative(const double bound, const double) const override
  {
    return bound * c;
  }
  double
  remainder_primitive(const double bound, const double s) const override
  {
    return bound * c * s * s / 2;
  }
  double
  relaxed_monotonicity_constant(const double) const override
  {
    return 0;
  }

private:
  double c;
};

int
main(int argc, char **argv)
{
  hemicontact::register_friction_law(
    hemicontact::friction_law_entry<VelocityStrengtheningLaw>());
  return hemicontact::run_command_line(argc, argv);
}
