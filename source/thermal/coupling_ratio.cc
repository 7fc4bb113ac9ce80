#include <deal.II/base/mpi.h>

#include <hemicontact/thermal/heat_model.h>

#include <algorithm>

namespace hemicontact
{
  template <int dim>
  double
  HeatModel<dim>::largest_coupling_ratio() const
  {
    // the coefficients cached per quadrature point (cache_coefficients():
    // c_theta > 0 checked there); cells of other ranks are zero here
    double ratio = 0;
    for (std::size_t i = 0; i < coefficients.c_e.size(); ++i)
      if (coefficients.c_theta[i] > 0)
        ratio = std::max(ratio,
                         coefficients.c_e[i] * coefficients.c_e[i] /
                           coefficients.c_theta[i]);
    return Utilities::MPI::max(ratio, mpi_communicator);
  }

  template double
  HeatModel<2>::largest_coupling_ratio() const;
  template double
  HeatModel<3>::largest_coupling_ratio() const;
} // namespace hemicontact
