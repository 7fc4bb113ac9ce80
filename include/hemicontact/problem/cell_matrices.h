#pragma once

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <hemicontact/model/kelvin_voigt.h>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The cell matrices of @p material on the cell @p fe_values is at: the
   * mass rho M, the viscous A and the elastic B (assembly.cc).
   */
  template <int dim>
  void
  cell_matrices(const KelvinVoigtMaterial<dim> &material,
                const FEValues<dim>            &fe_values,
                FullMatrix<double>             &mass,
                FullMatrix<double>             &viscous,
                FullMatrix<double>             &elastic);
} // namespace hemicontact
