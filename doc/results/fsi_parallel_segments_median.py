#!/usr/bin/env python3
"""Median of several passes of doc/results/fsi_parallel_segments.sh (performance.md, section 8).

Each pass runs the same 17 segments of the shipped FSI3 run on one and on two ranks from the same
checkpoints; the work of a segment is the same in every pass (checked here: time steps, coupling
iterations, solid outer iterations, pressure solves and their CG iterations), so the passes differ
only by the machine. For each segment this takes the median of its one-rank loop times T1 and the
median of its two-rank loop times T2 over the passes, and prints

    E = sum of median T1 / (2 sum of median T2)

beside each pass's own E. Reads the passes' segments.json from doc/results/fsi_parallel_segments.json
(the shipped raw data) or from what the command line names: run directories, and files of the
shipped raw data's form (their passes are taken under the file's name), e.g. the three passes of
one binary and a pass of another on the same segments (the same work is checked).

  usage: doc/results/fsi_parallel_segments_median.py [RUN_DIRECTORY | RAW_DATA.json ...]
"""
import json
import os
import statistics
import sys

WORK = ["time_steps", "coupling_iterations", "solid_outer_iterations",
        "fluid_pressure_linear_solves", "fluid_pressure_iterations_per_solve"]


def load_passes(arguments):
    if not arguments:
        shipped = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                               "fsi_parallel_segments.json")
        return json.load(open(shipped))["passes"]
    passes = {}
    for a in arguments:
        if a.endswith(".json"):
            for name, data in json.load(open(a))["passes"].items():
                passes["%s: %s" % (os.path.basename(a), name)] = data
        else:
            passes[a] = json.load(open(os.path.join(a, "segments.json")))
    return passes


def loop_seconds(segment):
    """(T1, T2): the time-step loop's wall time on one and on two ranks [s]."""
    return segment["loop_seconds"]


QUIET = {"geometry": 0.93, "fluid: predicted fluxes": 1.10}


def section_efficiency(segment, section):
    """A section's efficiency T1 / (2 T2) in a segment, None where the segment did not run it. The
    geometry and the predicted fluxes are local loops with no communication: at or above QUIET
    when the machine is quiet (each rank's half fits the caches better), below it when the
    moment was disturbed."""
    one, two = (t.get(section, 0.0) for t in segment["timing"])
    return one / (2 * two) if two > 0 else None


def moment(segment):
    """The check on the moment: the geometry's efficiency, or the predicted fluxes' where the
    fluid ran alone (no mesh motion); a '*' marks a disturbed run (below QUIET)."""
    for section in QUIET:
        e = section_efficiency(segment, section)
        if e is not None:
            tag = " (pf)" if section != "geometry" else ""
            return "%.0f%%%s%s" % (100 * e, tag, "*" if e < QUIET[section] else "")
    return "-"


def check_same_work(passes):
    """The passes must have done the same work segment by segment, or their times do not compare."""
    names = list(passes)
    first = passes[names[0]]["segments"]
    for name in names[1:]:
        for a, b in zip(first, passes[name]["segments"]):
            for r in (0, 1):
                for key in WORK:
                    if key in a["results"][r] and a["results"][r][key] != b["results"][r].get(key):
                        sys.exit("fsi_parallel_segments_median.py: segment %d, %d rank(s): %s differs "
                                 "between %s and %s" % (a["segment"], r + 1, key, names[0], name))


def main():
    passes = load_passes(sys.argv[1:])
    if len(passes) < 2:
        sys.exit("fsi_parallel_segments_median.py: needs two passes or more")
    check_same_work(passes)
    names = list(passes)
    n = len(passes[names[0]]["segments"])
    print("| segment | T1 per pass [s] | T2 per pass [s] | E per pass | geometry E per pass (pf: predicted fluxes; *: disturbed) "
          "| median T1, T2 [s] | E of medians |")
    print("|---|---|---|---|---|---|---|")
    M1 = M2 = 0.0
    for k in range(n):
        t1 = [loop_seconds(passes[p]["segments"][k])[0] for p in names]
        t2 = [loop_seconds(passes[p]["segments"][k])[1] for p in names]
        m1, m2 = statistics.median(t1), statistics.median(t2)
        M1 += m1
        M2 += m2
        geometry = ", ".join(moment(passes[p]["segments"][k]) for p in names)
        print("| %d | %s | %s | %s | %s | %.1f, %.1f | %.0f%% |"
              % (k + 1, ", ".join("%.1f" % t for t in t1), ", ".join("%.1f" % t for t in t2),
                 ", ".join("%.0f%%" % (100 * a / (2 * b)) for a, b in zip(t1, t2)), geometry,
                 m1, m2, 100 * m1 / (2 * m2)))
    totals = [(sum(loop_seconds(s)[0] for s in passes[p]["segments"]),
               sum(loop_seconds(s)[1] for s in passes[p]["segments"])) for p in names]
    print("| **all** | %s | %s | %s | | %.1f, %.1f | **%.1f%%** |"
          % (", ".join("%.1f" % a for a, _ in totals), ", ".join("%.1f" % b for _, b in totals),
             ", ".join("%.1f%%" % (100 * a / (2 * b)) for a, b in totals), M1, M2, 100 * M1 / (2 * M2)))
    fastest = [sum(min(loop_seconds(passes[p]["segments"][k])[r] for p in names) for k in range(n))
               for r in (0, 1)]
    print("\nmedian of the passes' own E: %.1f%%; from each segment's fastest T1 and T2: %.1f%%"
          % (100 * statistics.median(a / (2 * b) for a, b in totals),
             100 * fastest[0] / (2 * fastest[1])))
    # The coupled segment runs whose geometry ran at its quiet efficiency: a filter on a section
    # that is part of the loop time, so it selects the outcome in part.
    coupled = [s for p in names for s in passes[p]["segments"]
               if section_efficiency(s, "geometry") is not None]
    quiet = [s for s in coupled if section_efficiency(s, "geometry") >= QUIET["geometry"]]
    geometry_share = (sum(s["timing"][0]["geometry"] for s in coupled)
                      / sum(loop_seconds(s)[0] for s in coupled))
    print("over the %d of %d coupled segment runs with geometry E >= %.0f%%: %.1f%% (the geometry is "
          "%.1f%% of T1)" % (len(quiet), len(coupled), 100 * QUIET["geometry"],
                             100 * sum(loop_seconds(s)[0] for s in quiet)
                             / (2 * sum(loop_seconds(s)[1] for s in quiet)), 100 * geometry_share))


if __name__ == "__main__":
    main()
