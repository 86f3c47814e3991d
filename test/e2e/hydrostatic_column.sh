# Adami walls hold a water column at rest: dam_break_2d in a tank as wide as
# its column (n = 20, 2L high) settles for t = 0.5 s (about 16 acoustic
# crossings of the column), and then the pressure, averaged over bands 0.2 L
# deep, is within 2 % of rho g d at the band's mean depth d below the
# surface for every band at least 0.5 L deep, and within 2 % of rho g H for
# every band. The fluid is then nearly still (speeds under 1 % of sqrt(gH)).
. "$(dirname "$0")/lib.sh"
bin=$1 backend=${2:-serial}

expect_exit 0 "$bin/dam_break_2d-$backend" 20 1 --end-time 0.5 --quiet --dump column.csv --out run
/usr/bin/python3 - column.csv <<'PY' || fail "the column's pressure is not hydrostatic (above)"
import csv, math, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["type"] == "0"]  # type 0: fluid
rho0, g, H, dx = 1000.0, 9.81, 2.0, 1.0 / 20
surface = max(float(r["y"]) for r in rows) + 0.5 * dx
speed = max(math.hypot(float(r["vx"]), float(r["vy"])) for r in rows)
print(f"{len(rows)} fluid particles, surface at y = {surface:.4f}, fastest {speed:.2e} m/s")
ok = abs(surface - H) < 0.5 * dx and speed < 0.01 * math.sqrt(g * H)
for k in range(10):
    band = [r for r in rows if 0.2 * k <= float(r["y"]) < 0.2 * (k + 1)]
    P = sum(float(r["pressure"]) for r in band) / len(band)
    d = sum(surface - float(r["y"]) for r in band) / len(band)
    err, of_max = P / (rho0 * g * d) - 1.0, (P - rho0 * g * d) / (rho0 * g * H)
    band_ok = abs(of_max) < 0.02 and (d < 0.5 or abs(err) < 0.02)
    ok = ok and band_ok
    print(f"y in [{0.2 * k:.1f}, {0.2 * (k + 1):.1f}): depth {d:.3f}, P = {P:.1f}, rho g d = {rho0 * g * d:.1f},"
          f" {100 * err:+.2f} % {'ok' if band_ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
echo "hydrostatic column ($backend): Adami walls hold rho g h within 2 %"
