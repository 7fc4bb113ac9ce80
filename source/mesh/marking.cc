#include <hemicontact/mesh/marking.h>

#include <algorithm>
#include <functional>
#include <limits>

namespace hemicontact
{
  namespace
  {
    /** Relative gap of the cut after the first @p i of @p v (0 < i < N). */
    double
    relative_gap(const std::vector<float> &v, const std::size_t i)
    {
      const double above = v[i - 1], below = v[i];
      return above > 0 ? (above - below) / above : 0.;
    }

    /** The threshold halfway between the values on the two sides of a cut. */
    double
    threshold_at(const std::vector<float> &v, const std::size_t cut)
    {
      if (cut == 0)
        return std::numeric_limits<double>::infinity();
      if (cut == v.size())
        return -std::numeric_limits<double>::infinity();
      return 0.5 * (static_cast<double>(v[cut - 1]) + v[cut]);
    }
  } // namespace

  std::size_t
  untied_cut(const std::vector<float> &descending,
             const std::size_t         n,
             const bool                prefer_smaller)
  {
    const std::size_t N = descending.size();
    if (n >= N)
      return N;
    const auto untied = [&](const std::size_t i) {
      return i == 0 || i == N ||
             relative_gap(descending, i) > marking_tie_tolerance;
    };
    if (untied(n))
      return n;

    // the candidates by distance, the preferred one of two equally near first
    const std::size_t        reach = std::max<std::size_t>(8, N / 1000);
    std::vector<std::size_t> candidates;
    for (std::size_t d = 1; d <= reach; ++d)
      {
        const bool        has_lower = n >= d, has_upper = n + d <= N;
        const std::size_t lower = n - d, upper = n + d;
        if (prefer_smaller)
          {
            if (has_lower)
              candidates.push_back(lower);
            if (has_upper)
              candidates.push_back(upper);
          }
        else
          {
            if (has_upper)
              candidates.push_back(upper);
            if (has_lower)
              candidates.push_back(lower);
          }
      }
    for (const std::size_t i : candidates)
      if (untied(i))
        return i;

    // no untied cut within reach (a long run of near-ties): the widest gap
    std::size_t best     = n;
    double      best_gap = relative_gap(descending, n);
    for (const std::size_t i : candidates)
      if (i > 0 && i < N && relative_gap(descending, i) > best_gap)
        {
          best     = i;
          best_gap = relative_gap(descending, i);
        }
    return best;
  }

  MarkingThresholds
  marking_thresholds(std::vector<float>    indicators,
                     const MarkingStrategy strategy,
                     const double          refine_fraction,
                     const double          coarsen_fraction)
  {
    std::sort(indicators.begin(), indicators.end(), std::greater<float>());
    const std::vector<float> &v = indicators;
    const std::size_t         N = v.size();
    if (N == 0)
      return {std::numeric_limits<double>::infinity(),
              -std::numeric_limits<double>::infinity()};

    // the aimed number of refined cells (from the top) and of coarsened ones
    // (from the bottom)
    std::size_t n_refine = 0, n_coarsen = 0;
    if (strategy == MarkingStrategy::fixed_number)
      {
        n_refine  = static_cast<std::size_t>(refine_fraction * N);
        n_coarsen = static_cast<std::size_t>(coarsen_fraction * N);
      }
    else
      {
        double total = 0;
        for (const float x : v)
          total += x;
        if (refine_fraction > 0)
          for (double sum = 0; n_refine < N && sum < refine_fraction * total;
               ++n_refine)
            sum += v[n_refine];
        if (coarsen_fraction > 0)
          for (double sum = v[N - 1];
               n_coarsen < N && sum <= coarsen_fraction * total;)
            {
              ++n_coarsen;
              if (n_coarsen < N)
                sum += v[N - 1 - n_coarsen];
            }
      }
    n_refine  = std::min(n_refine, N);
    n_coarsen = std::min(n_coarsen, N - n_refine);

    const std::size_t refine_cut = untied_cut(v, n_refine, true);
    // fewer coarsened cells: a cut further down
    const std::size_t coarsen_cut =
      std::max(untied_cut(v, N - n_coarsen, false), refine_cut);
    return {threshold_at(v, refine_cut), threshold_at(v, coarsen_cut)};
  }
} // namespace hemicontact
