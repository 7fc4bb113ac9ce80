// ActiveSetNewton on its own, against a small problem with a known answer:
// minimise J(x) = 1/2 x.K x - b.x + sum_{i in C} p/2 min(x_i, 0)^2 over
// R^8 (K tridiagonal, SPD; C four "contact" entries whose branch is
// x_i < 0). The answer is found by trying all 16 branch sets. Newton must
// find it within a few iterations, decrease J in every iteration, report
// the iterations it took, and fail with its message when it may take only
// one or two iterations (naming 'max iterations') or when its linear
// solves are too inaccurate (a stall on fixed branches).
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/solver/active_set_newton.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests.h"

using namespace hemicontact;
using namespace dealii;

namespace
{
  constexpr unsigned int          n       = 8;
  constexpr double                penalty = 50;
  const std::vector<unsigned int> contact = {1, 3, 5, 7};

  FullMatrix<double>
  stiffness()
  {
    FullMatrix<double> k(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        k(i, i) = 4;
        if (i + 1 < n)
          k(i, i + 1) = k(i + 1, i) = -1;
      }
    return k;
  }

  Vector<double>
  load()
  {
    Vector<double> b(n);
    const double   values[n] = {1, -2, 0.5, -1.5, 2, 0.7, 0.3, -1};
    for (unsigned int i = 0; i < n; ++i)
      b[i] = values[i];
    return b;
  }

  /** The minimiser of the quadratic J with the penalty on @p active. */
  Vector<double>
  solve_on(const std::vector<bool> &active)
  {
    FullMatrix<double> k = stiffness();
    for (unsigned int j = 0; j < contact.size(); ++j)
      if (active[j])
        k(contact[j], contact[j]) += penalty;
    k.gauss_jordan();
    Vector<double> x(n);
    k.vmult(x, load());
    return x;
  }

  Vector<double>
  to_serial(const TrilinosWrappers::MPI::Vector &v)
  {
    Vector<double> x(n);
    for (unsigned int i = 0; i < n; ++i)
      x[i] = v[i];
    return x;
  }

  void
  from_serial(const Vector<double> &x, TrilinosWrappers::MPI::Vector &v)
  {
    for (unsigned int i = 0; i < n; ++i)
      v[i] = x[i];
    v.compress(VectorOperation::insert);
  }

  class PenaltyProblem : public ActiveSetProblem
  {
  public:
    void
    residual(const VectorType &w, VectorType &r) const override
    {
      Vector<double> kw(n);
      stiffness().vmult(kw, to_serial(w));
      kw -= load();
      from_serial(kw, r);
    }

    double
    load_norm() const override
    {
      return load().l2_norm();
    }

    unsigned int
    update_branches(const VectorType &w,
                    const VectorType &,
                    const unsigned int) override
    {
      energies.push_back(energy(w));
      unsigned int changed = 0;
      for (unsigned int j = 0; j < contact.size(); ++j)
        {
          const bool now = w[contact[j]] < 0;
          changed += (now != active[j]);
          active[j] = now;
        }
      return changed;
    }

    double
    nonsmooth_residual(const VectorType &r) const override
    {
      // the gradient of J: K x - b plus the penalty's p min(x, 0)
      Vector<double> g = to_serial(r);
      for (unsigned int j = 0; j < contact.size(); ++j)
        g[contact[j]] += penalty * std::min(last_w[contact[j]], 0.);
      return g.l2_norm();
    }

    unsigned int
    solve_linearized(const VectorType &,
                     const double,
                     const double,
                     VectorType &trial) override
    {
      from_serial(solve_on(active), trial);
      return 1;
    }

    void
    apply_quadratic(const VectorType &d, VectorType &k_d) const override
    {
      Vector<double> kd(n);
      stiffness().vmult(kd, to_serial(d));
      from_serial(kd, k_d);
    }

    double
    nodal_energy(const VectorType &w) const override
    {
      double e = 0;
      for (const unsigned int i : contact)
        e += 0.5 * penalty * std::pow(std::min(w[i], 0.), 2);
      return e;
    }

    /** J(w). */
    double
    energy(const VectorType &w)
    {
      last_w = to_serial(w);
      Vector<double> kw(n);
      stiffness().vmult(kw, last_w);
      return 0.5 * (last_w * kw) - load() * last_w + nodal_energy(w);
    }

    std::vector<bool>   active = std::vector<bool>(contact.size(), false);
    std::vector<double> energies; ///< J at every iteration's start
    Vector<double>      last_w = Vector<double>(n);
  };

  /** The same problem with linear solves that miss the branch set's
   *  minimiser by @p miss in every entry, a miss that shrinks by the
   *  factor @p shrink with every solve: with shrink = 1 the residual stops
   *  falling on fixed branches (a stall), with shrink = 0.1 it falls by
   *  about 10 in every iteration. */
  class InaccurateProblem : public PenaltyProblem
  {
  public:
    InaccurateProblem(const double miss, const double shrink)
      : miss(miss)
      , shrink(shrink)
    {}

    unsigned int
    solve_linearized(const VectorType &,
                     const double,
                     const double,
                     VectorType &trial) override
    {
      Vector<double> x = solve_on(active);
      x.add(miss);
      miss *= shrink;
      from_serial(x, trial);
      return 1;
    }

  private:
    double       miss;
    const double shrink;
  };

  /** Whether @p message contains @p text. */
  const char *
  says(const std::string &message, const std::string &text)
  {
    return message.find(text) != std::string::npos ? "yes" : "NO";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // the answer: the one branch set whose minimiser has exactly those
  // contact entries negative
  Vector<double> exact;
  unsigned int   n_consistent = 0;
  for (unsigned int set = 0; set < 16; ++set)
    {
      std::vector<bool> active(contact.size());
      for (unsigned int j = 0; j < contact.size(); ++j)
        active[j] = (set >> j) & 1;
      const Vector<double> x          = solve_on(active);
      bool                 consistent = true;
      for (unsigned int j = 0; j < contact.size(); ++j)
        consistent = consistent && ((x[contact[j]] < 0) == active[j]);
      if (consistent)
        {
          exact = x;
          ++n_consistent;
        }
    }
  out() << "branch sets consistent with their minimiser: " << n_consistent
        << "\n";

  const IndexSet            all = complete_index_set(n);
  ActiveSetNewton::Settings settings;
  settings.tolerance = 1e-12;
  for (const double start : {0., 1., -3.})
    {
      PenaltyProblem                problem;
      TrilinosWrappers::MPI::Vector w(all, MPI_COMM_WORLD), r(w);
      w = start;
      const ActiveSetNewton::Report report =
        ActiveSetNewton(settings).solve(problem, w, r);
      Vector<double> error = to_serial(w);
      error -= exact;
      bool decreasing = true;
      for (unsigned int i = 1; i < problem.energies.size(); ++i)
        decreasing =
          decreasing && problem.energies[i] <= problem.energies[i - 1] + 1e-14;
      out() << "start " << start << ": " << report.newton_iterations
            << " Newton iterations, " << report.linear_iterations
            << " linear solves, error "
            << (error.linfty_norm() < 1e-12 ? "< 1e-12" : "TOO LARGE")
            << ", J decreasing: " << (decreasing ? "yes" : "NO")
            << ", residual below tolerance: "
            << (report.relative_residual <= settings.tolerance ? "yes" : "NO")
            << "\n";
    }

  // one iteration is not enough from 0: Newton says so
  settings.max_iterations = 1;
  PenaltyProblem                problem;
  TrilinosWrappers::MPI::Vector w(all, MPI_COMM_WORLD), r(w);
  try
    {
      ActiveSetNewton(settings).solve(problem, w, r);
      out() << "max iterations 1: converged (UNEXPECTED)\n";
    }
  catch (const SolverFailure &failure)
    {
      const std::string message = failure.what();
      out() << "max iterations 1: " << message.substr(0, message.find(':'))
            << "\n";
      out() << "  names the limit: "
            << says(message, "limit 'nonlinear solver/max iterations' = 1")
            << ", nodes changing branch: "
            << says(message, "nodes still changing branch")
            << ", says stalled: " << says(message, "stalled") << "\n";
    }

  // linear solves whose error falls by 10 in every iteration: at the
  // limit of 4 iterations the residual is still falling, the iteration was
  // cut short, not stalled
  const auto failure_of = [&](InaccurateProblem &inaccurate) {
    TrilinosWrappers::MPI::Vector w_0(all, MPI_COMM_WORLD), r_0(w_0);
    try
      {
        ActiveSetNewton(settings).solve(inaccurate, w_0, r_0);
      }
    catch (const SolverFailure &failure)
      {
        return std::string(failure.what());
      }
    return std::string("converged");
  };
  settings.max_iterations = 4;
  InaccurateProblem slow(1e-2, 0.1);
  std::string       message = failure_of(slow);
  out() << "max iterations 4, residual falling: cut short: "
        << says(message, "the iteration was cut short") << ", names the limit: "
        << says(message, "limit 'nonlinear solver/max iterations' = 4")
        << ", says stalled: " << says(message, "stalled") << "\n";

  // linear solves that cannot reach the tolerance: a stall on fixed
  // branches, named as such and not blamed on the limit
  settings.max_iterations = 8;
  InaccurateProblem stalling(1e-4, 1);
  message = failure_of(stalling);
  out() << "max iterations 8, residual not falling: stalled: "
        << says(message, "stalled on fixed branches")
        << ", cut short: " << says(message, "cut short") << "\n";
}
