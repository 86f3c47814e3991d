# Translator faults and misuse (issue #31), one mode per test:
#   overwrite  wash never writes over an input, a file it did not write, or a
#              generated file the user edited; links are written through
#   include    an #include of a FIFO, /dev/stdin or /dev/zero is an error at
#              the #include, within a bound, not a hang or an empty file
#   stdout     a failed write to standard output is an error, exit 1
#   names      a simulation name no build can name is refused before anything
#              is written (make would expand '$(touch x)')
. "$(dirname "$0")/lib.sh"
wash=$1/wash mode=$2

# simulation FILE [LINE]: a small simulation, LINE (an #include) atop it.
simulation() {
  { [ $# -gt 1 ] && echo "$2"; cat <<'CPP'
#include <wash/wash.hpp>
void Heat(wash::Particle& p) { p.set_density(p.get_density() * 2.0); }
int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Heat);
  wash::set_max_iterations(1);
  wash::start();
}
CPP
  } > "$1"
}

case $mode in
overwrite)
  simulation sim.cpp
  cp sim.cpp sim.orig
  expect_exit 1 "$wash" sim.cpp -o p --depfile sim.cpp
  expect_in out.txt "is a file the translation reads"
  cmp -s sim.cpp sim.orig || fail "--depfile sim.cpp changed the simulation"
  expect_exit 1 "$wash" --force sim.cpp -o p --depfile sim.cpp
  cmp -s sim.cpp sim.orig || fail "--force --depfile sim.cpp changed the simulation"
  expect_exit 0 "$wash" sim.cpp -o p --depfile p.d
  echo "// mine" >> p/sim.wash.hpp
  expect_exit 1 "$wash" sim.cpp -o p --depfile p.d
  expect_in out.txt "p/sim.wash.hpp' was written by wash but has changed since"
  grep -qx "// mine" p/sim.wash.hpp || fail "an edited generated file was overwritten"
  echo mine > notes.txt
  expect_exit 1 "$wash" sim.cpp -o p --depfile notes.txt
  grep -qx mine notes.txt || fail "a file wash did not write was overwritten by the depfile"
  expect_exit 0 "$wash" --force sim.cpp -o p --depfile p.d
  ln -s p link
  expect_exit 0 "$wash" --backend=openmp sim.cpp -o link
  [ -L link ] || fail "-o at a symbolic link replaced the link"
  [ -f p/sim.openmp.cpp ] || fail "-o at a symbolic link did not write through it"
  ;;
include)
  mkfifo fifo.h
  for included in /dev/stdin /proc/self/fd/0 "$work/fifo.h" /dev/zero; do
    simulation sim.cpp "#include \"$included\""
    timeout 60 "$wash" --dump-model sim.cpp > out.txt 2>&1 < /dev/null
    got=$?
    [ $got -eq 124 ] && fail "#include \"$included\" hung the translator"
    [ $got -eq 1 ] || { cat out.txt >&2; fail "#include \"$included\" exited $got, expected 1"; }
    expect_in out.txt "sim.cpp:1:10: fatal error: cannot open file '$included': it is not a regular file"
  done
  ;;
stdout)
  simulation sim.cpp
  "$wash" --dump-model sim.cpp > /dev/full 2> err.txt && fail "--dump-model > /dev/full exited 0"
  expect_in err.txt "wash: error: cannot write to standard output: No space left on device"
  ;;
names)
  for name in 'a;b' 'q"uote' "$(printf 'a\tb')" "$(printf 'a\nb')" 'x$(touch expanded)'; do
    simulation "$name.cpp"
    expect_exit 1 "$wash" "$name.cpp" -o project
    expect_in out.txt "which the generated project's build (CMake, make, Ninja) cannot name"
    [ -e project ] && fail "'$name.cpp' was refused but a project was written"
  done
  [ -e expanded ] && fail "a file name was expanded"
  ;;
*) fail "unknown mode '$mode'" ;;
esac
exit 0
