#include <hemicontact/model/step_scheme.h>

#include <sstream>
#include <utility>
#include <vector>

namespace hemicontact
{
  namespace
  {
    /** "a", "a and b", "a, b and c". */
    std::string
    joined(const std::vector<std::string> &items)
    {
      std::string text;
      for (std::size_t i = 0; i < items.size(); ++i)
        text += (i == 0                ? "" :
                 i + 1 == items.size() ? " and " :
                                         ", ") +
                items[i];
      return text;
    }

    /** The note of StepScheme::ignored_parameters() for the static class. */
    std::string
    ignored_by_static_class(const Parameters &parameters)
    {
      // the defaults: density 1, viscosity mu = lambda = 1, initial values
      // 0, the left-point rule
      std::vector<std::string>  ignored;
      const MaterialParameters &m = parameters.material;
      if (m.density != 1.)
        {
          std::ostringstream value;
          value << m.density;
          ignored.push_back("'material/density' = " + value.str());
        }
      if (m.viscosity.mu != 1. || m.viscosity.lambda != 1.)
        ignored.push_back("'material/viscosity'");
      if (!parameters.manufactured.enabled)
        for (const auto &[name, value] :
             {std::make_pair("initial displacement",
                             parameters.data.initial_displacement),
              std::make_pair("initial velocity",
                             parameters.data.initial_velocity)})
          if (value != "0")
            ignored.push_back(std::string("'data/") + name + "' = '" + value +
                              "'");
      if (parameters.problem.time_scheme != TimeScheme::left_point)
        ignored.push_back("'problem/time scheme'");
      // theta is data: the heat equation's and the contact heat law's
      // entries (their defaults 0)
      std::vector<std::string>     thermal;
      const TemperatureParameters &temperature = parameters.temperature;
      if (temperature.enabled)
        {
          for (const auto &[name, value] :
               {std::make_pair("exchange coefficient",
                               temperature.exchange_coefficient),
                std::make_pair("foundation temperature",
                               temperature.foundation_temperature),
                std::make_pair("initial temperature",
                               temperature.initial_temperature),
                std::make_pair("heat source", temperature.heat_source),
                std::make_pair("prescribed temperature",
                               temperature.prescribed_temperature),
                std::make_pair("heat flux", temperature.heat_flux)})
            if (value != "0")
              thermal.push_back(std::string("'temperature/") + name + "' = '" +
                                value + "'");
          if (temperature.frictional_heat_fraction != 0.)
            {
              std::ostringstream value;
              value << temperature.frictional_heat_fraction;
              thermal.push_back("'temperature/frictional heat fraction' = " +
                                value.str());
            }
        }
      std::string note;
      if (!ignored.empty())
        note = "the static class does not use " + joined(ignored) +
               " (no inertia, no viscosity, no initial state: one problem "
               "per load value t_n = n k, doc/theory.md section 9.2).";
      if (!thermal.empty())
        note += std::string(note.empty() ? "the" : " The") +
                " static class does not use " + joined(thermal) +
                " (theta is 'given temperature': no heat equation, no "
                "contact heat law, doc/theory.md section 13.2).";
      return note;
    }
  } // namespace

  StepScheme::StepScheme(const ProblemClass problem_class,
                         const TimeScheme   time_scheme)
    : the_class(problem_class)
    , the_scheme(time_scheme)
  {}

  StepScheme::StepScheme(const ProblemParameters &parameters)
    : StepScheme(parameters.problem_class, parameters.time_scheme)
  {}

  MaterialParameters
  StepScheme::class_material(const MaterialParameters &material) const
  {
    MaterialParameters m = material;
    if (is_static())
      m.viscosity = LamePair{0., 0.};
    return m;
  }

  std::string
  StepScheme::name() const
  {
    if (is_static())
      return "static";
    return std::string(has_inertia() ? "dynamic" : "quasistatic") +
           (the_scheme == TimeScheme::left_point ? ", left point" :
                                                   ", implicit");
  }

  StepMatrixCoefficients
  StepScheme::step_matrix(const double k) const
  {
    // doc/theory.md, section 9 (the table)
    StepMatrixCoefficients c;
    if (is_static())
      return StepMatrixCoefficients{0., 0., 1.};
    c.mass    = has_inertia() ? 1. / k : 0.;
    c.viscous = 1.;
    c.elastic = the_scheme == TimeScheme::implicit ? k : 0.;
    return c;
  }

  StepMatrixCoefficients
  StepScheme::initial_matrix() const
  {
    // doc/theory.md, section 9.2: K = A, b = F_0 - B u_0
    return StepMatrixCoefficients{0., 1., 0.};
  }

  std::string
  StepScheme::step_matrix_name() const
  {
    if (is_static())
      return "B";
    return std::string(has_inertia() ? "rho/k M + A" : "A") +
           (the_scheme == TimeScheme::implicit ? " + k B" : "");
  }

  StepScheme::StepEnergy
  StepScheme::step_energy(const double k,
                          const double w_A_w,
                          const double dw_M_dw,
                          const double w_B_w) const
  {
    // doc/theory.md, section 9.3
    StepEnergy e;
    e.viscous            = k * w_A_w;
    const double kinetic = has_inertia() ? 0.5 * dw_M_dw : 0.;
    e.numerical          = the_scheme == TimeScheme::implicit ?
                             kinetic + 0.5 * k * k * w_B_w :
                             kinetic - 0.5 * k * k * w_B_w;
    return e;
  }

  std::string
  StepScheme::stability_condition() const
  {
    if (!has_time_step_limit())
      return "none (the implicit rule is stable for every time step)";
    if (has_inertia())
      return "the largest generalized eigenvalue of the elastic operator B "
             "against A + 2M/k must not exceed 2/k; doc/theory.md, section 8";
    return "the largest generalized eigenvalue of the elastic operator B "
           "against the viscous operator A must not exceed 2/k, i.e. "
           "k B <= 2 A; doc/theory.md, section 9.6";
  }

  std::string
  StepScheme::convexity_remedy(const double k) const
  {
    std::ostringstream s;
    if (has_inertia())
      s << "reduce the time step k = " << k;
    else if (is_static())
      s << "in the static class the condition is one on the elastic "
           "moduli, the geometry and the laws alone (K = B, doc/theory.md "
           "section 9.5): use stiffer elastic moduli";
    else
      s << "in the quasistatic class the condition does not improve with the "
           "time step (K = "
        << step_matrix_name()
        << ", doc/theory.md section 9.5): use a larger viscosity";
    return s.str();
  }

  std::string
  StepScheme::ignored_parameters(const Parameters &parameters) const
  {
    if (has_inertia())
      return "";
    if (is_static())
      return ignored_by_static_class(parameters);
    // the defaults of 'material/density' and 'data/initial velocity'
    std::string ignored;
    if (parameters.material.density != 1.)
      {
        std::ostringstream value;
        value << parameters.material.density;
        ignored += "'material/density' = " + value.str();
      }
    if (parameters.data.initial_velocity != "0" &&
        !parameters.manufactured.enabled)
      ignored += std::string(ignored.empty() ? "" : " and ") +
                 "'data/initial velocity' = '" +
                 parameters.data.initial_velocity + "'";
    if (ignored.empty())
      return "";
    return "the quasistatic class does not use " + ignored +
           " (no inertia; the initial velocity is the step problem at t = 0, "
           "doc/theory.md section 9.2).";
  }
} // namespace hemicontact
