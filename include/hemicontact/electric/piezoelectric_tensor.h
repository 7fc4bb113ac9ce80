#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The piezoelectric tensor E_kij (doc/theory.md 14.1) of 'piezoelectric
   * constants': e_31, e_33, e_15 of a body poled along the last axis (2D:
   * E_y,xx = e_31, E_y,yy = e_33, E_x,xy = E_x,yx = e_15; 3D: e_31 on
   * E_z,xx and E_z,yy, e_33 on E_z,zz, e_15 on E_x,xz, E_y,yz and their
   * symmetric entries), or its dim^3 entries in the order k, i, j.
   */
  template <int dim>
  Tensor<3, dim>
  piezoelectric_tensor(const std::vector<double> &constants)
  {
    Tensor<3, dim> e;
    if (constants.size() == dim * dim * dim && dim * dim * dim != 3)
      {
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              e[k][i][j] = constants[(k * dim + i) * dim + j];
        return e;
      }
    const double e31 = constants[0], e33 = constants[1], e15 = constants[2];
    const unsigned int p = dim - 1; // the poling axis
    for (unsigned int i = 0; i < p; ++i)
      {
        e[p][i][i] = e31;
        e[i][i][p] = e[i][p][i] = e15;
      }
    e[p][p][p] = e33;
    return e;
  }

  /** (E eps)_k = E_kij eps_ij. */
  template <int dim>
  Tensor<1, dim>
  piezoelectric_polarization(const Tensor<3, dim>          &e,
                             const SymmetricTensor<2, dim> &eps)
  {
    Tensor<1, dim> d;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          d[k] += e[k][i][j] * eps[i][j];
    return d;
  }
} // namespace hemicontact
