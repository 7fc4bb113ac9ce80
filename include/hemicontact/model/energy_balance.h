#pragma once

#include <hemicontact/model/energy_term.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  /**
   * The discrete energy identity that the scheme satisfies exactly, here
   * for the dynamic left point (every velocity class and rule:
   * doc/theory.md, section 9.3, with the terms of
   * StepScheme::step_energy(); the static class books the identity of
   * section 9.4 per load value in the same terms).
   * Testing step n of Problem 4.4 with w_n and using u_{n+1} = u_n + k w_n:
   *
   *   E_n - E_{n-1} + k a_A(w_n,w_n) + k sum_i m_i (xi_nu w_nu + F_b|w_tau|)
   *     + [ rho/2 |w_n - w_{n-1}|^2 - k^2/2 a_B(w_n,w_n) ] = k <f_n, w_n>,
   *
   * with E_n = rho/2 |w_n|^2 + 1/2 a_B(u_{n+1}, u_{n+1}). The bracket is the
   * scheme's own numerical dissipation: backward Euler removes
   * rho/2 |w_n - w_{n-1}|^2, the explicit (left-point) elastic term adds
   * k^2/2 a_B(w_n, w_n). The defect of this identity, summed over the
   * steps, is zero up to the solver tolerance.
   *
   * A mesh adaptation moves w_n and u_n to the new mesh by interpolation,
   * and a change of the time step (halving after a Newton failure) changes
   * u_{n+1} = u_n + k w_n; both change E_n by themselves. Those changes are
   * summed in transfer_change and taken out of the defect, so the identity
   * still checks the steps.
   */
  struct EnergyBalance
  {
    double kinetic               = 0; ///< rho/2 |w_n|^2
    double elastic               = 0; ///< 1/2 a_B(u_{n+1}, u_{n+1})
    double initial_energy        = 0; ///< E_0
    double viscous_dissipation   = 0; ///< sum k a_A(w_n, w_n)
    double friction_dissipation  = 0; ///< sum k m_i F_b |w_tau|
    double damping_dissipation   = 0; ///< sum k m_i xi_nu w_nu
    double external_work         = 0; ///< sum k <f_n, w_n>
    double numerical_dissipation = 0; ///< sum of the bracket above
    double transfer_change =
      0; ///< sum of E after - E before a mesh or k change
    /** The step energy J_n at the step's solution (doc/theory.md 9). */
    double minimised_energy = 0;
    /**
     * The work of the memory stress (doc/theory.md, section 11): sum k
     * (M_n, eps(w_n)) in the velocity classes, 1/2 (M_n, eps(u_n)) at a
     * load value of the static class; 0 without memory.
     */
    double memory_work = 0;
    /**
     * The terms of the coupled fields (doc/theory.md 13.4), in the order
     * and with the roles of coupled_energy_terms(): zero for a field the
     * run does not enable. The numerical dissipation of a field's step is
     * in numerical_dissipation.
     */
    std::vector<double> coupled =
      std::vector<double>(coupled_energy_terms().size(), 0.);

    /** The coupled term named @p name (coupled_energy_terms()). */
    double
    coupled_term(const std::string &name) const
    {
      const std::vector<EnergyTermSpec> &terms = coupled_energy_terms();
      for (std::size_t i = 0; i < terms.size(); ++i)
        if (terms[i].name == name)
          return coupled[i];
      return 0;
    }

    /**
     * The coupled terms of role @p role summed in their order, each with
     * its sign @p sign(role) (so that the sums are the numbers the balance
     * had before a field was added: 0 + x is x).
     */
    template <class Term>
    double
    coupled_sum(const EnergyRole role, Term term) const
    {
      const std::vector<EnergyTermSpec> &terms = coupled_energy_terms();
      double                             sum   = 0;
      for (std::size_t i = 0; i < terms.size() && i < coupled.size(); ++i)
        if (terms[i].role == role)
          sum = term(sum, coupled[i]);
      return sum;
    }

    /** The stored energies of the coupled fields. */
    double
    coupled_stored() const
    {
      return coupled_sum(EnergyRole::stored,
                         [](double s, double v) { return s + v; });
    }

    double
    total_energy() const
    {
      double                             e     = kinetic + elastic;
      const std::vector<EnergyTermSpec> &terms = coupled_energy_terms();
      for (std::size_t i = 0; i < terms.size() && i < coupled.size(); ++i)
        if (terms[i].role == EnergyRole::stored)
          e += coupled[i];
      return e;
    }

    /** E_n - E_0 + dissipations - work: zero up to solver tolerance. */
    double
    defect() const
    {
      const double d = total_energy() - initial_energy - transfer_change +
                       viscous_dissipation + friction_dissipation +
                       damping_dissipation + numerical_dissipation -
                       external_work;
      // the coupled fields' dissipation - supply - coupling, in their order
      double                             field = 0;
      const std::vector<EnergyTermSpec> &terms = coupled_energy_terms();
      for (std::size_t i = 0; i < terms.size() && i < coupled.size(); ++i)
        if (terms[i].role == EnergyRole::dissipated)
          field += coupled[i];
        else if (terms[i].role == EnergyRole::supplied ||
                 terms[i].role == EnergyRole::coupling)
          field -= coupled[i];
      // the terms a run without them has are added only where they are,
      // so that such a run's defect is the same number
      return (memory_work == 0. ? d : d + memory_work) +
             (field == 0. ? 0. : field);
    }

    /**
     * The energy put into the body: data_energy() (+ |memory work|, which
     * a kernel may turn into energy put in). A stable run holds at most about
     * this much (the dissipations of the laws and the viscosity are
     * non-negative), so it is the scale the defect is measured against: an
     * energy that explodes cannot hide its own round-off in it.
     */
    double
    supplied_energy() const
    {
      return data_energy() + std::abs(memory_work);
    }

    /** The defect relative to the energy supplied. */
    double
    relative_defect() const
    {
      return std::abs(defect()) / std::max(supplied_energy(), 1e-300);
    }

    /** E_n relative to the energy supplied (about 1 or below when stable). */
    double
    growth() const
    {
      return total_energy() / std::max(supplied_energy(), 1e-300);
    }

    /**
     * The energy the data put into the body: |E_0| + |sum k <f_n, w_n>| +
     * |transfer changes| (+ the |supplied| terms of the coupled fields),
     * without the memory's work, which an unstable memory rule inflates
     * with the energy it creates (doc/theory.md 11.13). A field's
     * converted terms (its load's work, in external_work) and its coupling
     * terms move energy between the body's motion and the field: neither
     * is put in (doc/theory.md 13.4), so that a coupling that creates
     * energy cannot count its own growth as supplied.
     */
    double
    data_energy() const
    {
      const double converted =
        coupled_sum(EnergyRole::converted,
                    [](double s, double v) { return s + v; });
      const double supplied =
        coupled_sum(EnergyRole::supplied,
                    [](double s, double v) { return s + std::abs(v); });
      return std::abs(initial_energy) + std::abs(external_work - converted) +
             std::abs(transfer_change) + supplied;
    }

    /** E_n relative to data_energy(). */
    double
    data_growth() const
    {
      return total_energy() / std::max(data_energy(), 1e-300);
    }
  };

  /** A term of an EnergyBalance that a checkpoint stores, by name: a
   *  mechanical member or a coupled field's term. */
  struct SavedEnergyTerm
  {
    std::string name;
    /** The mechanical term; nullptr for EnergyBalance::coupled[index]. */
    double EnergyBalance::*member = nullptr;
    std::size_t            index  = 0;

    double &
    in(EnergyBalance &e) const
    {
      return member != nullptr ? e.*member : e.coupled[index];
    }
    double
    in(const EnergyBalance &e) const
    {
      return member != nullptr ? e.*member : e.coupled[index];
    }
  };

  /**
   * The terms of an EnergyBalance that a checkpoint stores, by name: the
   * one list that writing and reading a checkpoint loop over (J_n is the
   * step's own and is not stored): the mechanical terms, then
   * coupled_energy_terms(). A term is added at the end: a checkpoint that
   * holds the list without the terms added after it resumes with their
   * sums from zero.
   */
  inline const std::vector<SavedEnergyTerm> &
  saved_energy_terms()
  {
    static const std::vector<SavedEnergyTerm> terms = []() {
      using E = EnergyBalance;
      std::vector<SavedEnergyTerm> list{
        {"kinetic", &E::kinetic},
        {"elastic", &E::elastic},
        {"initial_energy", &E::initial_energy},
        {"viscous_dissipation", &E::viscous_dissipation},
        {"friction_dissipation", &E::friction_dissipation},
        {"damping_dissipation", &E::damping_dissipation},
        {"external_work", &E::external_work},
        {"numerical_dissipation", &E::numerical_dissipation},
        {"transfer_change", &E::transfer_change},
        {"memory_work", &E::memory_work}};
      const std::vector<EnergyTermSpec> &coupled = coupled_energy_terms();
      for (std::size_t i = 0; i < coupled.size(); ++i)
        list.push_back({coupled[i].name, nullptr, i});
      return list;
    }();
    return terms;
  }
} // namespace hemicontact
