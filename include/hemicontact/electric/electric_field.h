#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/coupling/coupled_field.h>
#include <hemicontact/expressions/expression.h>
#include <hemicontact/input/parameters.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  /**
   * The electric potential phi of a piezoelectric body (doc/theory.md,
   * section 14) as a coupled field: sigma gains E^T grad phi, and the
   * electric step
   *
   *   (beta grad phi_n, grad zeta) + sum_i m_i p_e(u_nu,i) phi_n,i zeta_i
   *   = (E eps(u_n), grad zeta) + sum_i m_i p_e phi_F,i zeta_i
   *     - (q_b, zeta)_{Gamma_b} + (q_0, zeta),
   *
   * phi = phi_D on the electrodes, solved by CG with AMG before the
   * mechanical step, whose right-hand side gains -(grad phi_n, E eps(v)).
   * With the left-point rule u_n is known before the step (exact); with the
   * implicit rule and in the static class the two steps alternate to the
   * monolithic answer (couple_step()).
   */
  template <int dim>
  class ElectricField : public CoupledField<dim>
  {
  public:
    ElectricField(const PiezoelectricParameters &parameters,
                  const std::string             &constants,
                  const bool                     static_class,
                  const bool                     left_point,
                  MPI_Comm                       comm);

    /** The name of phi in the state's list of fields. */
    static constexpr const char *field_name = "electric_potential";

    /** Its energy terms (doc/theory.md 14.3), in the checkpoint's order. */
    static const std::vector<EnergyTermSpec> &
    terms();

    FieldDefinition<dim>
    definition(const bool simplex) const override;
    std::string
    subsection() const override;
    std::string
    symbol() const override;
    typename CoupledField<dim>::Order
    order() const override;
    FieldCoupling
    coupling() const override;
    std::string
    step_name() const override;
    void
    reinit(const FieldSpace<dim>     &space,
           const MechanicalView<dim> &view) override;
    void
    start(const MechanicalView<dim>     &view,
          LinearSolver                  &solver,
          TrilinosWrappers::MPI::Vector &value,
          const bool                     resumed) override;
    void
    add_mechanical_load(const double                   t,
                        const MechanicalView<dim>     &view,
                        TrilinosWrappers::MPI::Vector &value,
                        TrilinosWrappers::MPI::Vector &load) override;
    FieldStepEnergy
    step(const double                   t,
         const double                   k,
         const MechanicalView<dim>     &view,
         LinearSolver                  &solver,
         TrilinosWrappers::MPI::Vector &value) override;
    void
    complete_step(const double                         t,
                  const double                         k,
                  const MechanicalView<dim>           &view,
                  const TrilinosWrappers::MPI::Vector &before,
                  const TrilinosWrappers::MPI::Vector &value,
                  FieldStepEnergy                     &terms) override;
    const std::vector<EnergyTermSpec> &
    energy_terms() const override;
    std::vector<double>
    stored_energies(const MechanicalView<dim>           &view,
                    const TrilinosWrappers::MPI::Vector &value) const override;
    std::vector<std::pair<std::string, Vector<float>>>
    cell_output(const TrilinosWrappers::MPI::Vector &value) const override;
    std::vector<std::string>
    contact_columns() const override;
    std::vector<std::vector<double>>
    contact_values(const MechanicalView<dim>           &view,
                   const TrilinosWrappers::MPI::Vector &value) const override;

    /** CG iterations of the last electric step. */
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

  private:
    /**
     * What the energy identity needs of one electric solve at time t
     * (doc/theory.md 14.3): the nodal conductances c_i = m_i p_e,i at the
     * free Gamma_3 dofs, the data functional G(zeta) = (q_0, zeta) -
     * (q_b, zeta) + sum_i c_i phi_F,i zeta_i plus the electrodes' charge
     * (the residual of their rows), and the solution phi.
     */
    struct Solve
    {
      TrilinosWrappers::MPI::Vector conductance, data, phi;
    };

    /** phi at @p t from the displacement @p u (owned entries) of @p view
     *  into @p value; its Solve kept for the energy (by time). */
    void
    solve(const double                         t,
          const MechanicalView<dim>           &view,
          const TrilinosWrappers::MPI::Vector &u,
          LinearSolver                        &solver,
          TrilinosWrappers::MPI::Vector       &value);

    /** The constraints at @p t: hanging nodes and phi_D on the electrodes. */
    void
    make_constraints(const double t);

    /** p_e at the contact node @p i of @p view at @p t with u from @p u
     *  (ghosted), checked finite and >= 0. */
    double
    conductance_at(const MechanicalView<dim>           &view,
                   const unsigned int                   i,
                   const TrilinosWrappers::MPI::Vector &u,
                   const double                         t) const;

    /** (grad phi, E eps(u)) and 1/2 (beta grad phi, grad phi) of @p phi and
     *  @p u (owned entries). */
    std::pair<double, double>
    cross_and_field_energy(const MechanicalView<dim>           &view,
                           const TrilinosWrappers::MPI::Vector &phi,
                           const TrilinosWrappers::MPI::Vector &u) const;

    PiezoelectricParameters        parameters;
    bool                           static_class, left_point;
    MPI_Comm                       mpi_communicator;
    Tensor<3, dim>                 piezo;
    Tensor<2, dim>                 beta;
    std::shared_ptr<Function<dim>> volume_charge, electrode_potential,
      surface_charge, foundation_potential;
    std::unique_ptr<Expression> conductance;

    const FieldSpace<dim>            *space          = nullptr;
    const Discretization<dim>        *discretization = nullptr;
    AffineConstraints<double>         hanging_constraints, constraints;
    TrilinosWrappers::SparseMatrix    matrix;
    TrilinosWrappers::PreconditionAMG amg;
    TrilinosWrappers::MPI::Vector     rhs;
    /** The phi dof at each contact node (in the order of the nodes). */
    std::vector<types::global_dof_index> node_dofs;
    /** The load -(grad phi, E eps(v)) last added (displacement space). */
    TrilinosWrappers::MPI::Vector stress_load;
    /** The solves of the last steps, by time. */
    std::map<double, Solve> solves;
    unsigned int            iterations = 0;
  };
} // namespace hemicontact
