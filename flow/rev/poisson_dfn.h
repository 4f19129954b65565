// A stochastic 2D DFN of straight traces for the REV study (theory.md 3.7
// step 1; after Min, Jing et al. 2004): per set, trace centres uniform in a
// square region (a Poisson process), orientation normal about the set's mean
// angle, lengths from a truncated power law n(l) ~ l^-a on [l_min, l_max],
// apertures log-normal; the number of traces is set by the set's P21 (trace
// length per unit area). Realization r uses seed + r, so every realization is
// reproducible and independent of the order in which threads ask for it.
#pragma once

#include <vector>

#include "flow/network/trace_network.h"

namespace fissure::flow {

struct DfnSet {
  double angle = 0;               ///< mean trace direction (rad)
  double angle_std = 0;           ///< standard deviation of the direction (rad)
  double p21 = 1;                 ///< trace length per unit area (1/m)
  double length_min = 1;          ///< m
  double length_max = 10;         ///< m
  double length_exponent = 2.5;   ///< a of n(l) ~ l^-a (a != 1, 2 handled)
  double aperture = 1e-4;         ///< median aperture (m)
  double aperture_log10_std = 0;  ///< standard deviation of log10(aperture)
};

struct PoissonDfn {
  std::vector<DfnSet> sets;
  double region = 20;  ///< side of the square region, centred on the study's centre (m)
  Vec2 centre = Vec2::Zero();
  unsigned long seed = 1;
};

/// The traces of realization r.
std::vector<Trace> generate_traces(const PoissonDfn& dfn, int realization);

/// Mean trace length of a set's truncated power law (m).
double mean_length(const DfnSet& set);

}  // namespace fissure::flow
