// The run set-up every runtime shares (run_settings.hpp, run.hpp): the
// settings calls' checks and messages, and the start-up checks of Run, for a
// translated program and for the untranslated reference.
#include <wash/detail/run.hpp>
#include <wash/settings.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <regex>

#include <unistd.h>

using namespace wash;
using detail::programOptions;
using detail::runSettings;
using detail::Translation;

namespace {

constexpr Translation serial2d{.backend = "serial", .dimensions = 2};
constexpr Translation untranslated{.backend = "reference",
                                   .dimensions = 2,
                                   .floatStorage = std::nullopt,
                                   .smoothingLengthSearch = std::nullopt};

/// Fresh settings of a 2D program whose output goes to a directory of the
/// test's own: ctest runs the tests in parallel processes.
struct RunTest : ::testing::Test {
  std::filesystem::path out = std::filesystem::temp_directory_path() /
                              ("wash-run-test-" + std::to_string(::getpid()) + "-" +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override {
    runSettings() = {.dimensions = 2};
    detail::simTime() = {};
    programOptions() = {.outDir = out.string(), .quiet = true};
    set_influence_radius(0.5);
    set_max_iterations(4);
  }
  void TearDown() override {
    std::filesystem::remove_all(out);
    detail::runStage() = {}; // a run that threw leaves its step (random_test reads it)
  }
};

/// The message of the error f throws.
template <typename Error, typename F> std::string messageOf(F f) {
  try {
    f();
  } catch (const Error &e) {
    return e.what();
  }
  return "(no error)";
}

} // namespace

TEST_F(RunTest, BadSettingsAreErrorsAtTheCall) {
  const int line = __LINE__ + 1;
  std::string msg = messageOf<detail::UsageError>([] { set_precision("half"); });
  EXPECT_NE(msg.find("run_test.cpp:" + std::to_string(line) + ":"), std::string::npos) << msg;
  EXPECT_NE(msg.find(": error: precision must be \"double\" or \"float\", not \"half\""),
            std::string::npos)
      << msg;
  for (double r : {0.0, -1.0, std::numeric_limits<double>::infinity()})
    EXPECT_NE(messageOf<detail::UsageError>([r] {
                set_influence_radius(r);
              }).find("error: influence radius must be a positive number"),
              std::string::npos);
  EXPECT_NE(messageOf<detail::UsageError>([] {
              set_smoothing_length_support(std::nan(""));
            }).find("error: the support radius must be a positive multiple of h"),
            std::string::npos);
  // The lists must fit the program's dimension, here 2.
  for (auto box : {std::vector<double>{0.0}, std::vector<double>{0.0, 0.0, 0.0}})
    EXPECT_NE(messageOf<detail::UsageError>([&] { set_bounding_box(box, box, {true}); })
                  .find("error: set_bounding_box needs 2 values for lo, hi and periodic, with hi "
                        "> lo on every axis"),
              std::string::npos);
  EXPECT_THROW(set_bounding_box({0.0, 1.0}, {1.0, 1.0}, {false, false}), detail::UsageError);
}

TEST_F(RunTest, SettingsAreKeptForTheRun) {
  set_precision("float");
  set_simulation_name("sim");
  EXPECT_EQ(runSettings().outputBaseName(), "sim");
  set_output_file_name("frames");
  EXPECT_EQ(runSettings().outputBaseName(), "frames");
  set_bounding_box({0.0, -1.0}, {2.0, 1.0}, {true, false});
  EXPECT_EQ(runSettings().useFloat, true);
  EXPECT_EQ(runSettings().maxIterations, 4u);
  EXPECT_TRUE(runSettings().box.defined && runSettings().box.periodic[0]);
  EXPECT_EQ(runSettings().box.lo[1], -1.0);
}

TEST_F(RunTest, StartUpChecksTheNeighbourRuleAndTheIterationCount) {
  set_smoothing_length_support(2.0);
  EXPECT_EQ(messageOf<detail::RunError>([] { detail::Run(serial2d, true); }),
            "both set_influence_radius and set_smoothing_length_support were called; a "
            "simulation uses one neighbour rule");
  runSettings().search = {};
  EXPECT_EQ(messageOf<detail::RunError>([] { detail::Run(untranslated, true); }),
            "no neighbour rule: call wash::set_influence_radius or "
            "wash::set_smoothing_length_support before start()");
  set_influence_radius(0.5);
  runSettings().maxIterations.reset();
  EXPECT_EQ(messageOf<detail::RunError>([] { detail::Run(serial2d, true); }),
            "no iteration count: call wash::set_max_iterations or pass --steps N (or give an end "
            "time: wash::set_end_time or --end-time T)");
  programOptions().steps = 7; // --steps overrides set_max_iterations
  set_max_iterations(4);
  EXPECT_EQ(detail::Run(serial2d, true).steps(), 7u);
  EXPECT_EQ(detail::Run(serial2d, true).radius(), 0.5);
}

TEST_F(RunTest, APeriodicBoxMustBeLongerThanTwiceTheRadius) {
  set_bounding_box({0.0, 0.0}, {2.0, 0.9}, {false, true});
  EXPECT_EQ(messageOf<detail::RunError>([] { detail::Run(serial2d, true); }),
            "a periodic box must be longer than twice the influence radius (axis 1)");
}

TEST_F(RunTest, ATranslatedProgramRunsOnlyWhatItWasTranslatedFor) {
  set_precision("float");
  EXPECT_EQ(messageOf<detail::RunError>([] { detail::Run(serial2d, true); }),
            "this program was translated for double precision, but main asked for float; call "
            "set_precision unconditionally in main");
  runSettings().useFloat.reset();
  // `if (argc > 5) set_precision("float");` is translated for float: a run
  // that skips the call would store doubles in the reference.
  const Translation forFloat{.backend = "serial", .dimensions = 2, .floatStorage = true};
  EXPECT_EQ(messageOf<detail::RunError>([&] { detail::Run(forFloat, true); }),
            "this program was translated for float precision, but main did not call "
            "set_precision(\"float\") in this run; call set_precision unconditionally in main");
  set_precision("float");
  EXPECT_NO_THROW(detail::Run(forFloat, true));
  runSettings().useFloat.reset();
  runSettings().search = {.support = 2.0};
  EXPECT_EQ(messageOf<detail::RunError>([] { detail::Run(serial2d, true); }),
            "this program was translated for an influence-radius neighbour search, but main "
            "asked for smoothing lengths; call the neighbour-rule setting unconditionally in main");
}

TEST_F(RunTest, TheSupportRuleIsKeptAndMustMatchTheTranslation) {
  runSettings().search = {};
  set_smoothing_length_support(2.0);
  EXPECT_FALSE(runSettings().search.symmetric); // Support::Gather by default
  set_smoothing_length_support(2.0, Support::Symmetric);
  EXPECT_TRUE(runSettings().search.symmetric);
  EXPECT_EQ(runSettings().search.describe(),
            "support radius 2h (pairs within the larger smoothing length)");
  const Translation gather{.backend = "serial", .dimensions = 2, .smoothingLengthSearch = true};
  const Translation symmetric{.backend = "serial",
                              .dimensions = 2,
                              .smoothingLengthSearch = true,
                              .symmetricSupport = true};
  EXPECT_EQ(messageOf<detail::RunError>([&] { detail::Run(gather, true); }),
            "this program was translated for the gather support rule, but main asked for "
            "wash::Support::Symmetric; call the neighbour-rule setting unconditionally in main");
  EXPECT_EQ(detail::Run(symmetric, true).support(), 2.0);
  set_smoothing_length_support(2.0, Support::Gather);
  EXPECT_EQ(messageOf<detail::RunError>([&] { detail::Run(symmetric, true); }),
            "this program was translated for the symmetric support rule, but main asked for "
            "wash::Support::Gather; call the neighbour-rule setting unconditionally in main");
  EXPECT_NE(messageOf<detail::UsageError>([] {
              set_smoothing_length_support(2.0, static_cast<Support>(7));
            }).find("error: the support rule must be wash::Support::Gather or "
                    "wash::Support::Symmetric"),
            std::string::npos);
}

TEST_F(RunTest, TheReferenceRunsWhateverMainAsksFor) {
  set_precision("float");
  runSettings().search = {.support = 2.0};
  detail::Run run(untranslated, true);
  EXPECT_EQ(run.support(), 2.0);
}

TEST_F(RunTest, HeaderAndSummaryLines) {
  programOptions().quiet = false;
  set_simulation_name("lines");
  set_precision("float");
  detail::Frame frame;
  frame.ids = {0, 1, 2};
  frame.columns.push_back({"pos", 2, {0.0, 0.0, 1.0, 0.0, 2.0, 0.0}});
  testing::internal::CaptureStdout();
  {
    detail::Run run(untranslated, true);
    run.begin(3, [&] { return frame; });
    for (std::uint64_t step = 1; step <= run.steps(); ++step)
      run.endStep(step, [&] { return frame; });
    run.finish(frame);
  }
  std::string text = testing::internal::GetCapturedStdout();
  EXPECT_TRUE(text.starts_with("wash reference: 'lines', 3 particles, 2D, float, influence "
                               "radius 0.5, 4 steps\nwash: 4 steps of 3 particles in "))
      << text;
  // Wall and CPU time of the steps, each per particle-step, and whose CPU.
  EXPECT_TRUE(
      std::regex_search(text, std::regex("; steps alone [0-9]+\\.[0-9]{3} s, [0-9]+\\.[0-9] ns "
                                         "per particle-step wall, CPU [0-9]+\\.[0-9]{3} s, "
                                         "[0-9]+\\.[0-9] ns per particle-step \\(this "
                                         "process, 1 thread\\); output in ")))
      << text;
  EXPECT_NE(
      text.find(" ns per particle-step (this process, 1 thread); output in " + out.string() + "\n"),
      std::string::npos)
      << text;
  EXPECT_EQ(text.find("profile"), std::string::npos) << text; // only with --profile
}

TEST_F(RunTest, TheProfileTablesEveryPhase) {
  detail::profiling = true;
  set_simulation_name("lines");
  detail::Frame frame;
  frame.ids = {0, 1, 2};
  frame.columns.push_back({"pos", 2, {0.0, 0.0, 1.0, 0.0, 2.0, 0.0}});
  testing::internal::CaptureStdout();
  {
    detail::Run run(untranslated, true);
    run.begin(3, [&] { return frame; });
    for (std::uint64_t step = 1; step <= run.steps(); ++step) {
      run.kernel("Density");
      {
        const detail::ProfileScope search("neighbour search");
      }
      run.kernel("Move");
      run.endStep(step, [&] { return frame; });
    }
    run.finish(frame);
  }
  detail::profiling = false;
  const std::string text = testing::internal::GetCapturedStdout(); // quiet: the table alone
  EXPECT_TRUE(text.starts_with("wash: profile of 4 steps (this process)\n")) << text;
  EXPECT_TRUE(std::regex_search(text, std::regex("\n  phase +calls +wall s +ms/step +% wall +"
                                                 "ns/particle +CPU s\n")))
      << text;
  // One row per phase, in the order they first ran, with its calls.
  EXPECT_TRUE(std::regex_search(
      text, std::regex("\n  \\(before the first kernel\\) +1 .*\n  Density +4 .*\n  neighbour "
                       "search +4 .*\n  Move +4 .*\n  \\(end of step: time, progress\\) +4 .*\n  "
                       "output \\(frames\\) +1 .*\n  total +18 ")))
      << text;
  EXPECT_EQ(text.find("ns per particle-step"), std::string::npos) << text;
}

TEST_F(RunTest, BusyCoresAreToldFromIdleThreads) {
  EXPECT_FALSE(detail::coresWereBusy(1.9, 1.0, 2, 5));      // every thread ran
  EXPECT_FALSE(detail::coresWereBusy(1.0, 1.0, 2, 5));      // one slept: serial work
  EXPECT_TRUE(detail::coresWereBusy(1.0, 1.0, 2, 400));     // preempted again and again
  EXPECT_TRUE(detail::coresWereBusy(13.0, 56.0, 2, 20000)); // the issue's run
  EXPECT_FALSE(detail::coresWereBusy(0.0, 0.0, 1, 0));
}

TEST_F(RunTest, AStopEndsTheRunAtThatStep) {
  detail::Run run(serial2d, /*writes=*/false);
  run.begin(0, [] { return detail::Frame{}; });
  run.endStep(1, [] { return detail::Frame{}; });
  EXPECT_EQ(run.steps(), 4u);
  runSettings().stopRequested = true;
  run.endStep(2, [] { return detail::Frame{}; });
  EXPECT_EQ(run.steps(), 2u);
  EXPECT_FALSE(std::filesystem::exists(out)) << "a run that does not write made its directory";
}

TEST_F(RunTest, NonFiniteValuesNameStepKernelFieldAndParticle) {
  detail::Run run(serial2d, true);
  std::vector<Vec2D> vel{{1.0, 2.0}, {3.0, -std::numeric_limits<double>::infinity()}};
  std::vector<std::uint64_t> ids{7, 9};
  std::vector<std::uint32_t> rows{0, 1};
  EXPECT_EQ(messageOf<detail::RunError>([&] { run.checkFinite(vel, ids, rows, 3, "push", "vel"); }),
            "step 3: after kernel 'push': field 'vel' of particle 9 is -inf");
  detail::Frame frame;
  frame.ids = ids;
  frame.columns.push_back({"density", 1, {1.0, std::nan("")}});
  EXPECT_EQ(messageOf<detail::RunError>([&] { run.checkFinite(frame, 0, "init"); }),
            "step 0: after kernel 'init': field 'density' of particle 9 is nan");
}

TEST_F(RunTest, TheTimeAdvancesByTheTimeStepAfterEachIteration) {
  detail::Run run(serial2d, /*writes=*/false);
  run.begin(0, [] { return detail::Frame{}; });
  EXPECT_EQ(get_time(), 0.0);
  EXPECT_EQ(get_time_step(), 0.0);
  run.endStep(1, [] { return detail::Frame{}; });
  EXPECT_EQ(get_time(), 0.0) << "no time step set: the time stays 0";
  set_time_step(0.25);
  run.endStep(2, [] { return detail::Frame{}; });
  detail::setReducedTimeStep(0.5); // a reduction kernel targeting "time_step"
  run.endStep(3, [] { return detail::Frame{}; });
  EXPECT_EQ(get_time(), 0.75);
  EXPECT_EQ(get_time_step(), 0.5);
  EXPECT_EQ(run.steps(), 4u);
}

TEST_F(RunTest, TheEndTimeEndsTheRunAtTheIterationThatReachesIt) {
  runSettings().maxIterations.reset(); // an end time needs no iteration count
  set_end_time(1.0);
  EXPECT_EQ(get_end_time(), 1.0);
  programOptions().endTime = 0.5; // --end-time overrides it
  EXPECT_EQ(get_end_time(), 0.5);
  detail::Run run(serial2d, /*writes=*/false);
  EXPECT_EQ(run.steps(), std::numeric_limits<std::uint64_t>::max());
  run.begin(0, [] { return detail::Frame{}; });
  set_time_step(0.2);
  for (std::uint64_t step = 1; step <= run.steps(); ++step)
    run.endStep(step, [] { return detail::Frame{}; });
  EXPECT_EQ(run.steps(), 3u) << "0.2, 0.4, 0.6: the third step reaches 0.5";
  EXPECT_DOUBLE_EQ(get_time(), 0.6);
}

TEST_F(RunTest, ATimeThatStopsShortOfTheOnlyEndIsAnError) {
  runSettings().maxIterations.reset();
  programOptions().endTime = 1.0;
  detail::Run run(serial2d, /*writes=*/false);
  run.begin(0, [] { return detail::Frame{}; });
  const std::string msg =
      messageOf<detail::RunError>([&] { run.endStep(1, [] { return detail::Frame{}; }); });
  EXPECT_NE(msg.find("at the end of step 1: the simulated time did not advance (t = 0, time "
                     "step 0, never set) and the run ends only at t = 1: it would never end"),
            std::string::npos)
      << msg;
  // A step set but too small for the time to notice is the same, after 100
  // steps in a row (a step a reduction computes may be 0 at first: Sedov's).
  detail::simTime().time = 1e-3;
  set_time_step(1e-30);
  for (std::uint64_t step = 2; step < 100; ++step)
    EXPECT_NO_THROW(run.endStep(step, [] { return detail::Frame{}; })) << step;
  const std::string stuck =
      messageOf<detail::RunError>([&] { run.endStep(100, [] { return detail::Frame{}; }); });
  EXPECT_NE(stuck.find("at the end of step 100: the simulated time did not advance in 100 steps "
                       "(t = 0.001, time step 1.0000000000000001e-30)"),
            std::string::npos)
      << stuck;
}

TEST_F(RunTest, ATimeStepOfZeroAtFirstIsNoError) {
  runSettings().maxIterations.reset();
  programOptions().endTime = 0.5;
  detail::Run run(serial2d, /*writes=*/false);
  run.begin(0, [] { return detail::Frame{}; });
  set_time_step(0.0); // as a reduction over a state at rest gives it
  run.endStep(1, [] { return detail::Frame{}; });
  set_time_step(0.25);
  for (std::uint64_t step = 2; step <= run.steps(); ++step)
    run.endStep(step, [] { return detail::Frame{}; });
  EXPECT_EQ(run.steps(), 3u) << "0, 0.25, 0.5";
  EXPECT_DOUBLE_EQ(get_time(), 0.5);
}

TEST_F(RunTest, TimeOptionsPastTwoToThe53MultiplesAreErrors) {
  EXPECT_EQ(detail::multiplesIn(0.5, 0.1, "--output-dt"), 5u);
  EXPECT_EQ(detail::multiplesIn(0.0, 1e-300, "--output-dt"), 0u);
  const std::string msg =
      messageOf<detail::RunError>([] { detail::multiplesIn(0.01, 1e-22, "--output-dt"); });
  EXPECT_NE(msg.find("multiples of --output-dt 1e-22, more than 2^53"), std::string::npos) << msg;
  programOptions().outputDt = 1e-22;
  detail::Run run(serial2d, /*writes=*/false);
  run.begin(0, [] { return detail::Frame{}; });
  set_time_step(0.01);
  EXPECT_THROW(run.endStep(1, [] { return detail::Frame{}; }), detail::RunError);
}

TEST_F(RunTest, BadTimeStepsAreErrors) {
  const int line = __LINE__ + 1;
  std::string msg = messageOf<detail::UsageError>([] { set_time_step(-1.0); });
  EXPECT_NE(msg.find("run_test.cpp:" + std::to_string(line) + ":"), std::string::npos) << msg;
  EXPECT_NE(msg.find(": error: wash::set_time_step: the time step is -1; it must be finite and "
                     "not negative"),
            std::string::npos)
      << msg;
  EXPECT_THROW(set_time_step(std::numeric_limits<double>::infinity()), detail::UsageError);
  EXPECT_THROW(set_end_time(std::nan("")), detail::UsageError);
  // A reduction over no particles gives +inf: the run stops at the end of the step.
  detail::Run run(serial2d, /*writes=*/false);
  run.begin(0, [] { return detail::Frame{}; });
  detail::setReducedTimeStep(std::numeric_limits<double>::infinity());
  EXPECT_EQ(messageOf<detail::RunError>([&] { run.endStep(1, [] { return detail::Frame{}; }); }),
            "at the end of step 1: the time step is inf; it must be finite and not negative");
  EXPECT_THROW(add_variable("time_step", 0.0), detail::UsageError);
}

TEST_F(RunTest, TheProgressLineShowsTheSimulatedTime) {
  EXPECT_EQ(detail::Progress::timeLine(10, std::numeric_limits<std::uint64_t>::max(), 0.0125, 0.05,
                                       3.2e6, 4.0),
            "step 10  t = 0.0125 of 0.05  3.2e+06 particles/s  ETA 4 s");
  EXPECT_EQ(detail::Progress::timeLine(10, 100, 0.5, std::nullopt, 3.2e6, 4.0),
            "step 10/100  t = 0.5  3.2e+06 particles/s  ETA 4 s");
  EXPECT_EQ(detail::Progress::line(10, 100, 3.2e6, 4.0),
            "step 10/100  3.2e+06 particles/s  ETA 4 s");
}
