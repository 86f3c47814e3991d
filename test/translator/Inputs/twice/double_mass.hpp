// No include guard: included twice, its code is rewritten once.
inline void DoubleMass(wash::Particle &p) {
  p.set_mass(p.get_mass() * 2.0);
}
