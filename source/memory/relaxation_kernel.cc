#include <hemicontact/base/exceptions.h>
#include <hemicontact/memory/relaxation_kernel.h>
#include <hemicontact/model/problem_data.h>

#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

namespace hemicontact
{
  RelaxationKernel::RelaxationKernel(const RelaxationParameters &parameters,
                                     const std::string          &constants)
    : kernel(parameters.kernel)
    , mu_text(parameters.mu)
    , lambda_text(parameters.lambda)
  {
    if (kernel == RelaxationKernelType::prony)
      {
        mu_amplitudes     = parameters.mu_amplitudes;
        lambda_amplitudes = parameters.lambda_amplitudes;
        relaxation_times  = parameters.relaxation_times;
      }
    else if (kernel == RelaxationKernelType::expression)
      {
        const std::map<std::string, double> c = parse_constants(constants);
        mu     = std::make_shared<Expression>(mu_text,
                                          std::vector<std::string>{"t"},
                                          c,
                                          "relaxation/mu");
        lambda = std::make_shared<Expression>(lambda_text,
                                              std::vector<std::string>{"t"},
                                              c,
                                              "relaxation/lambda");
      }
  }

  std::pair<double, double>
  RelaxationKernel::operator()(const double t) const
  {
    if (kernel == RelaxationKernelType::prony)
      {
        double mu_R = 0, lambda_R = 0;
        for (unsigned int m = 0; m < relaxation_times.size(); ++m)
          {
            const double decay = std::exp(-t / relaxation_times[m]);
            mu_R += mu_amplitudes[m] * decay;
            lambda_R += lambda_amplitudes[m] * decay;
          }
        return {mu_R, lambda_R};
      }
    if (kernel == RelaxationKernelType::none)
      return {0., 0.};
    const std::vector<double> at{t};
    const double              mu_R     = mu->evaluate(at);
    const double              lambda_R = lambda->evaluate(at);
    for (const auto &[name, text, value] :
         {std::make_tuple("mu", &mu_text, mu_R),
          std::make_tuple("lambda", &lambda_text, lambda_R)})
      if (!std::isfinite(value))
        {
          std::ostringstream message;
          message << "relaxation: '" << name << "' = '" << *text
                  << "' is not a finite number (" << value << ") at t = " << t
                  << "; the memory rule evaluates the kernel at every "
                     "t_n - t_j, the multiples of the time step up to the "
                     "end time (doc/theory.md, section 11).";
          throw InputError(message.str());
        }
    return {mu_R, lambda_R};
  }

  void
  RelaxationKernel::require_finite(const double       k,
                                   const unsigned int n_steps) const
  {
    if (kernel != RelaxationKernelType::expression)
      return;
    for (unsigned int n = 1; n <= n_steps; ++n)
      (*this)(n * k);
  }
} // namespace hemicontact
