// Per-size statistics and the REV size (theory.md 3.7 step 6). The criterion
// (Fissure's default, after Min et al. 2004): a size is representative when,
// over its realizations, the coefficients of variation of both principal
// permeabilities are below cv_max and the mean ellipse misfit is below
// misfit_max; the REV size is the smallest size from which on every larger
// size of the study is representative too (the components converge to a
// band, so one lucky size does not count).
#include <cmath>

#include "flow/rev/rev_study.h"

namespace fissure::flow {

namespace {

double coefficient_of_variation(double mean, double std) {
  return mean > 0 ? std / mean : INFINITY;
}

}  // namespace

void summarize_rev(RevStudyResult& result) {
  const RevStudyConfig& c = result.config;
  result.sizes.clear();
  for (std::size_t s = 0; s < c.sizes.size(); ++s) {
    SizeStatistics st;
    st.size = c.sizes[s];
    double sum_max = 0, sum_min = 0, sq_max = 0, sq_min = 0, cos2 = 0, sin2 = 0;
    for (const RealizationFit& f : result.fits) {
      if (f.size_index != static_cast<int>(s) || !f.connected) continue;
      ++st.samples;
      st.mean_kxx += f.fit.k(0, 0);
      st.mean_kyy += f.fit.k(1, 1);
      st.mean_kxy += f.fit.k(0, 1);
      sum_max += f.fit.k_max;
      sum_min += f.fit.k_min;
      sq_max += f.fit.k_max * f.fit.k_max;
      sq_min += f.fit.k_min * f.fit.k_min;
      st.mean_misfit += f.fit.misfit;
      cos2 += std::cos(2 * f.fit.angle);
      sin2 += std::sin(2 * f.fit.angle);
    }
    if (st.samples > 0) {
      const double n = st.samples;
      st.mean_kxx /= n, st.mean_kyy /= n, st.mean_kxy /= n, st.mean_misfit /= n;
      st.mean_kmax = sum_max / n;
      st.mean_kmin = sum_min / n;
      // Sample standard deviation (n - 1); zero for a single realization.
      const double var_max =
          n > 1 ? std::max(0.0, (sq_max - n * st.mean_kmax * st.mean_kmax) / (n - 1)) : 0;
      const double var_min =
          n > 1 ? std::max(0.0, (sq_min - n * st.mean_kmin * st.mean_kmin) / (n - 1)) : 0;
      st.std_kmax = std::sqrt(var_max);
      st.std_kmin = std::sqrt(var_min);
      st.cv_kmax = coefficient_of_variation(st.mean_kmax, st.std_kmax);
      st.cv_kmin = coefficient_of_variation(st.mean_kmin, st.std_kmin);
      st.mean_angle = 0.5 * std::atan2(sin2, cos2);  // axial mean of the directions
    } else {
      st.cv_kmax = st.cv_kmin = INFINITY;
    }
    // Every realization must have a connected network for the size to count.
    st.meets_criterion = st.samples == c.realizations && st.cv_kmax < c.cv_max &&
                         st.cv_kmin < c.cv_max && st.mean_misfit < c.misfit_max;
    result.sizes.push_back(st);
  }
  result.rev_size.reset();
  for (int s = static_cast<int>(result.sizes.size()) - 1; s >= 0; --s) {
    if (!result.sizes[s].meets_criterion) break;
    result.rev_size = result.sizes[s].size;
  }
}

}  // namespace fissure::flow
