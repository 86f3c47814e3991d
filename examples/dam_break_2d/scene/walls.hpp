// The tank of dam_break_2d: fixed wall particles around it, and the Adami,
// Hu & Adams (2012) wall treatment of wash/sph/walls.hpp applied to them.
//
// Wall particles are of the particle type "wall" (the fluid's is "fluid");
// the kernels are registered for the type they are for, so only code that
// sees both kinds, a neighbour loop, asks IsWall.
#pragma once

#include <wash/wash.hpp>
#include <wash/sph/eos.hpp>
#include <wash/sph/kernels.hpp>
#include <wash/sph/walls.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

inline bool IsWall(const wash::Particle& p) { return p.is_type("wall"); }

/// The centres of `layers` rows of wall particles of spacing dx outside the
/// tank [0, width] x [0, height]: the floor (corners included) and both sides.
inline std::vector<wash::Vec2D> WallPositions(double width, double height, double dx,
                                              int layers) {
    std::vector<wash::Vec2D> out;
    const int nx = int(std::lround(width / dx)), ny = int(std::lround(height / dx));
    for (int l = 0; l < layers; l++) {
        const double below = -(l + 0.5) * dx;
        for (int i = -layers; i < nx + layers; i++) // the floor
            out.push_back(wash::Vec2D{(i + 0.5) * dx, below});
        for (int j = 0; j < ny; j++) { // the sides
            out.push_back(wash::Vec2D{below, (j + 0.5) * dx});
            out.push_back(wash::Vec2D{width - below, (j + 0.5) * dx});
        }
    }
    return out;
}

/// For a wall particle, from its fluid neighbours (the kernel that calls it
/// is registered for walls with fluid neighbours): the pressure they extrapolate to it
/// (clamped at 0, so that a wall never pulls fluid), the density the equation
/// of state gives for it, and the no-slip velocity the viscous term uses.
inline void ExtrapolateToWall(wash::Particle& p, const std::vector<wash::Particle>& neighbours,
                              const wash::sph::Tait& eos, const wash::Vec2D& gravity) {
    const double h = p.get_smoothing_length();
    wash::sph::AdamiWall<2> sums;
    for (const auto& n : neighbours) {
        wash::Vec2D d = p.get_pos() - n.get_pos();
        double W = wash::sph::wendland_c2::W<2>(d.magnitude(), h);
        if (W > 0.0) sums.add(W, n.get_force_scalar("pressure"), n.get_density(), d, n.get_vel());
    }
    const double pressure = std::max(0.0, sums.pressure(gravity));
    p.set_force_scalar("pressure", pressure);
    p.set_density(eos.density(pressure));
    p.set_force_vector("wall_vel", sums.velocity(p.get_vel()));
}
