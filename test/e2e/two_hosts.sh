# The mpi program on two "hosts": two network namespaces on this machine joined
# by a veth pair. mpirun runs in namespace A; its launch agent enters namespace
# B (ip netns exec) where a real cluster would ssh, and Open MPI may use TCP
# over the veth only (no shared memory between the hosts). At 2 ranks (one per
# host) and 4 (two per host) the --dump must equal the serial program's, byte
# for byte, every rank must report the namespace it ran in, and the veth must
# have carried the traffic. Needs root, iproute2 and Open MPI: without them,
# or without the permission to make namespaces, the test reports itself
# skipped (77), never passed.
. "$(dirname "$0")/lib.sh"
mpiexec=$1 bin=$2 example=${3:-ca_fluid_sim} steps=${4:-20}

skip() { echo "two hosts: $*; skipped"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "network namespaces need root"
command -v ip >/dev/null || skip "no 'ip' command (iproute2)"
"$mpiexec" --version 2>/dev/null | grep -qE "Open MPI|OpenRTE" || skip "$mpiexec is not Open MPI's (its --mca options)"

ns_a=wash-a-$$ ns_b=wash-b-$$
addr_a=10.213.0.1 addr_b=10.213.0.2
cleanup() {
  local ns
  for ns in "$ns_a" "$ns_b"; do
    # Processes left in a namespace (a hung orted) are ours: stop them first.
    ip netns pids "$ns" 2>/dev/null | xargs -r kill -9 2>/dev/null
    ip netns del "$ns" 2>/dev/null # takes its end of the veth pair with it
  done
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 143' TERM INT HUP # so that the namespaces go even then
ip netns add "$ns_a" 2>netns.err || skip "cannot create a network namespace: $(cat netns.err)"
ip netns add "$ns_b" 2>netns.err || skip "cannot create a network namespace: $(cat netns.err)"
# The veth ends are created inside the namespaces, so their names never meet
# those of other runs or of the machine.
ip link add veth-a netns "$ns_a" type veth peer name veth-b netns "$ns_b" 2>netns.err ||
  skip "cannot create a veth pair: $(cat netns.err)"
ip -n "$ns_a" addr add "$addr_a/24" dev veth-a || fail "cannot address veth-a"
ip -n "$ns_b" addr add "$addr_b/24" dev veth-b || fail "cannot address veth-b"
ip -n "$ns_a" link set lo up && ip -n "$ns_a" link set veth-a up || fail "cannot bring up $ns_a's links"
ip -n "$ns_b" link set lo up && ip -n "$ns_b" link set veth-b up || fail "cannot bring up $ns_b's links"
ip netns exec "$ns_a" true 2>netns.err || skip "cannot enter a network namespace: $(cat netns.err)"

# Open MPI calls the agent as ssh: "agent [ssh options] host command words...",
# the words being one shell command line.
cat >agent.sh <<EOF
#!/bin/sh
while [ \$# -gt 0 ]; do
  case \$1 in
    -[bcDeEFIiJLlmOopQRSWw]) shift 2 ;; # ssh options taking an argument
    -*) shift ;;
    *) break ;;
  esac
done
host=\$1; shift
case \$host in
  $addr_a) ns=$ns_a ;;
  $addr_b) ns=$ns_b ;;
  *) echo "agent: unknown host '\$host'" >&2; exit 255 ;;
esac
echo "\$host \$*" >>"$work/agent.log"
exec ip netns exec "\$ns" sh -c "\$*"
EOF
# Each rank notes where it ran, then becomes the program.
cat >rank.sh <<EOF
#!/bin/sh
echo "\$OMPI_COMM_WORLD_RANK \$(ip netns identify)" >"$work/where.\$OMPI_COMM_WORLD_RANK"
exec "\$@"
EOF
chmod +x agent.sh rank.sh
printf '%s slots=2\n%s slots=2\n' "$addr_a" "$addr_b" >hostfile

veth_bytes() { # NS DEV: bytes the device has sent
  ip netns exec "$1" cat "/sys/class/net/$2/statistics/tx_bytes"
}

expect_exit 0 "$bin/$example-serial" --steps "$steps" --quiet --dump serial.csv --out serial
for ranks in 2 4; do
  rm -f where.*
  sent_a=$(veth_bytes "$ns_a" veth-a) sent_b=$(veth_bytes "$ns_b" veth-b)
  OMP_NUM_THREADS=1 expect_exit 0 timeout 120 ip netns exec "$ns_a" "$mpiexec" --allow-run-as-root \
    -np "$ranks" --hostfile hostfile --map-by node --bind-to none \
    --mca plm_rsh_agent "$work/agent.sh" \
    --mca btl tcp,self --mca btl_tcp_if_include 10.213.0.0/24 --mca oob_tcp_if_include 10.213.0.0/24 \
    -x OMP_NUM_THREADS \
    "$work/rank.sh" "$bin/$example-mpi" --steps "$steps" --quiet --dump "mpi-$ranks.csv" --out "mpi-$ranks"
  cmp -s serial.csv "mpi-$ranks.csv" ||
    fail "$example-mpi on $ranks ranks over two hosts differs from serial after $steps steps: $(cmp serial.csv "mpi-$ranks.csv")"
  # --map-by node: even ranks on the first host (A), odd ones on B.
  for ((r = 0; r < ranks; r++)); do
    want=$ns_a; ((r % 2)) && want=$ns_b
    [ "$(cat "where.$r" 2>/dev/null)" = "$r $want" ] ||
      fail "rank $r of $ranks ran in '$(cat "where.$r" 2>/dev/null)', expected namespace $want"
  done
  grep -q "^$addr_b " agent.log || fail "mpirun did not launch host B through the agent"
  grep -q "^$addr_a " agent.log && fail "mpirun launched its own host A through the agent"
  grown_a=$(($(veth_bytes "$ns_a" veth-a) - sent_a)) grown_b=$(($(veth_bytes "$ns_b" veth-b) - sent_b))
  # The halo of a 20-step run is well over 100 kB each way.
  [ "$grown_a" -gt 100000 ] && [ "$grown_b" -gt 100000 ] ||
    fail "veth carried only $grown_a bytes A to B and $grown_b bytes B to A at $ranks ranks"
  echo "$ranks ranks: identical to serial; veth carried $grown_a bytes A to B, $grown_b B to A"
done
echo "$example: mpi on two hosts (network namespaces) at 2 and 4 ranks identical to serial after $steps steps"
