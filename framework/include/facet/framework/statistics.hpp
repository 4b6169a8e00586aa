#pragma once
// Summary statistics of timing samples, as quoted in reports: medians and 95th percentiles.

#include <vector>

namespace facet {

// The p-th percentile (0..100) with linear interpolation between closest ranks; 0 when empty.
double percentile(std::vector<double> samples, double p);
inline double median(std::vector<double> samples) {
  return percentile(std::move(samples), 50.0);
}

}  // namespace facet
