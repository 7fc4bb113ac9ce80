#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/mesh/discretization.h>

#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The FEValues of the heat step's terms (doc/theory.md 13.2): theta's
   * values and gradients on a cell (the Gauss rule of degree 2), the
   * divergence of w on the same cell of the displacement's DoFHandler,
   * and theta's values on a face with its normal.
   */
  template <int dim>
  struct HeatStepValues
  {
    HeatStepValues(const Discretization<dim> &discretization,
                   const FiniteElement<dim>  &theta_fe)
      : quadrature(discretization.cell_quadrature(2))
      , face_quadrature(discretization.face_quadrature(2))
      , theta(*discretization.mapping,
              theta_fe,
              quadrature,
              update_values | update_gradients | update_quadrature_points |
                update_JxW_values)
      , displacement(*discretization.mapping,
                     *discretization.fe,
                     quadrature,
                     update_gradients)
      , face(*discretization.mapping,
             theta_fe,
             face_quadrature,
             update_values | update_quadrature_points | update_normal_vectors |
               update_JxW_values)
      , div_w(quadrature.size())
    {}

    /** theta's values on @p theta_cell, and div w there into div_w from
     *  @p w (ghosted) on the same cell of @p dof_handler. */
    void
    reinit(const typename DoFHandler<dim>::active_cell_iterator &theta_cell,
           const DoFHandler<dim>                                &dof_handler,
           const TrilinosWrappers::MPI::Vector                  &w)
    {
      theta.reinit(theta_cell);
      displacement.reinit(typename DoFHandler<dim>::active_cell_iterator(
        &theta_cell->get_triangulation(),
        theta_cell->level(),
        theta_cell->index(),
        &dof_handler));
      displacement[FEValuesExtractors::Vector(0)].get_function_divergences(
        w, div_w);
    }

    const Quadrature<dim>     quadrature;
    const Quadrature<dim - 1> face_quadrature;
    FEValues<dim>             theta, displacement;
    FEFaceValues<dim>         face;
    /** div w at the cell's quadrature points after reinit() */
    std::vector<double> div_w;
  };
} // namespace hemicontact
