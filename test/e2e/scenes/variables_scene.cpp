// Global variables, void kernels and reduction kernels: a void kernel damps a
// global "speed" by the total crowding (a Sum reduction: exact, so it agrees
// bit for bit on every backend, thread and rank count) and counts iterations;
// particles drift by it and a force kernel reads it, in a box periodic in x.
#include <wash/wash.hpp>

#include <vector>

void Spawn() {
    for (int j = 0; j < 20; j++)
        for (int i = 0; i < 30; i++)
            wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.05 * i + 0.01 * j, 0.05 * j},
                                  wash::Vec2D{1.0, 0.0});
    wash::set_variable("speed", 0.4);
}

void Damp() {
    double crowd = wash::get_variable("crowding") / 600.0;
    wash::set_variable("speed", wash::get_variable("speed") * (0.99 + 1e-4 * crowd) +
                                    1e-3 * (wash::get_variable("top") - wash::get_variable("bottom")));
    wash::set_variable("iterations", wash::get_variable("iterations") + 1.0);
}

double Crowding(const wash::Particle& p) { return p.get_density(); }
double Height(const wash::Particle& p) { return p.get_pos().at(1); }

void Drift(wash::Particle& p) {
    p.set_pos(p.get_pos() + p.get_vel() * (wash::get_variable("speed") * 0.01));
}

void Crowd(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    double near = 0.0;
    for (const auto& n : ns)
        near += (p.get_pos() - n.get_pos()).magnitude();
    p.set_density(near * wash::get_variable("speed") + wash::get_variable("iterations"));
}

int main() {
    wash::set_influence_radius(0.12);
    wash::set_bounding_box({0.0, 0.0}, {1.5, 1.0}, {true, false});
    wash::add_variable("speed", 0.0);
    wash::add_variable("iterations", 0.0);
    wash::add_variable("crowding", 0.0);
    wash::add_variable("top", 0.0);
    wash::add_variable("bottom", 0.0);
    wash::add_init_kernel(&Spawn);
    wash::add_reduction_kernel(&Crowding, wash::Reduction::Sum, "crowding");
    wash::add_reduction_kernel(&Height, wash::Reduction::Max, "top");
    wash::add_reduction_kernel(&Height, wash::Reduction::Min, "bottom");
    wash::add_void_kernel(&Damp);
    wash::add_update_kernel(&Drift);
    wash::add_force_kernel(&Crowd);
    wash::set_max_iterations(100);
    wash::start();
}
