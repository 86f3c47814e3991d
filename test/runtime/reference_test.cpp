// The reference runtime's semantics (docs/semantics.md), checked on small scenes.
// Built once for 2D and once for 3D.
#include "state.hpp"

#include <wash/detail/reduction.hpp>
#include <wash/detail/run_settings.hpp>
#include <wash/detail/variables.hpp>
#include <wash/wash.hpp>

#include <gtest/gtest.h>

#include <filesystem>

#include <unistd.h>

using namespace wash;
using detail::programOptions;
using detail::runSettings;
using detail::state;

namespace {

ParticleVec along(double x) {
  ParticleVec v;
  *v[0] = x;
  return v;
}

/// Fresh runtime state with output going to a temporary directory of the
/// test's own: ctest runs the tests of this suite in parallel processes.
struct ReferenceTest : ::testing::Test {
  std::filesystem::path out =
      std::filesystem::temp_directory_path() /
      ("wash-reference-test-" + std::to_string(WASH_DIM) + "d-" + std::to_string(::getpid()) + "-" +
       ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override {
    state() = detail::State{};
    runSettings() = {.dimensions = runSettings().dimensions}; // WASH_DIM, set before main
    programOptions() = {.steps = 1, .outDir = out.string(), .quiet = true};
    set_influence_radius(0.6);
  }
  void TearDown() override { std::filesystem::remove_all(out); }
};

std::vector<double> velocitiesX() {
  std::vector<double> v;
  for (const ParticleVec &p : state().particles.vel)
    v.push_back(p.at(0));
  return v;
}

void threeInALine() {
  for (int k = 0; k < 3; ++k)
    create_particle(1.0, 1.0, 0.5, along(0.5 * k), along(k + 1.0));
}

} // namespace

TEST_F(ReferenceTest, ForceKernelReadsNeighboursAsOfItsStart) {
  add_init_kernel(&threeInALine);
  // Writes its own velocity and reads its neighbours' velocities: a hazard.
  add_force_kernel([](Particle &p, const std::vector<Particle> &neighbours) {
    for (const Particle &n : neighbours)
      p.set_vel(p.get_vel() + n.get_vel());
  });
  start();
  // From the initial 1, 2, 3 whatever the processing order: 1+2, 2+1+3, 3+2.
  EXPECT_EQ(velocitiesX(), (std::vector<double>{3.0, 6.0, 5.0}));
}

TEST_F(ReferenceTest, ParticleSeesItsOwnWritesAtOnce) {
  add_init_kernel(&threeInALine);
  add_force_kernel([](Particle &p, const std::vector<Particle> &) {
    p.set_density(p.get_density() + 1.0);
    p.set_mass(p.get_density() * 2.0);
  });
  start();
  EXPECT_EQ(state().particles.mass[1], 4.0);
}

TEST_F(ReferenceTest, NeighboursAreOtherParticlesWithinTheRadiusInCanonicalOrder) {
  static std::vector<std::vector<std::size_t>> seen;
  seen.clear();
  add_init_kernel([] {
    // Created right to left, so creation order is not spatial order.
    for (double x : {0.85, 0.3, 0.0, 0.5})
      create_particle(1.0, 1.0, 0.5, along(x), {});
  });
  add_force_kernel([](Particle &p, const std::vector<Particle> &neighbours) {
    seen.resize(4);
    for (const Particle &n : neighbours)
      seen[p.get_id()].push_back(n.get_id());
  });
  start();
  // Cells of size 0.6: x = 0.0, 0.3, 0.5 in cell 0, 0.85 in cell 1; ids inside a cell ascending.
  EXPECT_EQ(seen[2], (std::vector<std::size_t>{1, 3}));    // x=0.0: 0.3, 0.5 (0.85 too far)
  EXPECT_EQ(seen[1], (std::vector<std::size_t>{2, 3, 0})); // x=0.3: cell 0 by id, then cell 1
  EXPECT_EQ(seen[0], (std::vector<std::size_t>{1, 3}));
}

TEST_F(ReferenceTest, UnregisteredForcesAreCreatedOnFirstUseAndOutputAfterRegisteredOnes) {
  add_force("zeta", 1);
  add_force("alpha", dimensions);
  add_init_kernel([] {
    Particle &p = create_particle(1.0, 1.0, 0.5, {}, {});
    p.set_force_scalar("yankee", 2.0);
    EXPECT_EQ(p.get_force_vector("bravo"), ParticleVec{}); // read before any write: zero
  });
  start();
  std::vector<std::string> names, dumped;
  for (const auto &c : state().frame(state().particles).columns) {
    names.push_back(c.name);
    if (c.inDump)
      dumped.push_back(c.name);
  }
  EXPECT_EQ(dumped, (std::vector<std::string>{"pos", "vel", "density", "mass", "smoothing_length",
                                              "zeta", "alpha", "bravo", "yankee"}));
  // Frames hold acc too, after vel; --dump never does.
  ASSERT_EQ(names.size(), dumped.size() + 1);
  EXPECT_EQ(names[2], "acc");
}

TEST_F(ReferenceTest, ANameUsedAsScalarAndVectorIsAnErrorAtTheUse) {
  add_force("nearDensity", 1);
  add_init_kernel([] {
    Particle &p = create_particle(1.0, 1.0, 0.5, {}, {});
    p.get_force_vector("nearDensity");
  });
  try {
    start();
    FAIL() << "no error";
  } catch (const detail::UsageError &e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("reference_test.cpp:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("error: force 'nearDensity' is a scalar but is used here as a vector"),
              std::string::npos)
        << msg;
  }
}

TEST_F(ReferenceTest, FloatPrecisionRoundsEveryStoredValue) {
  set_precision("float");
  add_init_kernel([] { create_particle(0.1, 1.0 / 3.0, 0.5, along(0.7), {}); });
  start();
  EXPECT_EQ(state().particles.density[0], double(0.1f));
  EXPECT_EQ(state().particles.mass[0], double(1.0f / 3.0f));
  EXPECT_EQ(state().particles.pos[0].at(0), double(0.7f));
}

TEST_F(ReferenceTest, NonFiniteStateStopsTheRunNamingStepKernelAndField) {
  add_init_kernel(&threeInALine);
  add_update_kernel([](Particle &p) {
    p.set_density(p.get_density() / (p.get_id() == 1 ? 0.0 : 1.0) - 1.0 / 0.0);
  });
  programOptions().steps = 3;
  try {
    start();
    FAIL() << "no error";
  } catch (const detail::RunError &e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("step 1: after kernel '"), std::string::npos) << msg;
    EXPECT_NE(msg.find("field 'density' of particle 0 is -inf"), std::string::npos) << msg;
  }
}

// The shared settings know this build's dimension before main runs.
TEST(ReferenceSettings, TheDimensionIsWashDim) { EXPECT_EQ(runSettings().dimensions, WASH_DIM); }

TEST_F(ReferenceTest, HeaderAndSummaryLinesAreTheSharedRunsWithItsName) {
  programOptions().quiet = false;
  set_simulation_name("lines");
  add_init_kernel(&threeInALine);
  testing::internal::CaptureStdout();
  start();
  std::string text = testing::internal::GetCapturedStdout();
  EXPECT_TRUE(text.starts_with("wash reference: 'lines', 3 particles, " + std::to_string(WASH_DIM) +
                               "D, double, influence radius 0.6, 1 steps\n"
                               "wash: 1 steps of 3 particles in "))
      << text;
  EXPECT_NE(text.find(" ns per particle-step (this process, 1 thread); output in " + out.string() +
                      "\n"),
            std::string::npos)
      << text;
}

TEST_F(ReferenceTest, StopOutsideAVoidKernelIsAnError) {
  EXPECT_THROW(stop(), detail::UsageError);
  EXPECT_FALSE(runSettings().stopRequested);
}

TEST_F(ReferenceTest, StopMakesThisIterationTheLast) {
  programOptions().steps = 5;
  add_init_kernel(&threeInALine);
  add_void_kernel([] { stop(); });
  add_update_kernel([](Particle &p) { p.set_density(p.get_density() + 1.0); });
  start();
  EXPECT_EQ(state().particles.density[0], 2.0); // 1, then one iteration
}

TEST_F(ReferenceTest, CreatingParticlesOutsideInitKernelsIsAnError) {
  EXPECT_THROW(create_particle(1.0, 1.0, 0.5, {}, {}), detail::UsageError);
}

TEST_F(ReferenceTest, BadSettingsAreErrors) {
  EXPECT_THROW(set_precision("half"), detail::UsageError);
  EXPECT_THROW(set_influence_radius(-1.0), detail::UsageError);
  EXPECT_THROW(add_force("f", 4), detail::UsageError);
  add_force("f", 1);
  EXPECT_THROW(add_force("f", 1), detail::UsageError);
}

TEST_F(ReferenceTest, PeriodicAxesWrapPositionsAndSeeNeighboursAcrossTheFace) {
  static std::vector<double> seenX;
  seenX.clear();
  std::vector<double> lo(dimensions, 0.0), hi(dimensions, 2.0);
  std::vector<bool> periodic(dimensions, false);
  periodic[0] = true;
  set_bounding_box(lo, hi, periodic);
  add_init_kernel([] {
    create_particle(1.0, 1.0, 0.5, along(0.1), {});
    create_particle(1.0, 1.0, 0.5, along(1.95), {});
    create_particle(1.0, 1.0, 0.5, along(2.3), {}); // outside: wrapped to 0.3 after init
  });
  add_force_kernel([](Particle &p, const std::vector<Particle> &neighbours) {
    if (p.get_id() == 0)
      for (const Particle &n : neighbours)
        seenX.push_back(n.get_pos().at(0));
  });
  start();
  EXPECT_NEAR(state().particles.pos[2].at(0), 0.3, 1e-15);
  // Particle 0 at 0.1 sees particle 1 through the face at its image, 1.95 - 2.
  ASSERT_EQ(seenX.size(), 2u);
  EXPECT_EQ(seenX[0], 1.95 - 2.0);
  EXPECT_NEAR(seenX[1], 0.3, 1e-15);
}

TEST_F(ReferenceTest, APeriodicBoxMustBeLongerThanTwiceTheRadius) {
  std::vector<double> lo(dimensions, 0.0), hi(dimensions, 1.0);
  set_bounding_box(lo, hi, std::vector<bool>(dimensions, true)); // radius 0.6: 1.0 < 1.2
  add_init_kernel(&threeInALine);
  EXPECT_THROW(start(), detail::RunError);
  EXPECT_THROW(set_bounding_box({0.0}, {1.0}, {true}), detail::UsageError); // wrong length
}

TEST_F(ReferenceTest, VoidKernelsRunOncePerIterationInOrderAndSetVariables) {
  detail::variables().clear();
  add_variable("ticks", 0.0);
  add_init_kernel(&threeInALine);
  add_void_kernel([] { set_variable("ticks", get_variable("ticks") + 1.0); });
  add_update_kernel([](Particle &p) { p.set_density(get_variable("ticks")); });
  programOptions().steps = 3;
  start();
  EXPECT_EQ(get_variable("ticks"), 3.0);
  EXPECT_EQ(state().particles.density[2], 3.0); // the update after the void kernel saw it
}

TEST_F(ReferenceTest, UnknownOrDuplicateVariablesAreErrorsAtTheUse) {
  detail::variables().clear();
  EXPECT_THROW(get_variable("nope"), detail::UsageError);
  EXPECT_THROW(set_variable("nope", 1.0), detail::UsageError);
  add_variable("dt", 0.1);
  EXPECT_THROW(add_variable("dt", 0.2), detail::UsageError);
}

TEST_F(ReferenceTest, ReductionKernelsCombineAllParticlesIntoAVariable) {
  detail::variables().clear();
  add_variable("sum", -1.0);
  add_variable("min", 0.0);
  add_variable("max", 0.0);
  add_init_kernel(&threeInALine); // x = 0, 0.5, 1; vel x = 1, 2, 3
  auto velX = [](const Particle &p) { return p.get_vel().at(0); };
  add_reduction_kernel(velX, Reduction::Sum, "sum");
  add_reduction_kernel(velX, Reduction::Min, "min");
  add_reduction_kernel(velX, Reduction::Max, "max");
  start();
  EXPECT_EQ(get_variable("sum"), 6.0);
  EXPECT_EQ(get_variable("min"), 1.0);
  EXPECT_EQ(get_variable("max"), 3.0);
  EXPECT_THROW(add_reduction_kernel(velX, Reduction::Sum, "missing"), detail::UsageError);
}

TEST(Reduction, SumsExactlyMinAndMaxOfNothingAreInfinite) {
  using detail::ReduceOp;
  // 1e16 + 1 + -1e16 added in this order is 0 in double; the exact sum is 1.
  EXPECT_EQ(detail::reduceInIdOrder({1e16, 1.0, -1e16}, ReduceOp::Sum), 1.0);
  EXPECT_EQ(detail::reduceInIdOrder({}, ReduceOp::Sum), 0.0);
  EXPECT_EQ(detail::reduceInIdOrder({}, ReduceOp::Min), std::numeric_limits<double>::infinity());
  EXPECT_EQ(detail::reduceInIdOrder({}, ReduceOp::Max), -std::numeric_limits<double>::infinity());
}
