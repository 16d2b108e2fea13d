# Plots a history file of fvfsi (a text table: a header line "# t name name ...", then one line
# per time step) as one panel per column over the first column. Written next to the history by
# `Plot history = true` and run there; run it again by hand after editing:
#   python3 plot_history.py fsi_history.txt history.png
# Needs matplotlib only (Debian: apt-get install python3-matplotlib).
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

UNITS = {"drag": "N/m", "lift": "N/m", "ux_A": "m", "uy_A": "m", "uz_A": "m"}


def read(path):
    names, rows = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                names = line[1:].split()
            elif line.strip():
                rows.append([float(x) for x in line.split()])
    if not names or not rows:
        sys.exit("plot_history.py: no data in " + path)
    return names, [list(column) for column in zip(*rows)]


def main(history, png):
    names, columns = read(history)
    n = len(names) - 1
    cols = 2 if n > 3 else 1
    rows = (n + cols - 1) // cols
    figure, axes = plt.subplots(rows, cols, figsize=(6 * cols, 2.2 * rows), sharex=True,
                                squeeze=False)
    for i in range(n):
        ax = axes[i // cols][i % cols]
        name = names[i + 1]
        ax.plot(columns[0], columns[i + 1], lw=0.8)
        ax.set_ylabel(name + (" [" + UNITS[name] + "]" if name in UNITS else ""))
        ax.grid(alpha=0.3)
    for i in range(n, rows * cols):
        axes[i // cols][i % cols].set_visible(False)
    for c in range(min(cols, n)):  # the time axis under the lowest panel of each column
        lowest = axes[(n - 1 - c) // cols][c]
        lowest.set_xlabel(names[0] + " [s]")
        lowest.xaxis.set_tick_params(labelbottom=True)
    figure.suptitle(history)
    figure.tight_layout()
    figure.savefig(png, dpi=100)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
