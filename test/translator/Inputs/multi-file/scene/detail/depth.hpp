// Depth 2, with a classic header guard.
#ifndef MULTI_FILE_DEPTH_HPP
#define MULTI_FILE_DEPTH_HPP

#include <wash/wash.hpp>

double Damping(const wash::Particle& p) { return p.get_density() > 2.0 ? 0.5 : 0.9; }

#endif
