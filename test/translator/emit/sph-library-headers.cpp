// wash's SPH library sits on the API's include path, yet it is user code: its
// headers are rewritten into the generated project under user/wash/sph/, with
// #line back to the installed originals, and a particle helper defined there
// (wash::sph::kinetic_energy) is rewritten like the simulation's own. The
// installed headers are not touched.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %wash --backend=serial -o %t/out --depfile %t/out.d %s
// RUN: FileCheck --check-prefix=MAIN %s < %t/out/sph-library-headers.serial.cpp
// RUN: FileCheck --check-prefix=DIAG %s < %t/out/user/wash/sph/diagnostics.hpp
// RUN: FileCheck --check-prefix=KERNELS %s < %t/out/user/wash/sph/kernels.hpp
// RUN: FileCheck --check-prefix=DEP %s < %t/out.d
// RUN: %cxx_check -I%t/out %t/out/sph-library-headers.serial.cpp
// RUN: %wash --dump-model %s | FileCheck --check-prefix=MODEL %s
// RUN: grep -rq "wash_gen::" %S/../../../runtime/include/wash/sph && exit 1 || true

// MAIN: #include "sph-library-headers.wash.hpp"
// MAIN: #include "user/wash/sph/diagnostics.hpp"
// MAIN: #include "user/wash/sph/kernels.hpp"
#include <wash/wash.hpp>
#include <wash/sph/diagnostics.hpp>
#include <wash/sph/kernels.hpp>

#include <vector>

// DIAG: #line 1 "{{.*}}/wash/sph/diagnostics.hpp"
// DIAG: #include "../../../sph-library-headers.wash.hpp"
// DIAG: inline double kinetic_energy(const auto &p) {
// DIAG-NEXT: wash::ParticleVec v = wash_gen::P.vel[p];
// DIAG-NEXT: return wash_gen::P.mass[p] * 0.5 * v.dot(v);

// KERNELS: #line 1 "{{.*}}/wash/sph/kernels.hpp"
// KERNELS: namespace wendland_c2 {

// DEP: {{.*}}/wash/sph/diagnostics.hpp
// DEP: {{.*}}/wash/sph/kernels.hpp

// MODEL: reduction Kinetic
// MODEL-NEXT: own-reads: vel mass

void Spawn() {
    for (int i = 0; i < 4; i++)
        wash::create_particle(1.0, 1.0, 0.5, wash::Vec2D{0.5 * i, 0.0}, wash::Vec2D{1.0, 0.0});
}

void Density(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    double rho = p.get_mass() * wash::sph::wendland_c2::W(0.0, p.get_smoothing_length());
    for (const auto& n : neighbours)
        rho += n.get_mass() * wash::sph::wendland_c2::W((p.get_pos() - n.get_pos()).magnitude(),
                                                        p.get_smoothing_length());
    p.set_density(rho);
}

double Kinetic(const wash::Particle& p) { return wash::sph::kinetic_energy(p); }

int main() {
    wash::set_precision("double");
    wash::set_influence_radius(1.0);
    wash::add_variable("kinetic", 0.0);
    wash::add_init_kernel(&Spawn);
    wash::add_force_kernel(&Density);
    wash::add_reduction_kernel(&Kinetic, wash::Reduction::Sum, "kinetic");
    wash::set_max_iterations(2);
    wash::start();
}
