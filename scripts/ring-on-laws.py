#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""How near the ring can come to a tire file's own MF-Tyre laws (docs/models.md section 14.2).

The ring (--model ring) and the cam (--model cam) of FILE are tabled by `tirenv flat --csv`
at the file's load range (0.5 to 1.5 FNOMIN), and the ring keys named by --vary (their logs)
are searched, by Nelder and Mead's simplex, for the ring whose deflection and contact length
are nearest the cam's, i.e. the file's vertical law and contact law (Q_RA1, Q_RA2): the
objective is the L^p norm (--p, 8 by default: near the largest) of the ten relative
differences. BELT_WIDTH is held within --width-bounds times the file's WIDTH (a penalty beyond
them). FILE needs an [ENVELOPING_RING] section: --set changes its keys, each trial is one
`tirenv flat` run. Prints every improvement and the best ring, with its differences in per cent
at each load (deflection, then contact length; + the ring's larger).

--fix KEY=VALUE sets a key for every trial without searching it (e.g. TREAD_SHEAR, NODE_ANGLE).
The softening carcass's keys (CARCASS_SOFTENING_DEFLECTION w_s, CARCASS_LINEAR_DEFLECTION w_0,
docs/models.md section 5.1) are searched as any other, by --vary; a trial the ring refuses (its
carcass pressed beyond w_0 outside the window, a buckling belt) counts as no trial.

--carcass-exponent Q0 also searches q, each load G solved on its own with FOUNDATION_STIFFNESS
times (G/FNOMIN)^q (FNOMIN the table's middle load): a stand-in, load by load, for a carcass
that softens (q < 0) as the tire is pressed in (docs/models.md section 14.2), kept from before
the ring had one (CARCASS_SOFTENING_DEFLECTION). It is not a model: each load is a different
ring.

    scripts/ring-on-laws.py --tire data/tires/205-60R15-mfswift.tir \\
        --vary BELT_WIDTH=0.16 --vary FOUNDATION_STIFFNESS=1.95e5
    scripts/ring-on-laws.py --tire data/tires/205-60R15-mfswift.tir --fix TREAD_SHEAR=5e5 \\
        --vary FOUNDATION_STIFFNESS=1e6 --vary CARCASS_SOFTENING_DEFLECTION=0.005 \\
        --vary CARCASS_LINEAR_DEFLECTION=0.002 --vary BELT_WIDTH=0.1
"""
import argparse
import csv
import io
import math
import os
import subprocess
import sys


def table(tirenv, tire, model, sets, load=None):
    cmd = [tirenv, "flat", "--tire", tire, "--model", model, "--csv"]
    if load is not None:
        cmd += ["--load", f"{load:.17g}"]
    for key, value in sets.items():
        cmd += ["--set", f"{key}={value:.6g}"]
    r = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if r.returncode:
        return None
    return [(float(row["deflection_m"]), float(row["contact_length_m"]), float(row["load_N"]))
            for row in csv.DictReader(io.StringIO(r.stdout))]


def file_width(tire):
    with open(tire, encoding="utf-8") as f:
        for line in f:
            parts = line.split("=")
            if len(parts) >= 2 and parts[0].strip() == "WIDTH":
                return float(parts[1].split()[0].split("$")[0])
    sys.exit(f"ring-on-laws: {tire}: no WIDTH, which bounds BELT_WIDTH")


def simplex(f, x0, step, iters):
    """Nelder and Mead (reflection 1, expansion 2, contraction and shrink 1/2)."""
    n = len(x0)
    pts = [list(x0)] + [[x0[j] + (step if j == i else 0) for j in range(n)] for i in range(n)]
    vals = [f(p) for p in pts]
    for _ in range(iters):
        order = sorted(range(n + 1), key=lambda i: vals[i])
        pts, vals = [pts[i] for i in order], [vals[i] for i in order]
        if vals[-1] - vals[0] < 1e-7:
            break
        c = [sum(p[j] for p in pts[:-1]) / n for j in range(n)]
        xr = [2 * c[j] - pts[-1][j] for j in range(n)]
        fr = f(xr)
        if fr < vals[0]:
            xe = [3 * c[j] - 2 * pts[-1][j] for j in range(n)]
            fe = f(xe)
            pts[-1], vals[-1] = (xe, fe) if fe < fr else (xr, fr)
        elif fr < vals[-2]:
            pts[-1], vals[-1] = xr, fr
        else:
            xc = [(c[j] + pts[-1][j]) / 2 for j in range(n)]
            fc = f(xc)
            if fc < vals[-1]:
                pts[-1], vals[-1] = xc, fc
            else:
                for i in range(1, n + 1):
                    pts[i] = [(pts[0][j] + pts[i][j]) / 2 for j in range(n)]
                    vals[i] = f(pts[i])


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tire", required=True)
    ap.add_argument("--vary", action="append", required=True, metavar="KEY=START")
    ap.add_argument("--tirenv", default=os.path.join(root, "build", "tirenv"))
    ap.add_argument("--p", type=float, default=8)
    ap.add_argument("--iters", type=int, default=150)
    ap.add_argument("--width-bounds", default="0.4,1.0")
    ap.add_argument("--carcass-exponent", type=float, metavar="Q0")
    ap.add_argument("--fix", action="append", default=[], metavar="KEY=VALUE")
    a = ap.parse_args()
    fixed = {v.split("=")[0]: float(v.split("=")[1]) for v in a.fix}
    keys = [v.split("=")[0] for v in a.vary]
    x0 = [math.log(float(v.split("=")[1])) for v in a.vary]
    soften = a.carcass_exponent is not None
    if soften:
        if "FOUNDATION_STIFFNESS" not in keys:
            sys.exit("ring-on-laws: --carcass-exponent needs --vary FOUNDATION_STIFFNESS=...")
        x0.append(a.carcass_exponent)
    lo, hi = (float(s) for s in a.width_bounds.split(","))
    if "BELT_WIDTH" in keys:
        w = file_width(a.tire)
        lo, hi = lo * w, hi * w
    cam = table(a.tirenv, a.tire, "cam", {})
    if cam is None:
        sys.exit(f"ring-on-laws: {a.tire}: tirenv flat --model cam failed")
    best = [math.inf, None]

    def ring_of(sets, q):
        if not soften:
            return table(a.tirenv, a.tire, "ring", sets)
        g_n = cam[len(cam) // 2][2]
        rows = []
        for c in cam:
            s = dict(sets, FOUNDATION_STIFFNESS=sets["FOUNDATION_STIFFNESS"] * (c[2] / g_n) ** q)
            r = table(a.tirenv, a.tire, "ring", s, c[2])
            if r is None:
                return None
            rows += r
        return rows

    def objective(x):
        sets, penalty = dict(fixed), 0.0
        for key, u in zip(keys, x[:len(keys)]):
            v = math.exp(u)
            if key == "BELT_WIDTH" and not lo <= v <= hi:
                penalty += 100 * math.log(v / min(max(v, lo), hi)) ** 2
                v = min(max(v, lo), hi)
            sets[key] = v
        ring = ring_of(sets, x[-1] if soften else 0)
        # The same loads as the cam's, or no trial: `tirenv flat` tables the paper's contact
        # lengths instead of 0.5 to 1.5 FNOMIN for a ring whose FNOMIN lies among their loads.
        if ring is None or [r[2] for r in ring] != [c[2] for c in cam]:
            return math.inf
        e = [r[0] / c[0] - 1 for r, c in zip(ring, cam)]
        e += [r[1] / c[1] - 1 for r, c in zip(ring, cam)]
        obj = sum(abs(x) ** a.p for x in e) ** (1 / a.p) + penalty
        if obj < best[0]:
            best[0], best[1] = obj, sets
            n = len(cam)
            print(f"largest {100 * max(abs(x) for x in e):.2f} %: "
                  + " ".join(f"{k} = {v:.6g}" for k, v in sets.items())
                  + (f" q = {x[-1]:.4f}" if soften else "")
                  + "; deflection " + " ".join(f"{100 * x:+.2f}" for x in e[:n])
                  + "; contact length " + " ".join(f"{100 * x:+.2f}" for x in e[n:]) + " %",
                  flush=True)
        return obj

    simplex(objective, x0, 0.3, a.iters)
    if best[1] is None:
        sys.exit("ring-on-laws: no trial ran")
    print("best: " + " ".join(f"--set {k}={v:.6g}" for k, v in best[1].items())
          + (" (FOUNDATION_STIFFNESS at FNOMIN; see q above)" if soften else ""))


if __name__ == "__main__":
    main()
