#include <hemicontact/base/exceptions.h>
#include <hemicontact/memory/normal_memory_kernel.h>
#include <hemicontact/model/problem_data.h>

#include <cmath>
#include <sstream>

namespace hemicontact
{
  NormalMemoryKernel::NormalMemoryKernel(
    const NormalMemoryParameters &parameters,
    const std::string            &constants)
    : kernel(parameters.kernel)
    , text(parameters.b)
  {
    if (kernel == RelaxationKernelType::prony)
      {
        amplitudes       = parameters.amplitudes;
        relaxation_times = parameters.relaxation_times;
      }
    else if (kernel == RelaxationKernelType::expression)
      b = std::make_shared<Expression>(text,
                                       std::vector<std::string>{"t"},
                                       parse_constants(constants),
                                       "normal memory/b");
  }

  double
  NormalMemoryKernel::operator()(const double t) const
  {
    if (kernel == RelaxationKernelType::none)
      return 0.;
    if (kernel == RelaxationKernelType::prony)
      {
        double value = 0;
        for (unsigned int m = 0; m < relaxation_times.size(); ++m)
          value += amplitudes[m] * std::exp(-t / relaxation_times[m]);
        return value;
      }
    const double value = b->evaluate(std::vector<double>{t});
    if (!std::isfinite(value))
      {
        std::ostringstream message;
        message << "normal memory: 'b' = '" << text
                << "' is not a finite number (" << value << ") at t = " << t
                << "; the memory rule evaluates the kernel at every "
                   "t_n - t_j, the multiples of the time step up to the "
                   "end time (doc/theory.md, section 11.9).";
        throw InputError(message.str());
      }
    return value;
  }

  void
  NormalMemoryKernel::require_finite(const double       k,
                                     const unsigned int n_steps) const
  {
    if (kernel != RelaxationKernelType::expression)
      return;
    for (unsigned int n = 1; n <= n_steps; ++n)
      (*this)(n * k);
  }
} // namespace hemicontact
