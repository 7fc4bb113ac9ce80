#include <hemicontact/base/exceptions.h>
#include <hemicontact/memory/memory_kernel.h>
#include <hemicontact/model/problem_data.h>

#include <cmath>
#include <map>
#include <sstream>

namespace hemicontact
{
  template <unsigned int n>
  MemoryKernel<n>::MemoryKernel(const MemoryKernelType          type,
                                const std::vector<double>      &times,
                                const std::array<Component, n> &components,
                                const std::string              &subsection,
                                const std::string              &section,
                                const std::string              &constants)
    : kernel(type)
    , components(components)
    , subsection(subsection)
    , section(section)
  {
    if (kernel == MemoryKernelType::prony)
      relaxation_times = times;
    else if (kernel == MemoryKernelType::expression)
      {
        const std::map<std::string, double> c = parse_constants(constants);
        for (unsigned int i = 0; i < n; ++i)
          expressions[i] =
            std::make_shared<Expression>(components[i].expression,
                                         std::vector<std::string>{"t"},
                                         c,
                                         subsection + "/" + components[i].name);
      }
  }

  template <unsigned int n>
  std::array<double, n>
  MemoryKernel<n>::values(const double t) const
  {
    std::array<double, n> result{};
    if (kernel == MemoryKernelType::none)
      return result;
    if (kernel == MemoryKernelType::prony)
      {
        for (unsigned int m = 0; m < relaxation_times.size(); ++m)
          {
            const double decay = std::exp(-t / relaxation_times[m]);
            for (unsigned int i = 0; i < n; ++i)
              result[i] += components[i].amplitudes[m] * decay;
          }
        return result;
      }
    const std::vector<double> at{t};
    for (unsigned int i = 0; i < n; ++i)
      result[i] = expressions[i]->evaluate(at);
    for (unsigned int i = 0; i < n; ++i)
      if (!std::isfinite(result[i]))
        {
          std::ostringstream message;
          message << subsection << ": '" << components[i].name << "' = '"
                  << components[i].expression << "' is not a finite number ("
                  << result[i] << ") at t = " << t
                  << "; the memory rule evaluates the kernel at every "
                     "t_n - t_j, the multiples of the time step up to the "
                     "end time (doc/theory.md, section "
                  << section << ").";
          throw InputError(message.str());
        }
    return result;
  }

  template <unsigned int n>
  void
  MemoryKernel<n>::require_finite(const double       k,
                                  const unsigned int n_steps) const
  {
    if (kernel != MemoryKernelType::expression)
      return;
    for (unsigned int i = 1; i <= n_steps; ++i)
      values(i * k);
  }

  template class MemoryKernel<1>;
  template class MemoryKernel<2>;
} // namespace hemicontact
