// Found on an include path (-I include): a pair force taking the particle
// and one neighbour, and a sum over the neighbour list.
#pragma once

#include "../../scene/walls.hpp"

#include <wash/wash.hpp>

#include <vector>

inline double Weight(double r) { return r < H ? (H - r) * (H - r) / (H * H) : 0.0; }

double DensitySum(const wash::Particle& self, const std::vector<wash::Particle>& ns) {
    double sum = 0.0;
    for (const wash::Particle& n : ns)
        sum += (IsWall(n) ? 0.5 : 1.0) * Weight((self.get_pos() - n.get_pos()).magnitude());
    return sum;
}

wash::Vec2D PairForce(const wash::Particle& self, const wash::Particle& n) {
    wash::Vec2D d = self.get_pos() - n.get_pos();
    double r = d.magnitude();
    if (r <= 0.0)
        return wash::Vec2D{0.0, 0.0};
    double strength = 40.0 * Weight(r) * (self.get_density() + n.get_density());
    if (IsWall(n))
        strength *= 2.0;
    return d / r * strength;
}
