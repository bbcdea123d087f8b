#!/usr/bin/env python3
"""The angular momentum of free bodies (fix esph/integrate, src/esph_spin_watch.h).

Two small cubes (5 particles a side, iron on aluminium, tests/physics/in.tumbling_cubes)
collide off-centre at 50 m/s and leave tumbling. A free body's angular momentum is
constant. Found by a hostile-input round (2026-12-05): with pair_style esph/solid gradient
corrected (the default) the stress forces are not torque-free where a body's kernel
support is cut, and such a small body spins up in free flight without bound (its
internal energy running negative), with no message; gradient torquefree keeps it exact.
Checked:
- corrected: fix esph/integrate warns, naming the body, and the measured drift is real
  (the target's |L| after the contact grows several-fold in free flight);
- torquefree: |L| of both cubes constant to round-off in free flight, no warning;
- a single 5^3 cube spinning freely at 2e4 rad/s with the default gradient (|L| kept to
  0.1 %): no warning (no false alarm on a body that keeps its angular momentum);
- the two-cube warning on 2 ranks as on 1.
About 15 s."""

import esphtest as et

a = et.parse_args()
c = et.Checks("angular momentum of free bodies")
INP = et.source_input(a, "in.tumbling_cubes")
WARN = "the angular momentum of body"


def case(tag, np_=1, **var):
    text = et.run(a, INP, var, np=np_, log=f"log.{tag}")
    th = et.production_thermo(text)
    warns = [l for l in text.splitlines() if l.startswith("WARNING") and WARN in l]
    print(f"INFO {tag}: {len(warns)} warnings; |L| of the cubes at the end "
          f"{th['v_L1'][-1]:.4g} {th['v_L2'][-1]:.4g}")
    return th, warns


def free_flight(th):
    """thermo rows after the last step with contact pairs"""
    last = max(k for k, n in enumerate(th["f_int[2]"]) if n > 0) if max(th["f_int[2]"]) > 0 else 0
    return {k: v[last + 2:] for k, v in th.items()}


th, warns = case("corrected", grad="corrected")
warns_c = warns
ff = free_flight(th)
c.true("corrected: warned", len(warns) > 0, "the drift of a free body is reported")
c.true("corrected: the warning names a body of the scene",
       all(("body 1 " in w) or ("body 2 " in w) for w in warns), "body IDs 1 and 2")
c.less("corrected: the target's |L| grows in free flight (start / end)",
       ff["v_L2"][0] / ff["v_L2"][-1], 0.5,
       "the defect the warning is for: measured x4 to x7 over 3000 steps")

th, warns = case("torquefree", grad="torquefree")
ff = free_flight(th)
for col in ("v_L1", "v_L2"):
    x = ff[col]
    c.less(f"torquefree: {col} in free flight, max relative change", (max(x) - min(x)) / max(x),
           1e-9, "exact up to round-off (measured 0 to the printed 12 digits)")
c.true("torquefree: no warning", len(warns) == 0, "its angular momentum is kept")

th, warns = case("spinning", grad="corrected", spin=1)
x = th["v_L1"]
c.less("free spinning cube, corrected: |L| relative change", (max(x) - min(x)) / x[0], 0.01,
       "measured 1.4e-3 over 4000 steps: a single body with no contact keeps it well")
c.true("free spinning cube, corrected: no warning", len(warns) == 0, "below 5 % of its scale")

for nranks in (2, 4):
    th2, warns2 = case(f"corrected_np{nranks}", np_=nranks, grad="corrected")
    c.true(f"corrected on {nranks} ranks: the same warnings as on 1 rank",
           [w.split(" (src")[0] for w in warns2] == [w.split(" (src")[0] for w in warns_c],
           "the sums are reduced over ranks")
c.done()
