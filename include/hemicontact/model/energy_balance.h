#pragma once

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
     * The temperature's terms (doc/theory.md 13.4), zero without one: the
     * heat step tested with theta_n. thermal = 1/2 c_theta |theta_n|^2;
     * thermal_dissipation = sum k (K grad theta_n, grad theta_n) (its
     * numerical dissipation 1/2 c_theta |theta_n - theta_{n-1}|^2 is in
     * numerical_dissipation); heat_supply = sum k (heat sources, theta_n)
     * with the prescribed temperature's boundary heat; thermal_coupling_work
     * = -sum k (c_e div w_n, theta_n), which with the thermal stress's work
     * in external_work leaves the staggering's sum k (c_e (theta_{n-1} -
     * theta_n), div w_n).
     */
    double thermal = 0, thermal_dissipation = 0, heat_supply = 0,
           thermal_coupling_work = 0;
    /** sum k (c_e theta, div w_n) of the mechanical steps' thermal load:
     *  the part of external_work that is heat turned into motion. */
    double thermal_stress_work = 0;
    /**
     * The heat booked (doc/theory.md 13.4): sum k sum_i m_i gamma
     * |sigma_tau . w_tau|_i (frictional) and sum k sum_i m_i k_e,i
     * (theta_F - theta_n)_i (exchanged), both into the body.
     */
    double frictional_heat = 0, exchanged_heat = 0;

    double
    total_energy() const
    {
      return kinetic + elastic + thermal;
    }

    /** E_n - E_0 + dissipations - work: zero up to solver tolerance. */
    double
    defect() const
    {
      const double d = total_energy() - initial_energy - transfer_change +
                       viscous_dissipation + friction_dissipation +
                       damping_dissipation + numerical_dissipation -
                       external_work;
      const double thermal_terms =
        thermal_dissipation - heat_supply - thermal_coupling_work;
      // the terms a run without them has are added only where they are,
      // so that such a run's defect is the same number
      return (memory_work == 0. ? d : d + memory_work) +
             (thermal_terms == 0. ? 0. : thermal_terms);
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
     * |transfer changes| (+ |heat supply| with a temperature), without the
     * memory's work, which an unstable memory rule inflates with the
     * energy it creates (doc/theory.md 11.13). The thermal stress's work
     * (thermal_stress_work, in external_work) and thermal_coupling_work
     * move energy between the body's motion and its heat: neither is put
     * in (doc/theory.md 13.4), so that a coupling that creates energy
     * cannot count its own growth as supplied.
     */
    double
    data_energy() const
    {
      return std::abs(initial_energy) +
             std::abs(external_work - thermal_stress_work) +
             std::abs(transfer_change) + std::abs(heat_supply);
    }

    /** E_n relative to data_energy(). */
    double
    data_growth() const
    {
      return total_energy() / std::max(data_energy(), 1e-300);
    }
  };

  /**
   * The terms of an EnergyBalance that a checkpoint stores, by name: the
   * one list that writing and reading a checkpoint loop over (J_n is the
   * step's own and is not stored). A term is added at the end: a
   * checkpoint that holds the list without the terms added after it
   * resumes with their sums from zero.
   */
  inline const std::vector<std::pair<std::string, double EnergyBalance::*>> &
  saved_energy_terms()
  {
    using E = EnergyBalance;
    static const std::vector<std::pair<std::string, double E::*>> terms{
      {"kinetic", &E::kinetic},
      {"elastic", &E::elastic},
      {"initial_energy", &E::initial_energy},
      {"viscous_dissipation", &E::viscous_dissipation},
      {"friction_dissipation", &E::friction_dissipation},
      {"damping_dissipation", &E::damping_dissipation},
      {"external_work", &E::external_work},
      {"numerical_dissipation", &E::numerical_dissipation},
      {"transfer_change", &E::transfer_change},
      {"memory_work", &E::memory_work},
      {"thermal", &E::thermal},
      {"thermal_dissipation", &E::thermal_dissipation},
      {"heat_supply", &E::heat_supply},
      {"thermal_coupling_work", &E::thermal_coupling_work},
      {"frictional_heat", &E::frictional_heat},
      {"exchanged_heat", &E::exchanged_heat},
      {"thermal_stress_work", &E::thermal_stress_work}};
    return terms;
  }
} // namespace hemicontact
