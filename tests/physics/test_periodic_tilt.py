#!/usr/bin/env python3
"""Bodies across the faces of a tilted periodic box (tests/physics/in.tilted_periodic: an
iron and an aluminium block in a box periodic in x and y with tilt xy = 1 mm, 800 steps,
contact from 3.92 us). Translating the whole scene is an exact symmetry of a periodic box:
every shift must give the same boundary particles, the same contact and the same momenta
(to round-off: the atoms' order, and so the order of the sums, changes). Before
fix esph/boundary made the periodic images of a tilted box from its box vectors, the blocks
moved across the slanted x faces got 66 boundary particles instead of 68 and 62 % more
lateral momentum, across the y faces 224 / 80 and normals 60 degrees off, without a message.
About 15 s."""

import esphtest as et

a = et.parse_args()
c = et.Checks("a tilted periodic box")
INP = et.source_input(a, "in.tilted_periodic")


def tilted(name, np_=1, **var):
    text = et.run(a, INP, var, np=np_, log=f"log.{name}")
    return et.summary(text, "TILTED"), text


ref, _ = tilted("orthogonal", xy=0.0)
print(f"INFO orthogonal box, no shift: {ref}")
c.true("the blocks came into contact", ref["tc_us"] > 0.1, "contact longer than 0.1 us")
cases = [("tilted", {}, 1), ("across x faces", {"sx": 2.5e-3}, 1),
         ("across x faces (kernel reach only)", {"sx": 2.0e-3}, 1),
         ("across y faces", {"sy": 1.7e-3}, 1), ("across both", {"sx": 2.5e-3, "sy": 1.7e-3}, 1),
         ("across both, np 2", {"sx": 2.5e-3, "sy": 1.7e-3}, 2)]
for name, var, np_ in cases:
    s, text = tilted(name.replace(" ", "_").replace(",", "").replace("(", "").replace(")", ""), np_,
               **var)
    print(f"INFO {name}: {s}")
    for k in ("nbndA", "nbndB"):
        c.near(f"{name}: boundary particles {k}", s[k], ref[k], 0,
                "a translation of the scene: the same boundary particles")
    for k in ("first_us", "tc_us"):
        c.near(f"{name}: {k}", s[k], ref[k], 1e-9, "the same contact steps")
    for k in ("pAx", "pAy", "etot"):
        c.near(f"{name}: {k} relative", s[k], ref[k], 1e-8 * abs(ref[k]),
                "round-off of sums in another order")
    c.true(f"{name}: no warning", "WARNING" not in text,
           "nothing is wrong with the scene (the bodies' normals were warned about when wrong)")
c.done()
