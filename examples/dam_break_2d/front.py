"""Scores dam_break_2d's surge front against the experiments.

    front.py LOG [--plot PNG] [--label TEXT] [--tmax 3]

LOG holds the program's "front T=<T> x/L=<Z>" lines. The data, Z = x/L
against T = t sqrt(2g/L), are those tabulated in PySPH
(pysph/examples/db_exp_data.py): Martin & Moyce (1952), Phil. Trans. R. Soc.
A 244, 312-324, Fig. 3, n^2 = 2 (a column twice as high as wide), for
a = 2.25 in and a = 1.125 in; and the experiment of Koshizuka & Oka (1996),
Nucl. Sci. Eng. 123, 421-434. For each data point with T <= tmax the
simulated front is interpolated linearly in T; the mean of
(Z_sim - Z_exp) / Z_exp is printed per data set. The last line holds the
metrics as key=value pairs; mm_error is against Martin & Moyce a = 2.25 in.
"""
import argparse
import re
import sys

import numpy as np

MARTIN_MOYCE_225 = [(0.832, 1.217), (1.219, 1.474), (1.997, 2.292), (2.547, 2.995),
                    (3.345, 4.134), (4.034, 4.944), (4.418, 5.881), (5.091, 6.980)]
MARTIN_MOYCE_1125 = [(0.849, 1.245), (1.212, 1.443), (1.602, 1.884), (2.283, 2.689),
                     (2.950, 3.728), (3.598, 4.528), (3.905, 4.999)]
KOSHIZUKA_OKA = [(0.0, 1.000), (0.381, 1.111), (0.769, 1.252), (1.153, 1.505), (1.537, 1.892),
                 (1.935, 2.241), (2.323, 2.615), (2.719, 3.003), (3.096, 3.624)]


def read_front(path):
    pattern = re.compile(r"^front T=(\S+) x/L=(\S+)$")
    rows = [tuple(map(float, m.groups())) for m in map(pattern.match, open(path)) if m]
    if len(rows) < 3:
        sys.exit(f"{path}: fewer than 3 'front' lines")
    return np.array(rows).T


def mean_error(T, Z, data, tmax):
    points = [(t, z) for t, z in data if 0.0 < t <= tmax and t <= T[-1]]
    errors = [(np.interp(t, T, Z) - z) / z for t, z in points]
    return float(np.mean(errors)), len(points)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("log")
    ap.add_argument("--plot")
    ap.add_argument("--label", default="wash dam_break_2d")
    ap.add_argument("--tmax", type=float, default=3.0)
    args = ap.parse_args()
    T, Z = read_front(args.log)
    results = {}
    for key, name, data in [("mm_error", "Martin & Moyce 1952, a = 2.25 in", MARTIN_MOYCE_225),
                            ("mm1125_error", "Martin & Moyce 1952, a = 1.125 in", MARTIN_MOYCE_1125),
                            ("ko_error", "Koshizuka & Oka 1996", KOSHIZUKA_OKA)]:
        err, n = mean_error(T, Z, data, args.tmax)
        results[key] = err
        print(f"{name}: mean relative front error over T <= {args.tmax:g}: {100 * err:+.1f} % ({n} points)")
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4.5))
        ax.plot(T, Z, "-", color="C0", label=args.label)
        for data, marker, name in [(MARTIN_MOYCE_225, "o", "Martin & Moyce (1952), a = 2.25 in"),
                                   (MARTIN_MOYCE_1125, "s", "Martin & Moyce (1952), a = 1.125 in"),
                                   (KOSHIZUKA_OKA, "^", "Koshizuka & Oka (1996)")]:
            t, z = np.array(data).T
            ax.plot(t, z, marker, mfc="none", label=name)
        ax.set_xlim(0, max(3.5, T[-1]))
        ax.set_ylim(1, 4.5)
        ax.set_xlabel(r"$T = t\sqrt{2g/L}$")
        ax.set_ylabel(r"surge front $x/L$")
        ax.axvline(args.tmax, color="0.8", lw=0.8)
        ax.legend(loc="upper left", fontsize=8)
        ax.set_title("Dam break: surge front")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=110)
    print(" ".join(f"{k}={v:.4f}" for k, v in results.items()))


if __name__ == "__main__":
    main()
