#!/usr/bin/env python3
"""The heavy flap of doc/results/hard_cases.md (section 8): its period and amplitude on a series of fluid
meshes against its in-vacuo period, from the runs of heavy_flap.sh.

Each tip history u_x(t) is fitted over 0.2 s <= t <= 1 s (after the start-up) by
  u_x = a + b (t - t0) + exp(-z (t - t0)) (c cos(w t) + d sin(w t)),
the linear terms by least squares for every (w, z), (w, z) by a grid search refined with
Nelder-Mead: the period 2 pi / w, the damping z [1/s], the amplitude sqrt(c^2 + d^2) at t0.

usage: python3 doc/results/heavy_flap.py WORK   (WORK as given to heavy_flap.sh)
Writes doc/results/heavy_flap.json and prints the table of heavy_flap.md.
"""
import json
import os
import sys

import numpy as np
from scipy.optimize import minimize

HERE = os.path.dirname(os.path.abspath(__file__))
T0 = 0.2


def load(path, column):
    names = open(path).readline().lstrip("#").split()
    data = np.loadtxt(path)
    return data[:, 0], data[:, names.index(column)]


def fit(t, u):
    m = t >= T0 - 1e-12
    t, u = t[m], u[m]

    def lsq(w, z):
        e = np.exp(-z * (t - T0))
        A = np.column_stack([np.ones_like(t), t - T0, e * np.cos(w * t), e * np.sin(w * t)])
        x = np.linalg.lstsq(A, u, rcond=None)[0]
        r = u - A @ x
        return r @ r, x

    grid = [(lsq(w, z)[0], w, z) for w in np.linspace(2 * np.pi / 0.25, 2 * np.pi / 0.15, 400)
            for z in np.linspace(0, 3, 31)]
    _, w, z = min(grid)
    w, z = minimize(lambda q: lsq(q[0], q[1])[0], [w, z], method="Nelder-Mead",
                    options={"xatol": 1e-11, "fatol": 1e-18, "maxiter": 4000}).x
    s, x = lsq(w, z)
    amplitude = float(np.hypot(x[2], x[3]))
    return {"period": float(2 * np.pi / w), "damping": float(z), "amplitude": amplitude,
            "mean": float(x[0]), "fit_residual": float(np.sqrt(s / len(t)) / amplitude)}


def main():
    work = sys.argv[1]
    runs = json.load(open(os.path.join(work, "runs.json")))
    rows = []
    for run in runs:
        name = "solid_history.txt" if run["kind"] == "vacuo" else "fsi_history.txt"
        t, u = load(os.path.join(work, run["name"], name), "ux_tip")
        row = dict(run, **fit(t, u))
        rows.append(row)
    for row in rows:
        vacuo = [x for x in rows if x["kind"] == "vacuo" and x["ratio"] == row["ratio"]][0]
        row["period_vs_vacuo"] = row["period"] / vacuo["period"] - 1
        finer = [x for x in rows if x["kind"] == row["kind"] and x["ratio"] == row["ratio"]
                 and x.get("inflow") == row.get("inflow") and x.get("r", 0) == row.get("r", 0) + 1]
        if finer:
            row["amplitude_change_to_next_r"] = finer[0]["amplitude"] / row["amplitude"] - 1
    print("| run | rho_s / rho_f | inflow | fluid cells | period [s] | vs in vacuo | amplitude "
          "at 0.2 s [mm] | change to the next r | damping [1/s] | coupling iterations per step "
          "| wall [s] |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for row in rows:
        change = row.get("amplitude_change_to_next_r")
        print("| %s | %d | %s | %s | %.6f | %+.3f%% | %.4f | %s | %.3f | %s | %.1f |" % (
            row["name"], row["ratio"], row.get("inflow", "-"), row.get("cells", "-"),
            row["period"], 100 * row["period_vs_vacuo"], 1e3 * row["amplitude"],
            "%+.2f%%" % (100 * change) if change is not None else "-", row["damping"],
            "%.2f" % row["iterations"] if row.get("iterations") else "-", row["wall_s"]))
    with open(os.path.join(HERE, "heavy_flap.json"), "w") as f:
        json.dump({"command": "bash doc/results/heavy_flap.sh build/fvfsi", "fit_from": T0,
                   "cpu": runs[0]["cpu"], "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
