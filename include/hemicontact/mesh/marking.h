#pragma once

#include <hemicontact/input/parameters.h>

#include <cstddef>
#include <vector>

namespace hemicontact
{
  /**
   * The marking of adaptive refinement, computed from all cell indicators
   * of the mesh sorted by size: the same for any partition of the mesh.
   * Cells with an indicator above @p refine are refined, those below
   * @p coarsen coarsened (refine >= coarsen).
   */
  struct MarkingThresholds
  {
    double refine;  ///< refine the cells with an indicator above this
    double coarsen; ///< coarsen the cells with an indicator below this
  };

  /**
   * Two indicators a >= b count as tied if a - b <= this times a. Far above
   * the float round-off (6e-8) and the differences that solver tolerances
   * make between runs on different numbers of MPI ranks (up to 1.2e-6 seen
   * on the default example).
   */
  constexpr double marking_tie_tolerance = 1e-5;

  /**
   * Where to cut the values @p descending (sorted from the largest) into
   * the first ones and the rest, aimed at @p n first ones: @p n itself unless
   * the values on both sides of the cut are tied (marking_tie_tolerance),
   * else the nearest cut whose neighbours are not tied (the smaller one of
   * two equally near if @p prefer_smaller, else the larger one), at most
   * max(8, N/1000) away; if there is none within that distance, the cut
   * with the largest relative gap within it.
   */
  std::size_t
  untied_cut(const std::vector<float> &descending,
             const std::size_t         n,
             const bool                prefer_smaller);

  /**
   * The thresholds for the indicators @p indicators of all cells of the
   * mesh (in any order). 'fixed number': refine the @p refine_fraction of
   * the cells with the largest indicators, coarsen the @p coarsen_fraction
   * with the smallest; 'fixed fraction': refine the fewest cells with the
   * largest indicators whose sum is at least @p refine_fraction of the sum
   * of all, coarsen the most cells with the smallest indicators whose sum is
   * at most @p coarsen_fraction of it. Either count is then moved off ties by
   * untied_cut() (preferring fewer refined and fewer coarsened cells) and
   * each threshold put halfway between the values on the two sides of its
   * cut, so that values that differ by round-off or by solver tolerances
   * fall on the same side of it.
   */
  MarkingThresholds
  marking_thresholds(std::vector<float>    indicators,
                     const MarkingStrategy strategy,
                     const double          refine_fraction,
                     const double          coarsen_fraction);
} // namespace hemicontact
