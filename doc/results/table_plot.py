#!/usr/bin/env python3
"""Plot a markdown table as a PNG: the benchmark scripts that print tables pipe them through this.

    table_plot.py TABLE.md OUT.png --x COLUMN --y COLUMN [--y COLUMN ...] [--group COLUMN ...]
                  [--bar] [--logx] [--logy] [--title TEXT] [--index N] [--all] [--match RE]

TABLE.md is any markdown file (or - for standard input); the N-th table in it (from 1) is read
(--all: with the rows of every table of the same header),
the columns are named by their header text, or @N for the N-th (where two have one text). Rows whose --y cell is not a number (a run that
diverged, "-") are left out of that curve and listed under the plot. With --group, one curve per
value of those columns; with --bar, one bar per row labelled by --x (then --x need not be a number;
more than 12 rows: horizontal bars).
Needs python3 with matplotlib (Debian: python3-matplotlib).
"""
import argparse
import os
import re
import subprocess
import sys

try:
    import matplotlib
except ImportError:  # Debian's package, installed here when run as root
    if os.geteuid() != 0:
        sys.exit("table_plot.py needs matplotlib: apt-get install python3-matplotlib")
    subprocess.run(["apt-get", "install", "-y", "-q", "python3-matplotlib"], check=True)
    sys.exit(subprocess.run(["/usr/bin/python3"] + sys.argv).returncode)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def tables(text):
    """The markdown tables of text, each as (header, rows of cells)."""
    found, block = [], []
    for line in text.splitlines() + [""]:
        if line.strip().startswith("|"):
            block.append([c.strip() for c in line.strip().strip("|").split("|")])
        elif block:
            if len(block) >= 2 and set("".join(block[1])) <= set("-: "):
                found.append((block[0], block[2:]))
            block = []
    return found


def number(cell):
    """The first number of a cell ("0.72 (0.88, ...)", "0.0024%", "1.2e-5"), or None."""
    m = re.match(r"^\s*([-+]?\d*\.?\d+(?:[eE][-+]?\d+)?)", cell.replace("*", ""))
    return float(m.group(1)) if m else None


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("source")
    p.add_argument("png")
    p.add_argument("--x", required=True)
    p.add_argument("--y", action="append", required=True)
    p.add_argument("--group", action="append", default=[])
    p.add_argument("--bar", action="store_true")
    p.add_argument("--logy", action="store_true")
    p.add_argument("--logx", action="store_true")
    p.add_argument("--title", default="")
    p.add_argument("--index", type=int, default=1)
    p.add_argument("--all", action="store_true")
    p.add_argument("--match", help="keep the rows whose first --y cell matches this regex")
    a = p.parse_args()
    text = sys.stdin.read() if a.source == "-" else open(a.source).read()
    found = tables(text)
    header, rows = found[a.index - 1]
    if a.all:  # the rows of every table with this header
        rows = [r for h, rs in found if h == header for r in rs]
    col = {name: i for i, name in enumerate(header)}
    for i, name in enumerate(header):  # @N: the N-th column (for repeated header texts)
        col[f"@{i + 1}"] = i
    for name in [a.x] + a.y + a.group:
        if name not in col:
            sys.exit(f"table_plot.py: no column `{name}` in {header}")
    if a.match:
        rows = [r for r in rows if re.search(a.match, r[col[a.y[0]]])]
    horizontal = a.bar and len(rows) > 12  # many bars: one per line, labels readable
    height = 0.2 * len(rows) + 1.8 if horizontal else 3.8
    fig, axes = plt.subplots(1, len(a.y), figsize=(5.5 * len(a.y), height), squeeze=False)
    missing = []
    for ax, y in zip(axes[0], a.y):
        if a.bar:
            labels = [" ".join([r[col[a.x]]] + [r[col[g]] for g in a.group]) for r in rows]
            values = [number(r[col[y]]) for r in rows]
            heights = [v if v is not None else 0 for v in values]
            if horizontal:
                ax.barh(range(len(rows)), heights)
                ax.set_yticks(range(len(rows)))
                ax.set_yticklabels(labels, fontsize=7)
                ax.invert_yaxis()
            else:
                ax.bar(range(len(rows)), heights)
                ax.set_xticks(range(len(rows)))
                ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
            missing += [f"{lab}: {r[col[y]][:24]}" for lab, v, r in zip(labels, values, rows)
                        if v is None]
        else:
            groups = {}
            for r in rows:
                groups.setdefault(" ".join(r[col[g]] for g in a.group), []).append(r)
            for g, rs in groups.items():
                pts = [(number(r[col[a.x]]), number(r[col[y]])) for r in rs]
                ok = [(x, v) for x, v in pts if x is not None and v is not None]
                missing += [f"{g} {r[col[a.x]]}: {r[col[y]][:24]}" for (x, v), r in zip(pts, rs)
                            if v is None]
                if ok:
                    ax.plot(*zip(*ok), "o-", label=g or None)
            ax.set_xlabel(a.x)
            if a.group:
                ax.legend(fontsize=8)
        label = header[col[y]] + (f" (column {col[y] + 1})" if y.startswith("@") else "")
        if horizontal:
            ax.set_xlabel(label)
        else:
            ax.set_ylabel(label)
        if a.logy:  # the value axis
            (ax.set_xscale if horizontal else ax.set_yscale)("log")
        if a.logx and not a.bar:
            ax.set_xscale("log")
        ax.grid(alpha=0.3)
    fig.suptitle(a.title, fontsize=10)
    if missing:
        fig.text(0.01, 0.01, "not plotted: " + "; ".join(sorted(set(missing)))[:400], fontsize=6,
                 wrap=True)
    fig.tight_layout(rect=(0, 0.5 / height if missing else 0, 1, 1 - 0.3 / height))
    fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
