/**
 * The subsection 'relaxation': the kernel of the memory term of the stress
 * (RelaxationParameters, include/hemicontact/input/parameters.h).
 */
#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/number_list.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/input/selection.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace hemicontact
{
  namespace
  {
    const SelectionNames<RelaxationKernelType> kernel_types = {
      {"none", RelaxationKernelType::none},
      {"prony", RelaxationKernelType::prony},
      {"expression", RelaxationKernelType::expression}};
  } // namespace

  void
  RelaxationParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("relaxation");
    prm.declare_entry(
      "kernel",
      "none",
      selection_pattern(kernel_types),
      "Long memory in the stress (doc/theory.md, section 11): sigma = "
      "A eps(w) + B eps(u) + int_0^t R(t - s) eps(u(s)) ds, R(t) eps = "
      "2 mu_R(t) eps + lambda_R(t) tr(eps) I, in every problem class "
      "(static: sigma = B eps(u) + int R eps(u)). The integral is the "
      "left-rectangle sum over the states before the step, M_n = sum_{j<n} "
      "k_j R(t_n - t_j) eps(u_j), on the step's right-hand side. 'none': no "
      "memory. 'prony': R(t) = sum_m exp(-t/tau_m) (2 mu_m eps + lambda_m "
      "tr(eps) I) from the three lists below, one vector of history per "
      "term, updated exactly at a fixed cost per step. 'expression': "
      "mu_R(t) and lambda_R(t) from 'mu' and 'lambda'; every past state is "
      "kept, so a step costs time and memory growing with the number of "
      "steps before it. Adapted meshes carry the history.");
    prm.declare_entry("mu amplitudes",
                      "",
                      Patterns::Anything(),
                      "'kernel = prony': the amplitudes mu_m of mu_R(t) = "
                      "sum_m mu_m exp(-t/tau_m), comma-separated finite "
                      "numbers, one per term of 'relaxation times'.");
    prm.declare_entry("lambda amplitudes",
                      "",
                      Patterns::Anything(),
                      "'kernel = prony': the amplitudes lambda_m of "
                      "lambda_R(t) = sum_m lambda_m exp(-t/tau_m), "
                      "comma-separated finite numbers, one per term of "
                      "'relaxation times'.");
    prm.declare_entry("relaxation times",
                      "",
                      Patterns::Anything(),
                      "'kernel = prony': the relaxation times tau_m > 0 of "
                      "the terms, comma-separated finite numbers.");
    prm.declare_entry("young amplitudes",
                      "",
                      Patterns::Anything(),
                      "'kernel = prony', in place of 'mu amplitudes' and "
                      "'lambda amplitudes': the amplitudes E_m of E_R(t) = "
                      "sum_m E_m exp(-t/tau_m), one per term, with the one "
                      "'poisson ratio' nu_R of the kernel: mu_m = E_m/(2 (1 + "
                      "nu_R)), lambda_m = E_m nu_R/((1 + nu_R)(1 - 2 nu_R)), "
                      "as 'material/elasticity' converts E and nu.");
    prm.declare_entry("poisson ratio",
                      "0",
                      Patterns::Double(),
                      "'kernel = prony' with 'young amplitudes': nu_R, -1 < "
                      "nu_R < 0.5.");
    prm.declare_entry("mu",
                      "0",
                      Patterns::Anything(),
                      "'kernel = expression': mu_R(t), a scalar expression "
                      "(doc/parameters.md, Expressions) in t and the "
                      "constants of 'data/constants'; it must be finite at "
                      "t = k, 2k, ..., T (the rule never evaluates it at "
                      "t = 0).");
    prm.declare_entry("lambda",
                      "0",
                      Patterns::Anything(),
                      "'kernel = expression': lambda_R(t), as 'mu'.");
    prm.leave_subsection();
  }

  void
  RelaxationParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("relaxation");
    kernel            = get_selection(prm, "kernel", kernel_types);
    mu_amplitudes     = get_number_list(prm, "relaxation", "mu amplitudes");
    lambda_amplitudes = get_number_list(prm, "relaxation", "lambda amplitudes");
    relaxation_times  = get_number_list(prm, "relaxation", "relaxation times");
    const std::vector<double> young_amplitudes =
      get_number_list(prm, "relaxation", "young amplitudes");
    const double poisson_ratio = prm.get_double("poisson ratio");
    mu                         = prm.get("mu");
    lambda                     = prm.get("lambda");
    prm.leave_subsection();

    if (kernel != RelaxationKernelType::prony)
      return;
    if (!young_amplitudes.empty())
      {
        require(mu_amplitudes.empty() && lambda_amplitudes.empty(),
                "relaxation: both 'young amplitudes' and 'mu amplitudes' or "
                "'lambda amplitudes' are set; give the terms either as E_m "
                "with 'poisson ratio' or as mu_m and lambda_m, not both.");
        std::ostringstream message;
        message << "relaxation: 'poisson ratio' = " << poisson_ratio
                << " must lie in (-1, 0.5) with 'young amplitudes'.";
        require(poisson_ratio > -1 && poisson_ratio < 0.5, message.str());
        for (const double E : young_amplitudes)
          {
            mu_amplitudes.push_back(E / (2 * (1 + poisson_ratio)));
            lambda_amplitudes.push_back(
              E * poisson_ratio /
              ((1 + poisson_ratio) * (1 - 2 * poisson_ratio)));
          }
      }
    require(!relaxation_times.empty(),
            "relaxation: 'kernel = prony' needs at least one term: set "
            "'relaxation times' (and the amplitudes of each term).");
    for (const double tau : relaxation_times)
      {
        std::ostringstream message;
        message << "relaxation: 'relaxation times' holds " << tau
                << "; every relaxation time tau_m must be positive (the "
                   "terms are exp(-t/tau_m)).";
        require(tau > 0, message.str());
      }
    for (const auto &[name, amplitudes] :
         {std::make_pair("mu amplitudes", &mu_amplitudes),
          std::make_pair("lambda amplitudes", &lambda_amplitudes)})
      require(amplitudes->size() == relaxation_times.size(),
              "relaxation: '" +
                std::string(young_amplitudes.empty() ? name :
                                                       "young amplitudes") +
                "' has " + std::to_string(amplitudes->size()) +
                " values and 'relaxation times' " +
                std::to_string(relaxation_times.size()) +
                "; give one amplitude per term (0 for none).");
  }
} // namespace hemicontact
