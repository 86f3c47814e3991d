// Found by scripts/fuzz_programs.py (seed 100: 11 of 20 programs): a particle
// access written in the source as the ARGUMENT of a function-like macro is
// rejected, located, as CodegenInMacro:
//   macro_argument_rejected.cpp:14:53: error: a particle access or particle
//   type inside a macro expansion cannot be rewritten; write it out in the source
// The reference builds and runs it. docs/diagnostics.md documents the error
// for an access inside the macro's BODY (SPEED(p)); here the argument's
// tokens are spelled in this file (their spelling locations are file
// locations), so it could be rewritten in place. A limitation, not a wrong
// result: reported, not fixed. Reproduce: wash --backend=serial <this file> -o out
#include <wash/wash.hpp>
#define DAMP(x) ((x) * 0.9)
void Spawn() { wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.0, 0.0}, wash::Vec2D{1.0, 0.0}); }
void Update(wash::Particle& p) { p.set_density(DAMP(p.get_density())); }
int main() {
    wash::set_influence_radius(0.2);
    wash::add_init_kernel(&Spawn);
    wash::add_update_kernel(&Update);
    wash::set_max_iterations(2);
    wash::start();
}
