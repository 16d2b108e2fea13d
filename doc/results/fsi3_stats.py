# Mean, amplitude and frequency (Turek-Hron definitions: (max + min) / 2, (max - min) / 2, from the
# mean up-crossings) of drag, lift and the displacement of point A in an fsi_history.txt over
# t >= T0, against the FSI3 reference values (../shared/reference/benchmarks.md section 2).
#   usage: /usr/bin/python3 doc/results/fsi3_stats.py OUTPUT/fsi_history.txt T0
import sys
import numpy as np
d = np.loadtxt(sys.argv[1])
t0 = float(sys.argv[2])
m = d[:,0] >= t0
t = d[m,0]
cols = {"drag": 3, "lift": 4, "ux_A": 5, "uy_A": 6}
ref = {"drag": (457.3, 22.66, 10.9), "lift": (2.22, 149.78, 5.3), "ux_A": (-2.69e-3, 2.53e-3, 10.9), "uy_A": (1.48e-3, 34.38e-3, 5.3)}
for k, c in cols.items():
    q = d[m, c]
    lo, hi = q.min(), q.max()
    mean, amp = (hi + lo) / 2, (hi - lo) / 2
    cr = [t[i-1] + (t[i]-t[i-1])*(mean-q[i-1])/(q[i]-q[i-1]) for i in range(1, len(q)) if q[i-1] < mean <= q[i]]
    f = (len(cr)-1)/(cr[-1]-cr[0]) if len(cr) >= 2 else float('nan')
    r = ref[k]
    print(f"{k}: mean {mean:.4g} (ref {r[0]:.4g}), amplitude {amp:.4g} (ref {r[1]:.4g}, {100*(amp-r[1])/r[1]:+.1f}%), frequency {f:.3g} (ref {r[2]}, {100*(f-r[2])/r[2]:+.1f}%)")
