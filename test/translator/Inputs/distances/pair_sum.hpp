#pragma once
#include <wash/wash.hpp>
#include <vector>

inline double PairSum(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double sum = 0;
  for (const auto &n : ns)
    sum += (p.get_pos() - n.get_pos()).magnitude();
  return sum;
}
