// Neighbour distances kept by the search, in every form the translator reads
// them in: a loop variable through local variables, ns[k] directly and
// through a reference, and a generic helper called with the particle itself
// (distances read) and with a neighbour (the magnitude computed as written).
// Particles drift in a box periodic in x, so images are among the neighbours.
#include <wash/wash.hpp>

#include <cmath>
#include <vector>

constexpr double h = 0.12;

double W(double r) { return r < h ? (h - r) * (h - r) : 0.0; }

void Spawn() {
    for (int j = 0; j < 20; j++)
        for (int i = 0; i < 30; i++)
            wash::create_particle(1.0, 1.0, h,
                                  wash::Vec2D{0.05 * i + 0.013 * std::sin(7.0 * j), 0.05 * j},
                                  wash::Vec2D{std::cos(0.3 * i + j), std::sin(0.2 * j - i)});
}

double Around(const wash::Particle& q, const std::vector<wash::Particle>& ns) {
    double sum = 0.0;
    for (const auto& n : ns)
        sum += W((q.get_pos() - n.get_pos()).magnitude());
    return sum;
}

void Density(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    p.set_density(1.0 + Around(p, ns));
}

void Push(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    const wash::Vec2D pos = p.get_pos();
    wash::Vec2D push{0.0, 0.0};
    for (const auto& n : ns) {
        wash::Vec2D offset = pos - n.get_pos();
        double r = offset.magnitude();
        if (r > 0.0)
            push += offset / r * (W(r) * (p.get_density() + n.get_density()));
    }
    double crowd = 0.0;
    for (size_t k = 0; k < ns.size(); k++) {
        crowd += W((ns[k].get_pos() - p.get_pos()).magnitude());
        const wash::Particle& n = ns[k];
        const wash::Vec2D d = n.get_pos() - pos;
        crowd += 0.5 * d.magnitude() * Around(n, ns) / (1.0 + ns.size());
    }
    p.set_vel(p.get_vel() * 0.99 + push * 0.05 + wash::Vec2D{0.0, -0.01 * crowd});
}

void Move(wash::Particle& p) {
    wash::Vec2D pos = p.get_pos() + p.get_vel() * 0.002;
    wash::Vec2D vel = p.get_vel();
    if (pos.at(1) < 0.0 || pos.at(1) > 1.0) {
        *vel[1] = -vel.at(1);
        *pos[1] = pos.at(1) < 0.0 ? -pos.at(1) : 2.0 - pos.at(1);
    }
    p.set_pos(pos);
    p.set_vel(vel);
}

int main() {
    wash::set_influence_radius(h);
    wash::set_bounding_box({0.0, 0.0}, {1.5, 1.0}, {true, false});
    wash::add_init_kernel(&Spawn);
    wash::add_force_kernel(&Density);
    wash::add_force_kernel(&Push);
    wash::add_update_kernel(&Move);
    wash::set_max_iterations(100);
    wash::start();
}
