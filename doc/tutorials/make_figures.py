#!/usr/bin/env python3
"""The figures of the tutorials' READMEs, drawn from their tested outputs (step-N/step-N.output, or
the `output` file a run of the program writes, given as STEP=FILE):

  step-1/step-1.png   max cell error against cells, with and without the non-orthogonal correction
  step-2/step-2.png   max displacement and hole-stress errors against cells
  step-3/step-3.png   drag and lift at Re = 100 from rest: step-3's PISO beside fvfsi::FluidSolver
  step-4/step-4.png   the interface residual per coupling iteration of each coupling method

usage: /usr/bin/python3 doc/tutorials/make_figures.py [step-1=FILE ...]   (needs matplotlib)
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def rows(text):
    """The lines of text whose words are all numbers or '-' (a table's body), as lists of words."""
    out = []
    for line in text.splitlines():
        words = line.split()
        if not words:
            continue
        try:
            float(words[0])
        except ValueError:
            continue
        out.append(words)
    return out


def loglog(ax, x, y, label, marker):
    ax.loglog(x, y, marker + "-", label=label)


def finish(fig, ax, png, **labels):
    """Axis labels and title, legend, grid; the figure written to png."""
    ax.set(**labels)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def step_1(text, png):
    table = [r for r in rows(text) if len(r) >= 6]
    cells = [float(r[0]) for r in table]
    fig, ax = plt.subplots(figsize=(5, 3.6))
    loglog(ax, cells, [float(r[3]) for r in table], "without the correction (Eq. 19 orthogonal part)", "s")
    corrected = [float(r[5]) for r in table]
    loglog(ax, cells, corrected, "with the non-orthogonal correction", "o")
    ax.loglog(cells, [corrected[0] * cells[0] / c for c in cells], "k:",
              label="second order (h^2 ~ 1/cells)")
    finish(fig, ax, png, xlabel="cells (distorted mesh)", ylabel="max cell error",
           title="step-1: FV Poisson")


def step_2(text, png):
    table = [r for r in rows(text) if len(r) >= 4]
    cells = [float(r[0]) for r in table]
    u = [float(r[1]) for r in table]
    s = [float(r[3]) for r in table]
    fig, ax = plt.subplots(figsize=(5, 3.6))
    loglog(ax, cells, [x / u[0] for x in u], "max displacement error", "o")
    loglog(ax, cells, [x / s[0] for x in s], "max hole-face stress error", "s")
    ax.loglog(cells, [cells[0] / c for c in cells], "k:", label="second order")
    finish(fig, ax, png, xlabel="cells", ylabel="error / error on the coarsest mesh",
           title="step-2: plate with a hole (Kirsch)")


def step_3(text, png):
    body = text.split("Re = 100 from rest")[1]
    table = [r for r in rows(body) if len(r) == 5]
    t = [float(r[0]) for r in table]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7, 3))
    a1.plot(t, [float(r[1]) for r in table], "o-", label="step-3")
    a1.plot(t, [float(r[3]) for r in table], "x--", label="fvfsi::FluidSolver")
    a2.plot(t, [float(r[2]) for r in table], "o-", label="step-3")
    a2.plot(t, [float(r[4]) for r in table], "x--", label="fvfsi::FluidSolver")
    a1.set(xlabel="t [s]", ylabel="drag [N/m]")
    a2.set(xlabel="t [s]", ylabel="lift [N/m]")
    a1.legend(fontsize=7)
    fig.suptitle("step-3: Re = 100 from rest, the tutorial's PISO and the library's")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def step_4(text, png):
    gs = text.split("Gauss-Seidel (omega = 1)")[1].split("...")[0]
    gs_rows = [r for r in rows(gs) if len(r) >= 2]
    block = text.split("per coupling iteration, time step 60")[1].split("fixed relaxation:")[0]
    methods = {"fixed relaxation (omega 0.4)": [], "Aitken": [], "IQN-ILS": []}
    for line in block.splitlines()[2:]:
        words = line.replace("(omega", "").replace(")", "").split()
        if not words or not words[0].isdigit():
            continue
        k = int(words[0])
        values = [w for w in words[1:] if "e" in w]
        for name, v in zip(methods, values):
            methods[name].append((k, float(v)))
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    ax.semilogy([int(r[0]) for r in gs_rows], [float(r[1]) / float(gs_rows[0][1]) * 8.1e-4
                                               for r in gs_rows], "k^-",
                label="Gauss-Seidel, time step 1 (scaled): diverges")
    for (name, points), marker in zip(methods.items(), "osd"):
        if points:
            ax.semilogy(*zip(*points), marker + "-", label=name + ", time step 60")
    finish(fig, ax, png, xlabel="coupling iteration k", ylabel="|r| / |d~|",
           title="step-4: the coupling methods on the pressure column")


def main():
    given = dict(a.split("=", 1) for a in sys.argv[1:])
    for step, draw in [("step-1", step_1), ("step-2", step_2), ("step-3", step_3), ("step-4", step_4)]:
        source = given.get(step, os.path.join(HERE, step, step + ".output"))
        with open(source) as f:
            draw(f.read(), os.path.join(HERE, step, step + ".png"))
        print("wrote", os.path.join(step, step + ".png"), "from", source)


if __name__ == "__main__":
    main()
