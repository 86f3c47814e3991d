#!/usr/bin/python3
"""Table, convergence orders and plot of a sedov_convergence.sh CSV.

    convergence_plot.py convergence.csv error_vs_time.png

Prints a markdown table (one row per run) with, per precision, the observed
order of the density L1 between successive sizes, order = log(L1_a / L1_b) /
log(n_b / n_a) (L1 ~ dx^order with dx = 1/n), beside SPH-EXA's reference
figures from the issue; plots L1 against wall time, log-log, one line per
precision.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# SPH-EXA on these machines, Sedov to t = 0.05 (the figures).
SPHEXA = {30: (0.107, 2.24), 50: (0.091, 2.78), 70: (0.084, 3.05)}
SPHEXA_NS = "7500-8000"


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    by_precision = {}
    for r in rows:
        by_precision.setdefault(r["precision"], []).append(r)
    print("| n | particles | precision | steps | wall s | ns/particle-step | density L1 | "
          "L1 order | peak density | shock radius error | SPH-EXA L1 | SPH-EXA peak |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for precision, runs in by_precision.items():
        runs.sort(key=lambda r: int(r["n"]))
        previous = None
        for r in runs:
            n, l1 = int(r["n"]), float(r["l1_density"])
            order = "–"
            if previous is not None:
                n0, l10 = previous
                order = "%.2f" % (math.log(l10 / l1) / math.log(n / n0))
            previous = (n, l1)
            ref_l1, ref_peak = SPHEXA.get(n, ("–", "–"))
            print(f"| {n} | {r['particles']} | {precision} | {r['steps']} | {float(r['wall_s']):.1f} | "
                  f"{float(r['ns_per_particle_step']):.0f} | {l1:.4f} | {order} | "
                  f"{float(r['peak_density']):.3f} | {float(r['shock_radius_error']):+.4f} | "
                  f"{ref_l1} | {ref_peak} |")
    print(f"(SPH-EXA: about {SPHEXA_NS} ns per particle-step on one core at every size)")

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for precision, runs in by_precision.items():
        t = [float(r["wall_s"]) for r in runs]
        e = [float(r["l1_density"]) for r in runs]
        ax.loglog(t, e, "o-", label=f"wash, {precision}")
        for r, ti, ei in zip(runs, t, e):
            ax.annotate(f"{r['n']}³", (ti, ei), textcoords="offset points", xytext=(4, 4))
    ref_n = sorted(SPHEXA)
    ax.axhline(SPHEXA[50][0], color="grey", ls=":", label="SPH-EXA L1 at 50³")
    ax.axhline(SPHEXA[70][0], color="grey", ls="--", label="SPH-EXA L1 at 70³")
    ax.set_xlabel("wall time of the run (s)")
    ax.set_ylabel("density L1 at t = 0.05 (mean |ρ − ρ_exact|)")
    ax.set_title("Sedov blast: error against run time")
    ax.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)
    print(f"plot: {sys.argv[2]} (sizes {', '.join(str(n) for n in ref_n)} for SPH-EXA)")


if __name__ == "__main__":
    main()
