# Reads the per-step lines of closed_box (step=S time=T energy=E kinetic=K
# momentum_x=PX momentum_y=PY; other lines are ignored) and prints one line of
# key=value drift measures:
#   steps                  number of step lines (they must be 1, 2, ..., steps)
#   energy0, kinetic0      total and kinetic energy of the initial state (step 1)
#   energy_drift           max over steps of |E(s) - E(1)| / E(1)
#   energy_step_drift      max over steps of |E(s) - E(s-1)| / E(1)
#   late_energy_drift      max over the second half, s >= late, of |E(s) - E(late)| / E(1),
#                          late = steps / 2 + 1 (after the shocks have died down)
#   momentum_drift         max over steps and axes of |P(s) - P(1)| (the scene's
#                          momentum unit is total mass x initial sound speed = 1)
#   kinetic_ratio          K(last) / K(1): how much kinetic energy became heat
#   time                   simulated time of the last step
# With -v csv=FILE it also writes the lines as CSV with the drifts per step.
# Exits 1 if the step numbers are not consecutive from 1 or a value is not a number.
function abs(x) { return x < 0 ? -x : x }
/^step=/ {
  for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
  for (k in v) if (v[k] !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) { print "bad value " k "=" v[k] " in: " $0 > "/dev/stderr"; bad = 1; exit 1 }
  n++
  if (v["step"] + 0 != n) { print "step " v["step"] " where " n " was expected" > "/dev/stderr"; bad = 1; exit 1 }
  S[n] = v["step"]; T[n] = v["time"]; E[n] = v["energy"] + 0; K[n] = v["kinetic"] + 0
  PX[n] = v["momentum_x"] + 0; PY[n] = v["momentum_y"] + 0
}
END {
  if (bad) exit 1
  if (n == 0) { print "no step lines" > "/dev/stderr"; exit 1 }
  late = int(n / 2) + 1
  if (csv != "") print "step,time,energy,kinetic,momentum_x,momentum_y,energy_drift,momentum_x_drift,momentum_y_drift" > csv
  for (s = 1; s <= n; s++) {
    d = abs(E[s] - E[1]) / E[1]; if (d > ed) ed = d
    if (s > 1) { d = abs(E[s] - E[s - 1]) / E[1]; if (d > esd) esd = d }
    if (s >= late) { d = abs(E[s] - E[late]) / E[1]; if (d > led) led = d }
    d = abs(PX[s] - PX[1]); if (d > pd) pd = d
    d = abs(PY[s] - PY[1]); if (d > pd) pd = d
    if (csv != "")
      printf "%s,%s,%.17g,%.17g,%.17g,%.17g,%.6e,%.6e,%.6e\n", S[s], T[s], E[s], K[s], PX[s], PY[s],
        (E[s] - E[1]) / E[1], PX[s] - PX[1], PY[s] - PY[1] > csv
  }
  printf "steps=%d time=%.6g energy0=%.17g kinetic0=%.17g energy_drift=%.3e energy_step_drift=%.3e late_energy_drift=%.3e momentum_drift=%.3e kinetic_ratio=%.4f\n",
    n, T[n], E[1], K[1], ed, esd, led, pd, K[n] / K[1]
}
