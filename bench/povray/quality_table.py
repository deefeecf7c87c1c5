#!/usr/bin/python3
"""The table bench/povray/quality.sh prints from its CSV: for raytex's best method at one sample
per pixel, the time POV-Ray needs to reach its error, and the ratio of the times.
Usage: bench/povray/quality_table.py QUALITY.csv
"""
import csv
import math
import sys

SAME_PATTERN = ("aSolidChecker", "aChecker", "anImage")  # README.md: the same patterns


def lower_hull(points):
    """The Pareto front of (time, error, ...) points (faster or more accurate than every other), then
    its lower convex hull in log(time)-log(error): the best trade-off POV-Ray's settings offer,
    the reading most in its favour."""
    front, best = [], math.inf
    for p in sorted(points):
        if p[0] > 0 and 0 < p[1] < best:
            front.append(p)
            best = p[1]
    hull = []
    for p in front:
        while len(hull) >= 2:
            (x0, y0), (x1, y1), (x2, y2) = [(math.log(q[0]), math.log(q[1])) for q in (hull[-2], hull[-1], p)]
            if (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0) > 0:
                break
            hull.pop()
        hull.append(p)
    return hull


def time_to_reach(points, target):
    """(bound, time_ms, how): the time POV-Ray needs to reach error `target`. bound is "" for a
    time interpolated between two settings, ">=" when no setting reaches it (the time of the
    most accurate one), "<=" when the fastest already does (its time)."""
    hull = lower_hull(points)
    if not hull:
        return ">=", math.nan, "no POV-Ray point"
    if target >= hull[0][1]:
        return "<=", hull[0][0], f"fastest: {hull[0][2]}, error {hull[0][1]:.5f}"
    for (t0, e0, s0), (t1, e1, s1) in zip(hull, hull[1:]):
        if e0 > target >= e1:
            a = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return "", math.exp(math.log(t0) + a * (math.log(t1) - math.log(t0))), f"between {s0} and {s1}"
    return ">=", hull[-1][0], f"best: {hull[-1][2]}, error {hull[-1][1]:.5f}"


def fmt(bound, x):
    return f"{bound}{x:.1f}" if bound else f"{x:.1f}"


def compare(rows, m, rmse_key, flip_key):
    """raytex's best 1-spp method on material m against POV-Ray; None without the points."""
    rt = [r for r in rows if r["material"] == m and r["renderer"] == "raytex" and r["setting"].endswith(" spp1")]
    # Against raytex's reference the converged render is one more POV-Ray setting.
    kinds = ("povray", "povray-converged") if rmse_key == "rmse_ref" else ("povray",)
    pov = [r for r in rows if r["material"] == m and r["renderer"] in kinds]
    if not rt or not pov:
        return None
    best = min(rt, key=lambda r: float(r["rmse"]))
    t_r = float(best["time_ms"])
    res = {"method": best["setting"].replace(" spp1", ""), "t_r": t_r}
    for key, col in (("rmse", rmse_key), ("flip", flip_key)):
        target = float(best[key])
        bound, t_p, how = time_to_reach([(float(r["time_ms"]), float(r[col]), r["setting"]) for r in pov], target)
        res[key] = (target, bound, t_p, t_p / t_r, how)
    return res


def table(rows, materials, rmse_key, flip_key, title):
    line = "%-13s %-9s %8s %7s %10s %8s %7s %12s %8s"
    print(title)
    print(line % ("material", "best", "E rmse", "T_r ms", "POV ms @E", "ratio", "FLIP_r", "POV ms @FLIP", "ratio"))
    ratios, notes = [], []
    for m in materials:
        c = compare(rows, m, rmse_key, flip_key)
        if c is None:
            continue
        e, b, t_p, q, how = c["rmse"]
        f, bf, t_pf, qf, _ = c["flip"]
        print(line % (m, c["method"], f"{e:.5f}", f"{c['t_r']:.1f}", fmt(b, t_p), fmt(b, q), f"{f:.4f}",
                      fmt(bf, t_pf), fmt(bf, qf)))
        ratios.append((b, q))
        notes.append(f"  {m}: POV-Ray reaches RMSE {e:.5f} at {fmt(b, t_p)} ms ({how})")
    for n in notes:
        print(n)
    vals = [q for _, q in ratios if q == q and q > 0]
    if vals:
        gm = math.exp(sum(math.log(q) for q in vals) / len(vals))
        met = sum(1 for b, q in ratios if q >= 50 and b != "<=")
        print(f"ratio by RMSE: min {min(vals):.1f}, geometric mean {gm:.1f}; goal >= 50x met in {met} of {len(vals)}")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: bench/povray/quality_table.py QUALITY.csv")
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    materials = list(dict.fromkeys(r["material"] for r in rows))
    table(rows, materials, "rmse", "flip",
          "Each renderer against its own converged image (POV-Ray: its converged render; raytex: its reference)")
    print()
    print("POV ms @E: POV-Ray's Trace Time to reach raytex's RMSE E, interpolated in log(time)-log(error)")
    print("on the lower convex hull of its settings' points; >=: no setting reaches E (the most accurate")
    print("one's time); <=: its fastest setting already does. ratio = POV-Ray / raytex (frame time).")
    print("FLIP columns: the same for raytex's mean FLIP.")

    shown = [m for m in materials if m in SAME_PATTERN]
    if shown:
        print()
        table(rows, shown, "rmse_ref", "flip_ref",
              "Both against raytex's float64 reference (the materials whose patterns match in the two scenes)")

    print()
    print("POV-Ray's converged render against raytex's reference (RMSE, FLIP):")
    for r in rows:
        if r["renderer"] == "povray-converged":
            print(f"  {r['material']:<13} {float(r['rmse_ref']):.5f} {float(r['flip_ref']):.4f}"
                  f"  (its trace {float(r['time_ms']) / 1000:.1f} s)")


if __name__ == "__main__":
    main()
