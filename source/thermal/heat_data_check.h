#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/coupling/field_support.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

namespace hemicontact
{
  /**
   * The heat model's rule for its data (doc/theory.md 13): every datum a
   * finite number (and > 0 or >= 0 where it must be), checked where it
   * is evaluated, the first violation of any rank thrown on every rank
   * with the entry, the point and the time (heat_model.cc).
   */
  namespace heat_data_check
  {
    using namespace dealii;

    /** "(x, y[, z])" of @p p. */
    template <int dim>
    std::string
    at(const Point<dim> &p)
    {
      std::ostringstream s;
      s << "(";
      for (unsigned int d = 0; d < dim; ++d)
        s << (d ? ", " : "") << p[d];
      s << ")";
      return s.str();
    }

    /** What a datum must be besides a finite number. */
    enum class Sign
    {
      any,
      non_negative,
      positive
    };

    /**
     * The rule for every datum of the heat model, checked where it is
     * evaluated: @p entry (quoted, or what it is derived from) is
     * @p value at @p p (and time @p t, for data that may depend on t),
     * which must be a finite number (> 0 or >= 0 as @p sign says). The
     * first violation goes into @p error (if that is still empty), thrown
     * on every rank by throw_first_error().
     */
    template <int dim>
    void
    check_datum(std::string                &error,
                const double                value,
                const std::string          &entry,
                const Point<dim>           &p,
                const std::optional<double> t,
                const Sign                  sign = Sign::any)
    {
      const bool signed_ok =
        sign == Sign::any || (sign == Sign::positive ? value > 0 : value >= 0);
      if ((std::isfinite(value) && signed_ok) || !error.empty())
        return;
      std::ostringstream message;
      message << "temperature: " << entry << " is ";
      if (std::isfinite(value))
        message << value;
      else
        message << "not a finite number (" << value << ")";
      message << " at x = " << at(p);
      if (t)
        message << ", t = " << *t;
      message << "; it must be a finite number"
              << (sign == Sign::positive     ? " > 0" :
                  sign == Sign::non_negative ? " >= 0" :
                                               "")
              << ": check the expression at that point"
              << (t ? " and time." : ".");
      error = message.str();
    }

    /** Whether every owned entry of @p v is a finite number, on all ranks
     *  (entry by entry: a norm would overflow or pass over a NaN). */
    inline bool
    all_finite(const TrilinosWrappers::MPI::Vector &v, MPI_Comm comm)
    {
      unsigned int n_bad = 0;
      for (const auto i : v.locally_owned_elements())
        n_bad += !std::isfinite(v[i]);
      return Utilities::MPI::sum(n_bad, comm) == 0;
    }

  } // namespace heat_data_check
} // namespace hemicontact
