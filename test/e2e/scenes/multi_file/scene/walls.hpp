// The scene's wall helpers: particle helpers in a header, which includes the
// wash API itself and a header of its own one folder deeper.
#pragma once

#include <wash/wash.hpp>

#include "detail/geometry.hpp"

constexpr double WallMass = 2.0;

bool IsWall(const wash::Particle& p) { return p.get_mass() > 1.5 * 1.0; }

// A mutable particle: the kernel's own.
void KeepAboveFloor(wash::Particle& p) {
    double gap = HeightAboveFloor(p);
    if (gap < 0.0) {
        wash::Vec2D pos = p.get_pos();
        *pos[1] = FloorY - gap;
        p.set_pos(pos);
        p.set_vel(wash::Vec2D{p.get_vel().at(0) * 0.5, -0.5 * p.get_vel().at(1)});
    }
}
