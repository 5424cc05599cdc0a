#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Could softening radial springs make the springs model's patch grow as a tire file's?

A feasibility study for docs/models.md section 14.2 (the 205/60R15's "Not within 5 %"), not
part of tirenv: the springs model on flat ground (sections 4.1, 4.2, 4.4) is solved here in
numpy, with each element's radial spring given a bilinear law

    f(w) = k_r*w                        for w <= w_1
         = k_r*w_1 + beta*k_r*(w - w_1) beyond,      k_r = c_r*dphi, 0 < beta <= 1,

(convex energy: the tip problem stays a unique minimum), the interradial springs k_ir =
c_b/dphi as in tirenv, and the sidewall of section 4.9 in series (rigid up to F_s0, then k_s).
beta = 1 is tirenv's linear law, which the script first compares with `tirenv flat --model
springs` at the file's own keys (--check-only: that alone).

The tips minimise sum_i E(w_i) + 1/2 k_ir sum_i (w_(i+1) - w_i)^2 subject to w_i >= d_i,
d_i = max(0, R0 - z/cos(theta_i)). It is solved by the primal-dual active set of section 4.4
together with each free element's branch of f (a semismooth Newton method: both sets updated
from the last solve until neither changes), half the chain by symmetry, one tridiagonal
(Thomas) solve per pass, vectorised over a table of centre heights. Nothing proves that
iteration converges for the bilinear law, so every table is checked against the optimality
conditions computed from f itself (gradient = reaction to 1e-9 of the largest reaction,
reactions >= 0, w >= d, complementarity); a violation stops the script. The contact length is
tirenv's (src/model/springs_model.c springs_contact_length), with K_ii from the element's
current tangent (k_r or beta*k_r) where the law is bilinear (--kii initial: tirenv's k_r +
2 k_ir; the patch's last element is on the stiff branch in the optima found, so both agree).

The elements' flat ground depends on c_r only through a factor on the force (w_1 is a
deflection), so each shape (c_b/c_r, w_1, beta) is tabled once over the deflection and c_r,
F_s0, k_s are searched on the table. The objective is the largest relative difference of the
hub deflection and the contact length from the cam's and the ring's (`tirenv flat --model cam`,
`--model ring`) at 9 loads from 0.5 to 1.5 FNOMIN: min-max by Nelder and Mead's simplex
(restarted) on the L^16 norm, then on the largest itself. The linear law's optimum comes first,
from `tirenv identify --reference cam,ring --loads ...` (the same min-max in C, docs/models.md
section 14.1, to the four digits it writes; --linear numpy: this script's own search, c_b/c_r
scanned, then golden sections, which the 205/60R15's values came from until the CLI wrote them), and is
re-run by `tirenv flat --set`; the bilinear law's simplex (log c_b/c_r, log w_1, logit beta)
starts from the best 3 of 18 seeds.

Printed: the check (beta = 1 with the file's keys against tirenv), each optimum with its
differences at every load (+ where the springs model's is larger) and its hub tangent, the
bilinear optimum's parameters again at dphi/2 and with the other K_ii, where its knee lies, and
both optima at --check-loads loads (41) between the fitted ones. About 1.5 minutes at 0.5
degrees on one core; --element-angle 0.00436 (0.25 degrees) takes about twice that.

    TIRENV_DATA=data scripts/springs-softening-study.py --tirenv build/tirenv \\
        --tire data/tires/205-60R15-mfswift.tir
"""
import argparse
import csv
import io
import math
import subprocess
import sys

import numpy as np


def tirenv_flat(tirenv, tire, model, load, sets=()):
    """(deflection m, contact length m) of `tirenv flat` at one load."""
    cmd = [tirenv, "flat", "--tire", tire, "--model", model, "--csv", "--load", f"{load:.17g}"]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True, check=True)
    row = list(csv.DictReader(io.StringIO(r.stdout)))[-1]
    return float(row["deflection_m"]), float(row["contact_length_m"])


def tirenv_identify(tirenv, tire, names, loads, sidewall):
    """c_r, c_b, F_s0, k_s of `tirenv identify --reference NAMES --loads ...`: the springs model
    identified on those models together, min-max, to the four digits it writes."""
    cmd = [tirenv, "identify", "--tire", tire, "--reference", ",".join(names),
           "--loads", ",".join(f"{G:.10g}" for G in loads)]
    if sidewall == "none":
        cmd += ["--set", "SIDEWALL_STIFFNESS=0", "--set", "SIDEWALL_PRELOAD=0"]
    elif not tir_keys(tire).get("SIDEWALL_STIFFNESS", 0.0) > 0:
        cmd += ["--set", "SIDEWALL_STIFFNESS=5e5"]  # a start value: asks for a sidewall
    r = subprocess.run(cmd, capture_output=True, text=True, check=True)
    got = {}
    for line in r.stdout.splitlines():
        words = line.split()
        if len(words) > 1 and words[0] in ("RADIAL_STIFFNESS", "INTERRADIAL_STIFFNESS",
                                           "SIDEWALL_PRELOAD", "SIDEWALL_STIFFNESS"):
            got[words[0]] = float(words[1])
    return (got["RADIAL_STIFFNESS"], got["INTERRADIAL_STIFFNESS"],
            got.get("SIDEWALL_PRELOAD", 0.0), got.get("SIDEWALL_STIFFNESS", 0.0))


def tir_keys(tire):
    """The .tir's numeric keys (name -> value), comments dropped."""
    keys = {}
    with open(tire, encoding="utf-8") as f:
        for line in f:
            line = line.split("$")[0]
            if "=" in line and not line.lstrip().startswith(("!", "[")):
                name, value = line.split("=", 1)
                try:
                    keys[name.strip()] = float(value.split()[0].strip("'"))
                except (ValueError, IndexError):
                    pass
    return keys


class Elements:
    """The elements' flat ground, per unit c_r, for one shape (rho = c_b/c_r, w_1, beta)."""

    def __init__(self, R0, dphi, segment=math.pi, kii="tangent"):
        self.R0 = R0
        self.kii = kii
        n = int(math.floor(segment / (2 * dphi))) + 1  # elements 0..i0 of the half chain
        self.dphi = dphi
        self.theta = np.arange(n) * dphi
        self.cos = np.cos(self.theta)
        self.tan = np.where(self.cos > 0, np.tan(self.theta), np.inf)
        self.weight = np.where(np.arange(n) == 0, 1.0, 2.0)  # the centre element once

    def solve(self, z, rho, w1, beta, max_pass=200):
        """Tips w, reactions p, tangents a (per c_r) at centre heights z (array)."""
        kr, kir = self.dphi, rho / self.dphi
        n, m = self.theta.size, z.size
        with np.errstate(divide="ignore"):
            delta = np.where(self.cos > 0, self.R0 - z[:, None] / self.cos, -np.inf)
        d = np.maximum(delta, 0.0)
        pinned = delta > 0
        soft = d > w1
        for _ in range(max_pass):
            a = np.where(soft, beta * kr, kr)
            b = np.where(soft, (1 - beta) * kr * w1, 0.0)
            lo = np.full((m, n), -kir)
            up = np.full((m, n), -kir)
            diag = a + 2 * kir
            up[:, 0] = -2 * kir  # w_(-1) = w_1: symmetry
            diag[:, -1] = a[:, -1] + kir  # end element: one neighbour
            up[:, -1] = 0.0
            lo[:, 0] = 0.0
            rhs = -b
            lo = np.where(pinned, 0.0, lo)
            up = np.where(pinned, 0.0, up)
            kdiag = diag.copy()
            diag = np.where(pinned, 1.0, diag)
            rhs = np.where(pinned, d, rhs)
            w = thomas(lo, diag, up, rhs)
            p = a * w + b + kir * (2 * w - np.roll(w, 1, axis=1) - np.roll(w, -1, axis=1))
            p[:, 0] = a[:, 0] * w[:, 0] + b[:, 0] + 2 * kir * (w[:, 0] - w[:, 1])
            p[:, -1] = a[:, -1] * w[:, -1] + b[:, -1] + kir * (w[:, -1] - w[:, -2])
            p = np.where(pinned, p, 0.0)
            new_pinned = p + kdiag * (d - w) > 0
            new_soft = w > w1
            if np.array_equal(new_pinned, pinned) and np.array_equal(new_soft, soft):
                return w, p, a, kdiag, delta
            pinned, soft = new_pinned, new_soft
        raise RuntimeError(f"no convergence in {max_pass} passes (rho {rho}, w1 {w1}, beta {beta})")

    def table(self, z, rho, w1, beta):
        """Hub force per c_r and contact length (m) at centre heights z."""
        w, p, a, kdiag, delta = self.solve(z, rho, w1, beta)
        f = np.where(w > w1, w1 + beta * (w - w1), w) * self.dphi
        kkt(w, p, f, rho / self.dphi, np.maximum(delta, 0.0))
        if self.kii == "initial":  # tirenv's K_ii = k_r + 2 k_ir whatever the branch
            kdiag = kdiag - a + self.dphi
        F = (self.weight * f * self.cos).sum(axis=1)
        L = np.zeros_like(z)
        for r in range(z.size):
            touch = np.nonzero(p[r] > 0)[0]
            if touch.size == 0:
                continue
            i = touch[-1]
            j = i + 1
            length = 2 * z[r] * self.tan[i]
            if j < self.theta.size and self.cos[j] > 0:
                e_i = p[r, i] / kdiag[r, i] + delta[r, i] - w[r, i]
                e_j = delta[r, j] - w[r, j]
                if e_i > 0 and e_j <= 0:
                    length += 2 * e_i / (e_i - e_j) * z[r] * (self.tan[j] - self.tan[i])
            L[r] = length
        return F, L


def kkt(w, p, f, kir, d):
    """The tip problem's optimality conditions, from the law itself (not the solve's branches):
    gradient = reaction, reaction >= 0, w >= d, complementarity; all per c_r, relative to
    the largest reaction."""
    lap = 2 * w - np.roll(w, 1, axis=1) - np.roll(w, -1, axis=1)
    lap[:, 0] = 2 * (w[:, 0] - w[:, 1])
    lap[:, -1] = w[:, -1] - w[:, -2]
    grad = f + kir * lap
    scale = max(float(np.abs(p).max()), 1e-300)
    bad = max(float(np.abs(grad - p).max()), float(-p.min()), 0.0) / scale
    gap = float((d - w).max()) / max(float(d.max()), 1e-300)
    comp = float(np.abs(p * (w - d)).max()) / (scale * max(float(d.max()), 1e-300))
    if bad > 1e-9 or gap > 1e-12 or comp > 1e-9:
        raise RuntimeError(f"KKT violated: residual {bad:.3g}, gap {gap:.3g},"
                           f" complementarity {comp:.3g}")


def thomas(lo, diag, up, rhs):
    """Tridiagonal solve along axis 1, vectorised over axis 0 (no pivoting: M-matrix rows)."""
    m, n = diag.shape
    c = np.empty((m, n))
    g = np.empty((m, n))
    c[:, 0] = up[:, 0] / diag[:, 0]
    g[:, 0] = rhs[:, 0] / diag[:, 0]
    for i in range(1, n):
        den = diag[:, i] - lo[:, i] * c[:, i - 1]
        c[:, i] = up[:, i] / den
        g[:, i] = (rhs[:, i] - lo[:, i] * g[:, i - 1]) / den
    x = np.empty((m, n))
    x[:, -1] = g[:, -1]
    for i in range(n - 2, -1, -1):
        x[:, i] = g[:, i] - c[:, i] * x[:, i + 1]
    return x


def at_loads(tab, loads, c_r, F_s0, k_s):
    """Hub deflection and contact length at the loads from a shape's table, or None."""
    defl, Fhat, L = tab
    need = loads / c_r
    if need[-1] > Fhat[-1] or need[0] < Fhat[0]:
        return None
    de = np.interp(need, Fhat, defl)
    u = np.maximum(0.0, loads - F_s0) / k_s if k_s > 0 else 0.0
    return de + u, np.interp(de, defl, L)


def nelder_mead(f, x0, step, iters=400, tol=1e-10):
    """Minimise f from x0 (plain simplex: reflection, expansion, contraction, shrink)."""
    x0 = np.asarray(x0, float)
    pts = [x0] + [x0 + s * e for s, e in zip(step, np.eye(x0.size))]
    vals = [f(x) for x in pts]
    for _ in range(iters):
        order = np.argsort(vals)
        pts = [pts[k] for k in order]
        vals = [vals[k] for k in order]
        if vals[-1] - vals[0] <= tol * (abs(vals[0]) + tol):
            break
        c = np.mean(pts[:-1], axis=0)
        xr = c + (c - pts[-1])
        fr = f(xr)
        if fr < vals[0]:
            xe = c + 2 * (c - pts[-1])
            fe = f(xe)
            pts[-1], vals[-1] = (xe, fe) if fe < fr else (xr, fr)
        elif fr < vals[-2]:
            pts[-1], vals[-1] = xr, fr
        else:
            xc = c + 0.5 * (pts[-1] - c) if fr >= vals[-1] else c + 0.5 * (xr - c)
            fc = f(xc)
            if fc < min(fr, vals[-1]):
                pts[-1], vals[-1] = xc, fc
            else:
                pts = [pts[0] + 0.5 * (x - pts[0]) for x in pts]
                vals = [vals[0]] + [f(x) for x in pts[1:]]
    k = int(np.argmin(vals))
    return pts[k], vals[k]


class Study:
    def __init__(self, elements, loads, targets, defl_max, step):
        self.el = elements
        self.loads = loads
        self.targets = targets  # list of (deflections, contact lengths)
        self.defl = np.arange(step, defl_max + step / 2, step)
        self.z = elements.R0 - self.defl
        self.sidewall = "preload"

    def tabulate(self, rho, w1, beta):
        F, L = self.el.table(self.z, rho, w1, beta)
        return self.defl, F, L

    def diffs(self, tab, c_r, F_s0, k_s):
        got = at_loads(tab, self.loads, c_r, F_s0, k_s)
        if got is None:
            return None
        return np.concatenate([np.concatenate([got[0] / t[0] - 1, got[1] / t[1] - 1])
                               for t in self.targets])

    def fit_hub(self, tab, start, p=16):
        """c_r, F_s0, k_s minimising the largest difference for one shape's table."""
        sidewall = self.sidewall

        def unpack(x):
            return math.exp(x[0]), (1000 * x[1] if sidewall == "preload" else 0.0), \
                (math.exp(x[2]) if sidewall != "none" else 0.0)

        def obj(x, p):
            c_r, F_s0, k_s = unpack(x)
            if F_s0 < 0:
                return 1e3 + -F_s0
            r = self.diffs(tab, c_r, F_s0, k_s)
            if r is None:
                return 1e3
            r = np.abs(r)
            return float(r.max()) if p is None else float((r ** p).mean() ** (1 / p))

        best = None
        for x0 in start:
            x, _ = nelder_mead(lambda x: obj(x, p), x0, [0.1, 0.5, 0.3], iters=300)
            x, v = nelder_mead(lambda x: obj(x, None), x, [0.02, 0.1, 0.05], iters=300)
            if best is None or v < best[1]:
                best = (x, v)
        return unpack(best[0]), best[1]


def report(study, tab, hub, label, names):
    """The differences at each load (+ where the springs model's is larger), and its tangent."""
    c_r, F_s0, k_s = hub
    r = study.diffs(tab, c_r, F_s0, k_s)
    n = len(study.loads)
    got = at_loads(tab, study.loads, c_r, F_s0, k_s)
    # Tangent of the hub's law: the elements' (from the table) and the sidewall's in series.
    defl, Fhat, _ = tab
    de = np.interp(study.loads / c_r, Fhat, defl)
    k_e = c_r * np.interp(de, 0.5 * (defl[1:] + defl[:-1]), np.diff(Fhat) / np.diff(defl))
    k = 1 / (1 / k_e + np.where((k_s > 0) & (study.loads > F_s0), 1 / max(k_s, 1e-300), 0.0))
    parts = ", ".join(f"{m} {100 * np.abs(r[2 * n * t:2 * n * (t + 1)]).max():.2f} %"
                      for t, m in enumerate(names))
    print(f"{label}: largest {100 * np.abs(r).max():.2f} %  ({parts})")
    print("   load_N  defl_mm  L_m     k_kN/m  " +
          "  ".join(f"{m}_mm  {m}_L    dd_{m}%  dL_{m}%" for m in names))
    for j, G in enumerate(study.loads):
        cols = "  ".join(f"{1e3 * t[0][j]:6.2f}  {t[1][j]:.4f}  {100 * r[2 * n * q + j]:+6.2f}  "
                         f"{100 * r[2 * n * q + n + j]:+6.2f}" for q, t in enumerate(study.targets))
        print(f"  {G:7.0f}  {1e3 * got[0][j]:6.2f}  {got[1][j]:.4f}  {1e-3 * k[j]:6.1f}  {cols}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tirenv", default="build/tirenv")
    ap.add_argument("--tire", default="data/tires/205-60R15-mfswift.tir")
    ap.add_argument("--loads", type=int, default=9, help="loads from 0.5 to 1.5 FNOMIN")
    ap.add_argument("--step", type=float, default=1e-4, help="deflection table step, m")
    ap.add_argument("--check-only", action="store_true", help="only compare beta = 1 with tirenv")
    ap.add_argument("--sidewall", choices=("preload", "linear", "none"), default="preload",
                    help="the sidewall searched: section 4.9's (F_s0, k_s), F_s0 = 0, or none")
    ap.add_argument("--kii", choices=("tangent", "initial"), default="tangent",
                    help="K_ii of the contact length's ends: the branch's tangent or k_r + 2 k_ir")
    ap.add_argument("--targets", choices=("cam,ring", "cam"), default="cam,ring",
                    help="the models whose deflection and contact length are matched")
    ap.add_argument("--linear", choices=("tirenv", "numpy"), default="tirenv",
                    help="the linear law's min-max: tirenv identify --reference (its four "
                         "digits; not with --sidewall linear) or this script's own search")
    ap.add_argument("--check-loads", type=int, default=41,
                    help="loads from 0.5 to 1.5 FNOMIN at which the optima are checked")
    ap.add_argument("--element-angle", type=float, default=None,
                    help="ELEMENT_ANGLE dphi, rad (default: the file's, else pi/360)")
    args = ap.parse_args()
    if args.sidewall == "linear":
        args.linear = "numpy"  # tirenv identify's sidewall has its preload

    keys = tir_keys(args.tire)
    R0, FNOMIN = keys["UNLOADED_RADIUS"], keys["FNOMIN"]
    dphi = args.element_angle or keys.get("ELEMENT_ANGLE", math.pi / 360)
    c_r, c_b = keys["RADIAL_STIFFNESS"], keys["INTERRADIAL_STIFFNESS"]
    F_s0, k_s = keys.get("SIDEWALL_PRELOAD", 0.0), keys.get("SIDEWALL_STIFFNESS", 0.0)
    loads = np.linspace(0.5, 1.5, args.loads) * FNOMIN
    targets = []
    names = args.targets.split(",")
    for model in names:
        t = [tirenv_flat(args.tirenv, args.tire, model, G) for G in loads]
        targets.append((np.array([a for a, _ in t]), np.array([b for _, b in t])))
    study = Study(Elements(R0, dphi, kii=args.kii), loads, targets, defl_max=0.06, step=args.step)
    study.sidewall = args.sidewall

    # The linear law (beta = 1) against tirenv's springs model with the file's own keys.
    tab = study.tabulate(c_b / c_r, 1.0, 1.0)
    got = at_loads(tab, loads, c_r, F_s0, k_s)
    worst = 0.0
    print(f"check: linear law, the file's c_r {c_r:g}, c_b {c_b:g}, F_s0 {F_s0:g}, k_s {k_s:g}")
    for k, G in enumerate(loads):
        ref = tirenv_flat(args.tirenv, args.tire, "springs", G, [f"ELEMENT_ANGLE={dphi:.17g}"])
        dd, dl = got[0][k] / ref[0] - 1, got[1][k] / ref[1] - 1
        worst = max(worst, abs(dd), abs(dl))
        print(f"  {G:6.0f} N  deflection {1e3 * got[0][k]:.4f} / tirenv {1e3 * ref[0]:.4f} mm"
              f" ({100 * dd:+.3f} %), contact length {got[1][k]:.5f} / {ref[1]:.5f} m"
              f" ({100 * dl:+.3f} %)")
    print(f"check: largest difference from tirenv {100 * worst:.3f} %")
    report(study, tab, (c_r, F_s0, k_s), "the file's springs model", names)
    if args.check_only:
        return

    def pack(hub):
        return [math.log(hub[0]), hub[1] / 1000, math.log(hub[2] if hub[2] > 0 else 6e5)]

    hub0 = [pack((c_r, F_s0, k_s)), pack((c_r, 0.0, 4e5)), pack((0.7 * c_r, 4000.0, 1e6))]

    if args.linear == "tirenv":
        # The linear law's min-max is `tirenv identify --reference` (docs/models.md 14.1), in
        # C, to the four digits it writes: this script's own search, below, is --linear numpy.
        c_r1, c_b1, F1, k1 = tirenv_identify(args.tirenv, args.tire, names, loads, args.sidewall)
        hub = (c_r1, F1, k1)
        best = (c_b1 / c_r1, hub,
                float(np.abs(study.diffs(study.tabulate(c_b1 / c_r1, 1.0, 1.0), *hub)).max()))
    else:
        # Linear law: the shape is c_b/c_r alone; a scan, then golden sections on log(c_b/c_r).
        def linear(rho, start):
            return study.fit_hub(study.tabulate(rho, 1.0, 1.0), start)

        best = None
        for rho in np.geomspace(1e-4, 0.3, 25):
            hub, v = linear(rho, hub0)
            if best is None or v < best[2]:
                best = (rho, hub, v)
        lo, hi = best[0] / 1.4, best[0] * 1.4
        for _ in range(12):
            m1, m2 = lo * (hi / lo) ** 0.382, lo * (hi / lo) ** 0.618
            start = [hub0[0], pack(best[1])]
            (h1, v1), (h2, v2) = linear(m1, start), linear(m2, start)
            for rho, hub, v in ((m1, h1, v1), (m2, h2, v2)):
                if v < best[2]:
                    best = (rho, hub, v)
            if v1 < v2:
                hi = m2
            else:
                lo = m1
    rho, hub, v = best
    print(f"\nlinear law: c_b/c_r {rho:.4g} rad^2, c_r {hub[0]:.4g}, c_b {rho * hub[0]:.4g},"
          f" F_s0 {hub[1]:.0f} N, k_s {hub[2]:.4g} N/m")
    report(study, study.tabulate(rho, 1.0, 1.0), hub, "linear law", names)
    sets = [f"RADIAL_STIFFNESS={hub[0]:.17g}", f"INTERRADIAL_STIFFNESS={rho * hub[0]:.17g}",
            f"SIDEWALL_PRELOAD={hub[1]:.17g}", f"SIDEWALL_STIFFNESS={hub[2]:.17g}"]
    if not hub[2] > 0:  # tirenv refuses a preload without a stiffness, even a transient one
        sets[2:] = ["SIDEWALL_PRELOAD=0", "SIDEWALL_STIFFNESS=0"]
    worst = 0.0
    for k, G in enumerate(loads):
        ref = tirenv_flat(args.tirenv, args.tire, "springs", G,
                          [f"ELEMENT_ANGLE={dphi:.17g}"] + sets)
        worst = max([worst] + [abs(ref[q] / t[q][k] - 1) for t in targets for q in (0, 1)])
    print(f"  the same with tirenv flat --model springs --set ...: largest {100 * worst:.2f} %")
    lin = ((rho, 1.0, 1.0), hub)
    sys.stdout.flush()

    # Bilinear law: (log rho, log w_1, logit beta) by the simplex, each trial a table.
    cache = {}

    def shape_obj(x):
        rho, w1, beta = math.exp(x[0]), math.exp(x[1]), 1 / (1 + math.exp(-x[2]))
        key = tuple(np.round(x, 12))
        if key not in cache:
            start = [pack(cache_best[0][1])] + hub0
            hub, v = study.fit_hub(study.tabulate(rho, w1, beta), start)
            cache[key] = (hub, v)
            if v < cache_best[0][2]:
                cache_best[0] = ((rho, w1, beta), hub, v)
                print(f"  bilinear: {100 * v:.3f} %  c_b/c_r {rho:.4g}, w_1 {1e3 * w1:.3f} mm,"
                      f" beta {beta:.4f}, c_r {hub[0]:.4g}, F_s0 {hub[1]:.0f} N, k_s {hub[2]:.4g}",
                      flush=True)
        return cache[key][1]

    cache_best = [((rho, 1.0, 1.0), hub, v)]
    seeds = []
    for r0 in (rho, 2 * rho, 4 * rho):
        for w1 in (0.004, 0.008, 0.015):
            for beta in (0.3, 0.6):
                seeds.append((shape_obj([math.log(r0), math.log(w1), math.log(beta / (1 - beta))]),
                              [math.log(r0), math.log(w1), math.log(beta / (1 - beta))]))
    seeds.sort(key=lambda s: s[0])
    for _, x0 in seeds[:3]:
        nelder_mead(shape_obj, x0, [0.4, 0.4, 0.6], iters=80, tol=1e-6)
    (rho, w1, beta), hub, v = cache_best[0]
    print(f"\nbilinear law: c_b/c_r {rho:.4g} rad^2, w_1 {1e3 * w1:.3f} mm, beta {beta:.4f},"
          f" c_r {hub[0]:.4g}, c_b {rho * hub[0]:.4g}, F_s0 {hub[1]:.0f} N, k_s {hub[2]:.4g} N/m")
    tab = study.tabulate(rho, w1, beta)
    report(study, tab, hub, "bilinear law", names)
    _, F, _ = tab
    knee = hub[0] * np.interp(w1, tab[0], F)
    for label, el in ((f"ELEMENT_ANGLE {dphi / 2:.6g} rad", Elements(R0, dphi / 2, kii=args.kii)),
                      ("K_ii " + ("initial" if args.kii == "tangent" else "tangent"),
                       Elements(R0, dphi, kii="initial" if args.kii == "tangent" else "tangent"))):
        other = Study(el, loads, targets, defl_max=0.06, step=args.step)
        r = other.diffs(other.tabulate(rho, w1, beta), *hub)
        print(f"  the same parameters with {label}: largest {100 * np.abs(r).max():.2f} %")
    print(f"  knee: tip deflection w_1 = {1e3 * w1:.3f} mm; the centre element reaches it at an"
          f" elements' load of about {knee:.0f} N (centre deflection = w_1)")

    # Both optima between the fitted loads: the contact length's edge interpolation makes it
    # wave as elements join the patch, which 9 loads can miss.
    dense = np.linspace(0.5, 1.5, args.check_loads) * FNOMIN
    dt = []
    for model in names:
        t = [tirenv_flat(args.tirenv, args.tire, model, G) for G in dense]
        dt.append((np.array([a for a, _ in t]), np.array([b for _, b in t])))
    check = Study(Elements(R0, dphi, kii=args.kii), dense, dt, defl_max=0.06, step=args.step)
    for label, (shape, h) in (("linear", lin), ("bilinear", ((rho, w1, beta), hub))):
        r = np.abs(check.diffs(check.tabulate(*shape), *h))
        j = int(np.argmax(r))
        q, rest = divmod(j, 2 * len(dense))
        what, at = ("deflection", "contact length")[rest // len(dense)], dense[rest % len(dense)]
        print(f"  {label} optimum at {len(dense)} loads: largest {100 * r[j]:.2f} %"
              f" ({what} against the {names[q]} at {at:.0f} N)")


if __name__ == "__main__":
    main()
