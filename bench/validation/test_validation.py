#!/usr/bin/python3
"""Self-test of the Sedov/Noh exact solutions and compare.py.

Run: /usr/bin/python3 bench/validation/test_validation.py
Exit status 0 when every check passes; the last line is "N passed, M failed".
"""

import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.integrate import simpson

sys.dont_write_bytecode = True  # keep the source tree clean
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare  # noqa: E402
import noh  # noqa: E402
import sedov  # noqa: E402

GAMMA = 5.0 / 3.0
results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    print("%s  %s%s" % ("PASS" if ok else "FAIL", name, ("  (" + detail + ")") if detail else ""))
    return ok


def close(name, got, want, rtol=0.0, atol=0.0):
    ok = bool(np.all(np.abs(np.asarray(got) - want) <= atol + rtol * abs(want)))
    return check(name, ok, "got %.10g, want %.10g" % (np.max(got) if np.ndim(got) else got, want))


# --- Sedov -------------------------------------------------------------------

def test_sedov():
    xi0 = sedov.shock_constant(GAMMA)
    close("sedov: shock constant xi0 = 1.15167 (gamma=5/3, j=3)", xi0, 1.15167, atol=5e-6)
    check("sedov: shock constant to 4 digits", round(xi0, 4) == 1.1517, "%.6f" % xi0)
    # Kamm (2000) / ExactPack: E = 0.851072 puts the gamma = 1.4 shock at r = 1 at t = 1.
    close("sedov: alpha(gamma=1.4) = 0.851072", sedov.SedovSolution(1.4, 3).alpha, 0.851072,
          rtol=2e-6)
    for t, E, rho0 in ((1.0, 1.0, 1.0), (0.05, 1.0, 1.0), (0.3, 2.0, 0.5)):
        R = sedov.shock_radius(t, E, rho0)
        close("sedov: r_s(t=%g,E=%g,rho0=%g) = xi0 (E t^2/rho0)^(1/5)" % (t, E, rho0), R,
              xi0 * (E * t * t / rho0) ** 0.2, rtol=1e-14)
        us = 0.4 * R / t
        rho, p, v = sedov.sedov_profile(np.array([R * (1 - 1e-12)]), t, E, rho0)
        close("sedov: post-shock density 4 rho0 (t=%g)" % t, rho[0], 4.0 * rho0, rtol=1e-9)
        close("sedov: post-shock pressure 2 rho0 u_s^2/(gamma+1)", p[0],
              2 * rho0 * us * us / (GAMMA + 1), rtol=1e-9)
        close("sedov: post-shock velocity 2 u_s/(gamma+1)", v[0], 2 * us / (GAMMA + 1), rtol=1e-9)
        rho, p, v = sedov.sedov_profile(np.array([R * (1 + 1e-9), 3 * R]), t, E, rho0)
        check("sedov: ambient ahead of the shock", np.all(rho == rho0) and np.all(p == 0)
              and np.all(v == 0))
        # Total energy from the profile, integrated in r independently of the
        # energy integral that fixed xi0 (grid clustered at the shock).
        u = np.linspace(0.0, 1.0, 200001)
        r = R * (1.0 - (1.0 - u) ** 2)
        rho, p, v = sedov.sedov_profile(r, t, E, rho0)
        e = 4 * math.pi * simpson((0.5 * rho * v * v + p / (GAMMA - 1)) * r * r, x=r)
        close("sedov: kinetic + internal energy over the sphere = E (t=%g)" % t, e, E, rtol=1e-4)
    # The closed form must satisfy the Euler equations (mass, momentum,
    # entropy) - an independent check of the exponents.
    t, R = 1.0, sedov.shock_radius(1.0)
    r, eps = np.linspace(0.5, 0.98, 25) * R, 1e-5
    P = sedov.sedov_profile
    rho, p, v = P(r, t)
    (rp, pp, vp), (rm, pm, vm) = P(r * (1 + eps), t), P(r * (1 - eps), t)
    (rt, pt, vt), (rtm, ptm, vtm) = P(r, t * (1 + eps)), P(r, t * (1 - eps))
    dr, dt = 2 * eps * r, 2 * eps * t
    rho_r, v_r, p_r = (rp - rm) / dr, (vp - vm) / dr, (pp - pm) / dr
    rho_t, v_t, p_t = (rt - rtm) / dt, (vt - vtm) / dt, (pt - ptm) / dt
    mass = (rho_t + rho * v_r + v * rho_r + 2 * rho * v / r) / (np.abs(rho_t) + np.abs(v * rho_r))
    mom = (v_t + v * v_r + p_r / rho) / (np.abs(v_t) + np.abs(p_r / rho))
    ent = (p_t / p - GAMMA * rho_t / rho + v * (p_r / p - GAMMA * rho_r / rho)) / np.abs(p_t / p)
    worst = max(np.max(np.abs(mass)), np.max(np.abs(mom)), np.max(np.abs(ent)))
    check("sedov: profile satisfies the Euler equations", worst < 1e-6, "max residual %.2g" % worst)
    lam = np.linspace(0, 1, 2001)[1:]
    rho, p, v = sedov.sedov_profile(lam * R, t)
    check("sedov: density increases, velocity increases outward",
          np.all(np.diff(rho) > 0) and np.all(np.diff(v) > 0))
    rho, p, v = sedov.sedov_profile(np.array([0.0, 1e-8]), t)
    check("sedov: centre: density -> 0, velocity -> 0, pressure finite",
          rho[0] < 1e-30 and abs(v[0]) < 1e-30 and 0.0 < p[0] < 0.5 * p[1] * 3, "%r" % (p,))


# --- Noh -----------------------------------------------------------------------

def test_noh():
    t = 0.6
    rs = noh.shock_radius(t)
    close("noh: shock radius t/3", rs, t / 3, rtol=1e-15)
    rho, p, v = noh.noh_profile(np.array([0.0, 0.5 * rs, rs * (1 - 1e-12)]), t)
    close("noh: post-shock density 64", rho, 64.0, rtol=1e-14)
    close("noh: post-shock pressure 64/3", p, 64.0 / 3, rtol=1e-14)
    close("noh: post-shock velocity 0", v, 0.0, atol=0.0)
    r = np.array([rs * (1 + 1e-12), 0.5, 1.0, 7.0])
    rho, p, v = noh.noh_profile(r, t)
    close("noh: pre-shock density (1 + t/r)^2", rho / (1 + t / r) ** 2, 1.0, rtol=1e-14)
    check("noh: pre-shock v = -1, p = 0", np.all(v == -1.0) and np.all(p == 0.0))
    close("noh: density just ahead of the shock 16", rho[0], 16.0, rtol=1e-9)
    # Rankine-Hugoniot in the shock frame (shock speed t/3 / t = 1/3).
    us = 1.0 / 3.0
    close("noh: mass flux through the shock", 16 * (-1 - us), 64 * (0 - us), rtol=1e-12)
    close("noh: momentum flux through the shock", 16 * (-1 - us) ** 2 + 0.0,
          64 * us ** 2 + 64.0 / 3, rtol=1e-12)


# --- compare.py on synthetic states ---------------------------------------------

def lattice(n, lo, hi, seed):
    s = (hi - lo) / n
    g = lo + (np.arange(n) + 0.5) * s
    pos = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1).reshape(-1, 3)
    rng = np.random.default_rng(seed)
    return pos + rng.uniform(-0.25 * s, 0.25 * s, pos.shape), s


def write_state(path, pos, vel, rho, p, spacing, pressure_name="pressure"):
    n = len(pos)
    mass = np.full(n, spacing ** 3)  # rho0 = 1
    h = np.full(n, 1.2 * spacing)
    u = np.where(rho > 0, p / np.where(rho > 0, rho, 1) / (GAMMA - 1), 0.0)
    cols = [np.arange(n), pos[:, 0], pos[:, 1], pos[:, 2], vel[:, 0], vel[:, 1], vel[:, 2],
            rho, mass, h, u, p]
    header = "id,x,y,z,vx,vy,vz,density,mass,smoothing_length,u," + pressure_name
    np.savetxt(path, np.column_stack(cols), delimiter=",", header=header, comments="",
               fmt=["%d"] + ["%.17g"] * (len(cols) - 1))


def exact_state(pos, profile, center, box):
    state = {"x": pos[:, 0], "y": pos[:, 1], "z": pos[:, 2]}
    d = compare.separations(pos, center, box)
    r = np.sqrt(np.einsum("ij,ij->i", d, d))
    rho, p, vr = profile(r)
    rhat = d / np.where(r > 0, r, 1.0)[:, None]
    return state, rho, p, vr[:, None] * rhat


def run_compare(args):
    cmd = [sys.executable, os.path.join(HERE, "compare.py")] + args
    proc = subprocess.run(cmd, capture_output=True, text=True)
    lines = proc.stdout.strip().splitlines()
    metrics = {}
    if proc.returncode == 0 and lines:
        for kv in lines[-1].split():
            k, v = kv.split("=")
            metrics[k] = float(v)
    return proc, metrics


def test_compare(tmp):
    # Sedov: 50^3 jittered lattice in the unit periodic box, blast at the centre.
    t = 0.05
    R = sedov.shock_radius(t)
    pos, s = lattice(50, 0.0, 1.0, seed=1)
    _, rho, p, vel = exact_state(pos, lambda r: sedov.sedov_profile(r, t), [0.5] * 3, 1.0)
    f = os.path.join(tmp, "sedov_exact.csv")
    write_state(f, pos, vel, rho, p, s)
    png = os.path.join(tmp, "sedov.png")
    t0 = time.time()
    proc, m = run_compare([f, "--problem", "sedov", "--time", str(t), "--box", "1",
                           "--plot", png, "--label", "synthetic exact Sedov"])
    print("     compare.py sedov: %.1f s; %s" % (time.time() - t0, proc.stdout.strip().splitlines()[-1]
                                                   if proc.stdout.strip() else proc.stderr))
    if not check("compare sedov exact: runs", proc.returncode == 0 and "particles" in m,
                 proc.stderr.strip()[-300:]):
        return
    check("compare sedov exact: particles = 125000", m["particles"] == 125000)
    for k in ("l1_density", "l1_density_norm", "l1_pressure_norm", "l1_velocity_norm"):
        check("compare sedov exact: %s < 1e-6" % k, m[k] < 1e-6, "%g" % m[k])
    close("compare sedov exact: shock_radius_exact", m["shock_radius_exact"], R, rtol=1e-5)
    check("compare sedov exact: |shock_radius_error| < 2%", abs(m["shock_radius_error"]) < 0.02,
          "%g" % m["shock_radius_error"])
    check("compare sedov exact: binned peak close to 4", 0.8 < m["peak_density_ratio"] <= 1.0,
          "%g" % m["peak_density_ratio"])
    check("compare sedov: plot written", os.path.getsize(png) > 10000 if os.path.exists(png)
          else False)
    nfields = len(proc.stdout.strip().splitlines()[-1].split())
    check("compare: last line has the 10 key=value pairs", nfields == 10, str(nfields))

    # The same state, perturbed: shock 5% further out (the exact solution at a
    # later time) and 3% multiplicative noise.  Must be reported as wrong.
    t2 = t * 1.05 ** 2.5
    _, rho2, p2, vel2 = exact_state(pos, lambda r: sedov.sedov_profile(r, t2), [0.5] * 3, 1.0)
    rng = np.random.default_rng(7)
    rho2 = rho2 * (1 + 0.03 * rng.standard_normal(len(rho2)))
    f2 = os.path.join(tmp, "sedov_perturbed.csv")
    write_state(f2, pos, vel2, rho2, p2, s)
    proc, m = run_compare([f2, "--problem", "sedov", "--time", str(t), "--box", "1"])
    if check("compare sedov perturbed: runs", proc.returncode == 0 and "particles" in m):
        check("compare sedov perturbed: l1_density_norm clearly non-zero",
              m["l1_density_norm"] > 0.005, "%g" % m["l1_density_norm"])
        check("compare sedov perturbed: l1_pressure_norm clearly non-zero",
              m["l1_pressure_norm"] > 0.005, "%g" % m["l1_pressure_norm"])
        check("compare sedov perturbed: shock_radius_error about +5%",
              0.035 < m["shock_radius_error"] < 0.065, "%g" % m["shock_radius_error"])

    # Wrong centre without --box: the blast is not where compare.py looks.
    proc, m = run_compare([f, "--problem", "sedov", "--time", str(t)])
    check("compare sedov, origin centre (no --box): large error",
          proc.returncode == 0 and m.get("l1_density_norm", 0) > 0.01)

    # Noh: 40^3 lattice in [-0.5, 0.5]^3 (not periodic), centre at the origin;
    # pressure column named "p".
    t = 0.6
    pos, s = lattice(40, -0.5, 0.5, seed=2)
    _, rho, p, vel = exact_state(pos, lambda r: noh.noh_profile(r, t), [0.0] * 3, None)
    f3 = os.path.join(tmp, "noh_exact.csv")
    write_state(f3, pos, vel, rho, p, s, pressure_name="p")
    proc, m = run_compare([f3, "--problem", "noh", "--time", str(t)])
    print("     compare.py noh: %s" % (proc.stdout.strip().splitlines()[-1]
                                        if proc.stdout.strip() else proc.stderr))
    if check("compare noh exact: runs (pressure column 'p')", proc.returncode == 0 and m):
        for k in ("l1_density", "l1_density_norm", "l1_pressure_norm", "l1_velocity_norm"):
            check("compare noh exact: %s < 1e-6" % k, m[k] < 1e-6, "%g" % m[k])
        close("compare noh exact: shock_radius_exact = t/3", m["shock_radius_exact"], 0.2,
              rtol=1e-5)
        check("compare noh exact: |shock_radius_error| < 2%",
              abs(m["shock_radius_error"]) < 0.02, "%g" % m["shock_radius_error"])
        check("compare noh exact: peak ratio ~ 1", 0.95 < m["peak_density_ratio"] <= 1.0,
              "%g" % m["peak_density_ratio"])
    # Noh perturbed: shock lagging by 10% (solution at an earlier time), then
    # the post-shock density smeared down to 48.
    _, rho4, p4, vel4 = exact_state(pos, lambda r: noh.noh_profile(r, 0.9 * t), [0.0] * 3, None)
    rho4 = np.where(rho4 > 60, 48.0, rho4)
    f4 = os.path.join(tmp, "noh_perturbed.csv")
    write_state(f4, pos, vel4, rho4, p4, s, pressure_name="p")
    proc, m = run_compare([f4, "--problem", "noh", "--time", str(t)])
    if check("compare noh perturbed: runs", proc.returncode == 0 and m):
        check("compare noh perturbed: l1 clearly non-zero", m["l1_density_norm"] > 0.005
              and m["l1_velocity_norm"] > 0.005, "%g" % m["l1_density_norm"])
        check("compare noh perturbed: shock_radius_error about -10%",
              -0.13 < m["shock_radius_error"] < -0.07, "%g" % m["shock_radius_error"])
        close("compare noh perturbed: peak_density_ratio 0.75", m["peak_density_ratio"], 0.75,
              rtol=1e-6)

    # Missing pressure column: a clear error, non-zero exit.
    f5 = os.path.join(tmp, "bad.csv")
    with open(f5, "w") as fh:
        fh.write("id,x,y,z,vx,vy,vz,density,mass\n0,0,0,0,0,0,0,1,1\n")
    proc, _ = run_compare([f5, "--problem", "noh", "--time", "1"])
    check("compare: missing pressure column -> exit 2 with a message",
          proc.returncode == 2 and "pressure" in proc.stderr, proc.stderr.strip())

    # Minimum image.
    d = compare.separations(np.array([[0.95, 0.5, 0.02]]), [0.05, 0.5, 0.98], 1.0)
    close("compare: minimum-image separation", np.abs(d - [-0.1, 0.0, 0.04]).max(), 0.0,
          atol=1e-12)


def main():
    t0 = time.time()
    test_sedov()
    test_noh()
    with tempfile.TemporaryDirectory(prefix="wash-validation-") as tmp:
        test_compare(tmp)
    print("(%.1f s)" % (time.time() - t0))
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
