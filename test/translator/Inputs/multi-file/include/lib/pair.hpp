// Found on the include path (-I include): a pair helper.
#pragma once

#include "../../scene/walls.hpp"

wash::Vec2D Pair(const wash::Particle& self, const wash::Particle& n) {
  return IsWall(n) ? wash::Vec2D{0.0, 0.0} : self.get_pos() - n.get_pos();
}
