#!/usr/bin/python3
"""CSM3 (Turek & Hron 2006): mean, amplitude and frequency of the displacement of point A.

usage: /usr/bin/python3 doc/results/csm3_analysis.py [--periods N] [--plot FILE.png] \
           [--label TEXT] HISTORY [HISTORY...]

HISTORY is the solid_history.txt of a `fvfsi prm/turek_hron_csm3.prm` run (columns
`# t ux_A uy_A Fx_clamped Fy_clamped`). For u_x(A) and u_y(A), over the last N full periods
(default 2), i.e. between the last N + 1 up-crossings of u - mean (linearly interpolated):
  mean      = (max + min) / 2,
  amplitude = (max - min) / 2,
  frequency = 1 / period = N / (time between the first and last of those up-crossings),
with max and min refined by a parabola through the three samples around them, and the mean
iterated (it defines the crossings). Crossings rather than maxima define the period because
u_x(A) has a double hump at its maximum (the flag swings through the straight position). The
frequency from successive maxima (one per cycle) is printed as a check, and so are the first and
last period (drift). Errors are relative to the reference values, in %.
With --plot, u_y(A) over time of every HISTORY is drawn into FILE.png (the first one solid).
"""
import argparse
import sys

import numpy as np

REFERENCE = {  # mean, amplitude [m], frequency [Hz]
    "ux_A": (-14.305e-3, 14.305e-3, 1.0995),
    "uy_A": (-63.607e-3, 65.160e-3, 1.0995),
}


def read_history(path):
    with open(path) as f:
        header = f.readline().lstrip("#").split()
    data = np.loadtxt(path, comments="#", ndmin=2)
    return {name: data[:, i] for i, name in enumerate(header)}


def parabola_peak(t, u, i):
    """Time and value of the vertex of the parabola through samples i-1, i, i+1."""
    dt = t[i + 1] - t[i]
    a, b, c = u[i - 1], u[i], u[i + 1]
    denom = a - 2 * b + c
    s = 0.0 if denom == 0 else 0.5 * (a - c) / denom  # offset in steps, |s| <= 1/2
    return t[i] + s * dt, b - 0.25 * (a - c) * s


def up_crossings(t, w):
    """Times where w goes from < 0 to >= 0, linearly interpolated."""
    i = np.where((w[:-1] < 0) & (w[1:] >= 0))[0]
    return t[i] - w[i] * (t[i + 1] - t[i]) / (w[i + 1] - w[i])


def extremum(t, u, a, b, sign):
    """Largest (sign = 1) or smallest (sign = -1) value of u for a < t < b, parabolically refined."""
    idx = np.where((t > a) & (t < b))[0]
    i = idx[np.argmax(sign * u[idx])]
    if 0 < i < len(t) - 1:
        return parabola_peak(t, u, i)
    return t[i], u[i]


def analyse(t, u, n_periods):
    """Mean, amplitude, frequency over the last n_periods full periods.

    A period is the time between two successive up-crossings of u - mean (one per cycle also for
    u_x, whose maxima are double humps); mean and amplitude come from the max and min of u between
    the first and last of the last n_periods + 1 up-crossings. The mean is iterated (it defines the
    crossings). The frequency from successive maxima is returned as a check."""
    level = 0.5 * (u.max() + u.min())
    for _ in range(5):
        t_up = up_crossings(t, u - level)
        if len(t_up) < n_periods + 1:
            raise RuntimeError(f"only {len(t_up)} up-crossings: run longer or use fewer --periods")
        t0, t1 = t_up[-n_periods - 1], t_up[-1]
        hi = extremum(t, u, t0, t1, 1)[1]
        lo = extremum(t, u, t0, t1, -1)[1]
        level = 0.5 * (hi + lo)
    t_up = up_crossings(t, u - level)
    t0, t1 = t_up[-n_periods - 1], t_up[-1]
    periods = np.diff(t_up)
    # Check: maxima, one per cycle (the largest value between successive up-crossings).
    t_max = np.array([extremum(t, u, a, b, 1)[0] for a, b in zip(t_up[:-1], t_up[1:])])
    f_max = (n_periods / (t_max[-1] - t_max[-n_periods - 1]) if len(t_max) > n_periods
             else float("nan"))
    return dict(mean=level, amplitude=0.5 * (hi - lo), frequency=n_periods / (t1 - t0),
                f_check=f_max, span=(t0, t1), first_period=periods[0], last_period=periods[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("history", nargs="+")
    parser.add_argument("--periods", type=int, default=2)
    parser.add_argument("--plot")
    parser.add_argument("--label", action="append", default=[])
    args = parser.parse_args()

    worst = 0.0
    for path in args.history:
        h = read_history(path)
        t = h["t"]
        print(f"{path}: {len(t)} steps, dt = {t[1] - t[0]:g} s, t_end = {t[-1]:g} s")
        for name, (m_ref, a_ref, f_ref) in REFERENCE.items():
            r = analyse(t, h[name], args.periods)
            e = [100 * (r["mean"] / m_ref - 1), 100 * (r["amplitude"] / a_ref - 1),
                 100 * (r["frequency"] / f_ref - 1)]
            worst = max(worst, *map(abs, e))
            print(f"  {name}: {r['mean'] * 1e3:9.3f}e-3 +- {r['amplitude'] * 1e3:8.3f}e-3 m "
                  f"[{r['frequency']:.4f} Hz]   errors: mean {e[0]:+6.2f}%, amplitude {e[1]:+6.2f}%, "
                  f"frequency {e[2]:+6.2f}%   (last {args.periods} periods, t = {r['span'][0]:.3f}"
                  f"..{r['span'][1]:.3f} s; frequency from maxima {r['f_check']:.4f} Hz; "
                  f"first/last period {r['first_period']:.4f}/{r['last_period']:.4f} s)")
    print(f"largest |error|: {worst:.2f}%")

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(9, 4))
        for k, path in enumerate(args.history):
            h = read_history(path)
            label = args.label[k] if k < len(args.label) else path
            ax.plot(h["t"], 1e3 * h["uy_A"], "-" if k == 0 else "--", lw=1.2 if k == 0 else 0.9,
                    label=label)
        m, a, _ = REFERENCE["uy_A"]
        for y, style in ((m, ":"), (m + a, "-."), (m - a, "-.")):
            ax.axhline(1e3 * y, color="k", ls=style, lw=0.7)
        ax.set_xlabel("t [s]")
        ax.set_ylabel("u_y(A) [mm]")
        ax.set_title("CSM3: vertical displacement of point A (black: reference mean +- amplitude)")
        ax.legend(fontsize=8, loc="lower right")
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print(f"wrote {args.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
