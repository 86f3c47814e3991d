// wash::random and wash::random_normal (wash/random.hpp): a lattice jittered
// by an init kernel, a random gust drawn by a void kernel into a variable,
// a dissipative-particle-dynamics-like random pair force (one normal number
// per pair and step, keyed by the pair so both particles draw the same one)
// and a random kick per particle in the update kernel. Every number is a hash
// of (key, step, stream), so the dump agrees bit for bit on every backend,
// thread and rank count, and after a restart from a checkpoint.
#include <wash/wash.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

constexpr int side = 24;
constexpr double spacing = 1.0 / side;
constexpr double dt = 0.002;

void Spawn() {
    for (int k = 0; k < side * side; k++) {
        const double x = (k % side + 0.5 + 0.4 * (wash::random(k, 0) - 0.5)) * spacing;
        const double y = (k / side + 0.5 + 0.4 * (wash::random(k, 1) - 0.5)) * spacing;
        wash::create_particle(1.0, 1.0, spacing, wash::Vec2D{x, y}, wash::Vec2D{0.0, 0.0});
    }
}

void Gust() { wash::set_variable("gust", 0.5 * wash::random_normal(0, 7)); }

void PairNoise(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    wash::Vec2D push{0.0, 0.0};
    double density = 0.0;
    for (const auto& n : ns) {
        const wash::Vec2D d = p.get_pos() - n.get_pos();
        const double r = d.magnitude();
        const double w = 1.0 - r / (2.0 * spacing);
        density += w * w;
        // The same number for (i, j) and (j, i): equal and opposite pushes.
        const std::uint64_t lo = std::min(p.get_id(), n.get_id());
        const std::uint64_t hi = std::max(p.get_id(), n.get_id());
        push += d * (w * (4.0 + wash::random_normal(lo * (side * side) + hi, 2)) / r);
    }
    p.set_density(density);
    p.set_force_vector("push", push);
}

void Move(wash::Particle& p) {
    const wash::Vec2D kick{wash::random(p.get_id(), 3) - 0.5, wash::random(p.get_id(), 4) - 0.5};
    wash::Vec2D v = p.get_vel() * 0.98 + (p.get_force_vector("push") + kick) * dt;
    v += wash::Vec2D{wash::get_variable("gust"), 0.0} * dt;
    wash::Vec2D x = p.get_pos() + v * dt;
    // Walls at 0 and 1 on y: reflect.
    if (x.at(1) < 0.0 || x.at(1) > 1.0) {
        v = wash::Vec2D{v.at(0), -v.at(1)};
        x = p.get_pos() + v * dt;
    }
    p.set_vel(v);
    p.set_pos(x);
}

int main() {
    wash::set_influence_radius(2.0 * spacing);
    wash::set_bounding_box({0.0, 0.0}, {1.0, 1.0}, {true, false});
    wash::add_variable("gust", 0.0);
    wash::add_force("push", 2);
    wash::add_init_kernel(&Spawn);
    wash::add_void_kernel(&Gust);
    wash::add_force_kernel(&PairNoise);
    wash::add_update_kernel(&Move);
    wash::set_max_iterations(40);
    wash::start();
}
