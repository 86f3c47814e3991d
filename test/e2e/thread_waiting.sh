# On a shared machine (WASH_SHARED_MACHINE=1) an OpenMP program's waiting
# threads spin only briefly (docs/backends.md, "Threads on a shared
# machine"): at 2 threads the OpenMP runtime runs with GOMP_SPINCOUNT=1000
# unless the user set a policy, which is kept; at 1 thread, or without the
# variable (idle cores, where the spin pays), nothing is executed again. The
# results do not change.
#   thread_waiting.sh BIN
. "$(dirname "$0")/lib.sh"
bin=$1
p=$bin/ca_fluid_sim-openmp

# shown SETTING: the OpenMP runtime's OMP_DISPLAY_ENV lines hold SETTING.
shown() { grep -qF -- "$1" out.txt || { cat out.txt >&2; fail "the OpenMP runtime ran without $1"; }; }

export WASH_SHARED_MACHINE=1
OMP_NUM_THREADS=2 OMP_DISPLAY_ENV=verbose expect_exit 0 "$p" --steps 2 --quiet --dump bounded.csv
if ! grep -q "GOMP_SPINCOUNT = " out.txt; then
  echo "not libgomp: its settings are not shown; the results alone are checked"
else
  shown "GOMP_SPINCOUNT = '1000'"
  OMP_NUM_THREADS=2 OMP_DISPLAY_ENV=verbose OMP_WAIT_POLICY=active expect_exit 0 "$p" --steps 2 --quiet
  shown "OMP_WAIT_POLICY = 'ACTIVE'"
  grep -qF "GOMP_SPINCOUNT = '1000'" out.txt && fail "the user's OMP_WAIT_POLICY=active was overridden"
  OMP_NUM_THREADS=2 OMP_DISPLAY_ENV=verbose GOMP_SPINCOUNT=5 expect_exit 0 "$p" --steps 2 --quiet
  shown "GOMP_SPINCOUNT = '5'"
  # One thread waits for nothing: one start, the runtime's defaults.
  OMP_NUM_THREADS=1 OMP_DISPLAY_ENV=true expect_exit 0 "$p" --steps 2 --quiet
  [ "$(grep -c "OPENMP DISPLAY ENVIRONMENT BEGIN" out.txt)" -eq 1 ] ||
    { cat out.txt >&2; fail "a 1-thread run was executed again"; }
  # Idle cores: the runtime's own spin, one start.
  WASH_SHARED_MACHINE= OMP_NUM_THREADS=2 OMP_DISPLAY_ENV=verbose expect_exit 0 "$p" --steps 2 --quiet
  grep -qF "GOMP_SPINCOUNT = '1000'" out.txt && fail "the spin was bounded without WASH_SHARED_MACHINE"
  [ "$(grep -c "OPENMP DISPLAY ENVIRONMENT BEGIN" out.txt)" -eq 1 ] ||
    { cat out.txt >&2; fail "a run without WASH_SHARED_MACHINE was executed again"; }
fi
OMP_NUM_THREADS=1 expect_exit 0 "$p" --steps 2 --quiet --dump one.csv
cmp -s bounded.csv one.csv || fail "the dump at 2 threads with the bounded spin differs from 1 thread's"
echo "thread waiting: ok"
