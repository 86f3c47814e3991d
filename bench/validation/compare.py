#!/usr/bin/python3
"""Compare a wash particle dump with the Sedov or Noh exact solution.

    compare.py STATE.csv --problem sedov|noh --time T [--center X Y Z] [--box L]
               [--rmax R] [--plot OUT.png] [--label TEXT]

STATE.csv is a wash `--dump` file (header row, one row per particle) with at
least the columns x, y, z, vx, vy, vz, density and pressure (or p); mass is
used for the default bin width when present.  The dump carries no time: give
the simulated time with --time.  STATE may instead be the .h5 file of a run
with --format hdf5 (its last step, read by scripts/wash_read.py).

Geometry: r = |x - centre|; with --box L the separation is taken as the
minimum image in a periodic cube of side L (each component wrapped into
[-L/2, L/2)).  The default centre is (L/2, L/2, L/2) with --box, else the
origin.  Radial velocity v_r = v . r_hat (0 for a particle exactly at the
centre).

Metrics (N particles, exact values at each particle's r and time T):
  l1_density        = (1/N) sum |rho - rho_exact(r)|           (SPH-EXA's metric)
  l1_density_norm   = l1_density / rho_post
  l1_pressure_norm  = (1/N) sum |p - p_exact(r)| / p_post
  l1_velocity_norm  = (1/N) sum |v_r - v_r,exact(r)| / v_ref
  with the post-shock values rho_post, p_post of the exact solution at T and
  v_ref = post-shock velocity (Sedov) or the inflow speed u0 (Noh).

  Radial bins: width dr (--bin-width; default a quarter of the median
  particle spacing, spacing = (mass/density)^(1/3), or from the particle
  count if there is no mass column), from r = 0 to the largest r; bins
  holding fewer than 4 particles are ignored.  rho_bin = mean density in
  the bin.  Binning cannot resolve the thin Sedov density spike: even the
  exact solution sampled at the particles gives a binned peak below rho_post
  (about 0.85 rho_post for a 50^3 lattice in the unit box); that reference
  value is printed (not part of the last line) as "binned exact peak ratio".
  peak_density       = max over bins of rho_bin
  peak_density_ratio = peak_density / rho_post
  shock_radius       = coming in from the outermost bin, the first bin whose
      rho_bin >= level, level = (rho_ahead + peak_density) / 2, where rho_ahead
      is the exact density just ahead of the exact shock (rho0 for Sedov,
      rho0 (1 + u0 T / r_s)^2 for Noh); the radius is interpolated linearly
      between that bin's centre and the next non-empty bin outside it.
  shock_radius_exact, shock_radius_error = (shock_radius - exact) / exact
  particles = N

The last line printed holds all of these as key=value (6 significant digits).
"""

import argparse
import csv
import math
import os
import sys

import numpy as np

sys.dont_write_bytecode = True  # keep the source tree clean
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import noh  # noqa: E402
import sedov  # noqa: E402
import wash_read  # noqa: E402

MIN_PER_BIN = 4
KEYS = ("l1_density", "l1_density_norm", "l1_pressure_norm", "l1_velocity_norm",
        "shock_radius", "shock_radius_exact", "shock_radius_error",
        "peak_density", "peak_density_ratio", "particles")


class InputError(Exception):
    pass


def read_state(path):
    """Columns of a wash CSV dump (or .h5 file's last step) as a dict name -> float array."""
    if path.endswith(".h5"):
        frame = wash_read.load(path)
        pressure = "pressure" if "pressure" in frame else "p"
        if pressure not in frame or "z" not in frame:
            raise InputError("%s: no pressure or z dataset; have %s" % (path, ",".join(frame)))
        out = {c: frame[c] for c in ["x", "y", "z", "vx", "vy", "vz", "density", "mass"] if c in frame}
        out["pressure"] = frame[pressure]
        return out
    with open(path, newline="") as fh:
        header = next(csv.reader(fh), None)
    if not header:
        raise InputError("%s: empty file" % path)
    header = [h.strip() for h in header]
    index = {name: k for k, name in enumerate(header)}
    pressure = "pressure" if "pressure" in index else ("p" if "p" in index else None)
    need = ["x", "y", "z", "vx", "vy", "vz", "density"]
    missing = [c for c in need if c not in index]
    if pressure is None:
        missing.append("pressure (or p)")
    if missing:
        raise InputError("%s: missing column(s) %s; have %s"
                         % (path, ", ".join(missing), ",".join(header)))
    wanted = need + [pressure] + (["mass"] if "mass" in index else [])
    cols = [index[c] for c in wanted]
    data = np.loadtxt(path, delimiter=",", skiprows=1, usecols=cols, ndmin=2)
    out = {name: data[:, k].copy() for k, name in enumerate(wanted)}
    out["pressure"] = out.pop(pressure)
    if len(out["x"]) == 0:
        raise InputError("%s: no particles" % path)
    return out


def separations(pos, center, box=None):
    """pos - center, minimum image in a periodic cube of side box if given."""
    d = pos - np.asarray(center, dtype=float)
    if box:
        d = d - box * np.floor(d / box + 0.5)
    return d


def radial(state, center, box=None):
    """(r, v_r) of every particle."""
    pos = np.column_stack([state["x"], state["y"], state["z"]])
    vel = np.column_stack([state["vx"], state["vy"], state["vz"]])
    d = separations(pos, center, box)
    r = np.sqrt(np.einsum("ij,ij->i", d, d))
    with np.errstate(invalid="ignore", divide="ignore"):
        vr = np.where(r > 0.0, np.einsum("ij,ij->i", d, vel) / np.where(r > 0, r, 1.0), 0.0)
    return r, vr


class Problem:
    """Exact solution, post-shock scales and the density ahead of the shock."""

    def __init__(self, name, time, gamma=5.0 / 3.0, energy=1.0, rho0=1.0, u0=1.0):
        self.name, self.t = name, time
        if name == "sedov":
            self.sol = lambda r: sedov.sedov_profile(r, time, energy, rho0, gamma)
            rho2, p2, v2, rs, _ = sedov.post_shock_state(time, energy, rho0, gamma)
            self.rho_post, self.p_post, self.v_ref, self.r_shock = rho2, p2, v2, rs
            self.rho_ahead = rho0
        elif name == "noh":
            self.sol = lambda r: noh.noh_profile(r, time, rho0, gamma, u0)
            rho2, p2, _, rs, rho1 = noh.post_shock_state(time, rho0, gamma, u0)
            self.rho_post, self.p_post, self.v_ref, self.r_shock = rho2, p2, abs(u0), rs
            self.rho_ahead = rho1
        else:
            raise InputError("unknown problem %r" % name)


def binned_means(r, values, width, r_max):
    """Bin centres, counts and per-bin means of each array in values."""
    nbins = max(1, int(math.ceil(r_max / width)))
    idx = np.minimum((r / width).astype(np.int64), nbins - 1)
    counts = np.bincount(idx, minlength=nbins)
    centres = (np.arange(nbins) + 0.5) * width
    means = []
    for v in values:
        s = np.bincount(idx, weights=v, minlength=nbins)
        with np.errstate(invalid="ignore", divide="ignore"):
            means.append(np.where(counts >= MIN_PER_BIN, s / np.maximum(counts, 1), np.nan))
    return centres, counts, means


def measure_shock(centres, rho_bin, rho_ahead):
    """(shock radius, peak) from binned density; see the module docstring."""
    ok = np.isfinite(rho_bin)
    if not np.any(ok):
        return float("nan"), float("nan")
    rc, rb = centres[ok], rho_bin[ok]
    peak = float(np.max(rb))
    level = 0.5 * (rho_ahead + peak)
    for k in range(len(rb) - 1, -1, -1):
        if rb[k] >= level:
            if k == len(rb) - 1:
                return float(rc[k]), peak
            frac = (rb[k] - level) / (rb[k] - rb[k + 1])
            return float(rc[k] + frac * (rc[k + 1] - rc[k])), peak
    return float("nan"), peak


def default_bin_width(state, r):
    n = len(r)
    if "mass" in state:
        with np.errstate(invalid="ignore", divide="ignore"):
            vol = state["mass"] / state["density"]
        vol = vol[np.isfinite(vol) & (vol > 0)]
        if len(vol):
            return 0.25 * float(np.median(vol)) ** (1.0 / 3.0)
    r_max = float(np.max(r))
    return 0.25 * (4.0 / 3.0 * math.pi * r_max ** 3 / n) ** (1.0 / 3.0)


def evaluate(state, problem, center, box=None, bin_width=None):
    """All metrics (dict) plus the arrays the plot needs."""
    r, vr = radial(state, center, box)
    rho_e, p_e, v_e = problem.sol(r)
    rho, p = state["density"], state["pressure"]
    l1_rho = float(np.mean(np.abs(rho - rho_e)))
    width = bin_width or default_bin_width(state, r)
    r_max = float(np.max(r)) * (1.0 + 1e-12) + 1e-300
    centres, counts, (rho_b, p_b, v_b, rho_eb) = binned_means(r, (rho, p, vr, rho_e), width,
                                                              r_max)
    r_s, peak = measure_shock(centres, rho_b, problem.rho_ahead)
    ok = np.isfinite(rho_eb)
    peak_exact_binned = float(np.max(rho_eb[ok])) if np.any(ok) else float("nan")
    m = {
        "l1_density": l1_rho,
        "l1_density_norm": l1_rho / problem.rho_post,
        "l1_pressure_norm": float(np.mean(np.abs(p - p_e))) / problem.p_post,
        "l1_velocity_norm": float(np.mean(np.abs(vr - v_e))) / problem.v_ref,
        "shock_radius": r_s,
        "shock_radius_exact": problem.r_shock,
        "shock_radius_error": (r_s - problem.r_shock) / problem.r_shock,
        "peak_density": peak,
        "peak_density_ratio": peak / problem.rho_post,
        "particles": len(r),
    }
    arrays = dict(r=r, vr=vr, rho=rho, p=p, centres=centres, rho_b=rho_b, p_b=p_b,
                  v_b=v_b, width=width, peak_exact_binned=peak_exact_binned)
    return m, arrays


def format_metrics(m):
    parts = []
    for k in KEYS:
        v = m[k]
        parts.append("%s=%d" % (k, v) if k == "particles" else "%s=%.6g" % (k, v))
    return " ".join(parts)


def plot(path, problem, m, a, label):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    r = a["r"]
    n = len(r)
    sel = np.arange(n)
    if n > 20000:
        sel = np.sort(np.random.default_rng(12345).choice(n, 20000, replace=False))
    r_hi = float(np.max(r))
    rr = np.linspace(0.0, r_hi, 4001)
    rr = np.union1d(rr, [problem.r_shock * (1 - 1e-9), problem.r_shock])
    ex = problem.sol(rr)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    panels = (("density", a["rho"], a["rho_b"], ex[0]),
              ("pressure", a["p"], a["p_b"], ex[1]),
              ("radial velocity", a["vr"], a["v_b"], ex[2]))
    for ax, (name, pv, bv, ev) in zip(axes, panels):
        ax.plot(r[sel], pv[sel], ".", ms=1.5, mew=0, color="0.45", alpha=0.5,
                label="particles")
        ok = np.isfinite(bv)
        ax.plot(a["centres"][ok], bv[ok], "-", color="C0", lw=1.5, label="binned mean")
        ax.plot(rr, ev, "--", color="C3", lw=1.2, label="exact")
        ax.axvline(problem.r_shock, color="C3", lw=0.5, ls=":")
        if name == "density" and np.isfinite(m["shock_radius"]):
            ax.axvline(m["shock_radius"], color="C0", lw=0.5, ls=":")
        ax.set_xlabel("r")
        ax.set_ylabel(name)
        ax.set_xlim(0.0, r_hi)
    axes[0].legend(loc="best", fontsize=8, markerscale=6)
    title = label or "%s, t = %g" % (problem.name, problem.t)
    fig.suptitle("%s\nL1(rho)/rho_post = %.3g, r_shock err = %.2f%%, peak ratio = %.3f"
                 % (title, m["l1_density_norm"], 100 * m["shock_radius_error"],
                    m["peak_density_ratio"]), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("state", help="wash --dump CSV file")
    ap.add_argument("--problem", required=True, choices=("sedov", "noh"))
    ap.add_argument("--time", required=True, type=float, help="simulated time of the dump")
    ap.add_argument("--center", nargs=3, type=float, metavar=("X", "Y", "Z"))
    ap.add_argument("--box", type=float, help="periodic cube side (minimum image)")
    ap.add_argument("--plot", metavar="OUT.png")
    ap.add_argument("--label", default="")
    ap.add_argument("--gamma", type=float, default=5.0 / 3.0)
    ap.add_argument("--energy", type=float, default=1.0, help="Sedov blast energy")
    ap.add_argument("--rho0", type=float, default=1.0, help="ambient density")
    ap.add_argument("--u0", type=float, default=1.0, help="Noh inflow speed")
    ap.add_argument("--bin-width", type=float, help="radial bin width (default: see doc)")
    ap.add_argument("--rmax", type=float,
                    help="score only the particles with r < RMAX (e.g. away from a free edge)")
    args = ap.parse_args(argv)
    if not args.time > 0:
        ap.error("--time must be > 0")
    if args.box is not None and not args.box > 0:
        ap.error("--box must be > 0")
    center = args.center
    if center is None:
        center = [0.5 * args.box] * 3 if args.box else [0.0, 0.0, 0.0]
    try:
        state = read_state(args.state)
        problem = Problem(args.problem, args.time, args.gamma, args.energy, args.rho0, args.u0)
    except (InputError, OSError, ValueError) as exc:
        print("compare.py: error: %s" % exc, file=sys.stderr)
        return 2
    if args.rmax is not None:
        inside = radial(state, center, args.box)[0] < args.rmax
        state = {name: column[inside] for name, column in state.items()}
    m, arrays = evaluate(state, problem, center, args.box, args.bin_width)
    print("%s at t=%g, centre (%g, %g, %g)%s, %d particles, bin width %.4g"
          % (args.problem, args.time, center[0], center[1], center[2],
             ", periodic box %g" % args.box if args.box else "", m["particles"],
             arrays["width"]))
    print("  post-shock: rho=%.6g p=%.6g v_ref=%.6g; exact shock radius %.6g"
          % (problem.rho_post, problem.p_post, problem.v_ref, problem.r_shock))
    print("  binned exact peak ratio %.6g (the best peak_density_ratio these bins allow)"
          % (arrays["peak_exact_binned"] / problem.rho_post))
    if args.plot:
        plot(args.plot, problem, m, arrays, args.label)
        print("  wrote %s" % args.plot)
    print(format_metrics(m))
    return 0


if __name__ == "__main__":
    sys.exit(main())
