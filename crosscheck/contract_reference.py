# The contract of shared/design/physics.md (section 2, 3's "yade" damping, 7.1 rolling
# resistance in the "yade" form, 7.2 Hertz-Mindlin) for scenes of spheres without walls, in
# plain Python (no YADE, no colza): an independent third implementation, to tell whether a
# YADE series (yade-scripts/run_scene.py) follows the contract, and how far a slip in the
# contract would move a scene (--variant). crosscheck/YADE_MECHANISMS.md has the results.
#
#   python3 crosscheck/contract_reference.py SCENE.toml YADE_SERIES.csv [--variant NAME]
#
# Prints, per recorded particle and quantity, max |reference - YADE| and the crosscheck micro
# metric (divided by max(max |reference signal|, floor), positions as displacements). Only the
# "series" stiffness rule with one particle material and listed particles; anything else is
# refused. Variants (deliberate slips, to measure what a scene detects):
#   mr_no_rotation   Mr not carried into the new frame     mr_no_tilt    twist only   mr_no_twist   tilt only
#   mr_twist_n_new   Mr's twist about n_new                mr_project    Mr projected on the tangent plane
#   bend_n_old       bending part of w2 - w1 about n_old   kr_pfc        kr = beta Ks R*^2
#   cap_pfc          cap mu_r R* max(Fn, 0)                kt_old_un     Mindlin kt from last step's overlap
import csv
import math
import sys
import tomllib

VARIANTS = ("mr_no_rotation", "mr_no_tilt", "mr_no_twist", "mr_twist_n_new", "mr_project", "bend_n_old", "kr_pfc", "cap_pfc",
            "kt_old_un")
FLOOR = {"": 1e-12, "v": 1e-12, "w": 1e-9, "f": 1e-12, "t": 1e-15}  # data/crosscheck-tolerances.toml [micro.floor]


def add(a, b):
    return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def mul(s, a):
    return [s * a[0], s * a[1], s * a[2]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def refuse(msg):
    sys.exit("contract_reference: " + msg)


def run(doc, variant):
    part, ct, integ, scene = doc["particle"], doc.get("contact", {}), doc["integration"], doc["scene"]
    if scene.get("walls") or scene.get("packing_file") or ct.get("stiffness_rule", "series") != "series":
        refuse("only listed spheres, no walls, the series stiffness rule")
    if ct.get("bond", "none") != "none" or ct.get("damping", "none") != "none":
        refuse("no bonds, no viscous damping")
    dt, g, alpha = float(integ["time_step"]), integ.get("gravity", [0.0, 0.0, -9.81]), integ.get("damping", 0.7)
    if alpha and integ.get("damping_form", "pfc") != "yade":
        refuse('local damping in the "yade" form only')
    hertz = ct.get("normal", "linear") == "hertz"
    if (ct.get("normal", "linear"), ct.get("tangential", "coulomb")) not in (("linear", "coulomb"), ("hertz", "mindlin")):
        refuse("linear + coulomb or hertz + mindlin only")
    rolling = ct.get("rolling", "none") == "elastic_plastic"
    ep = ct.get("elastic_plastic", {})
    if rolling and (ep.get("form", "yade") != "yade" or hertz):
        refuse('rolling in the "yade" form with the linear law only')
    mu = part["friction"]
    kn = part["normal_stiffness"] * part["normal_stiffness"] / (2 * part["normal_stiffness"])   # series rule
    ks = part["shear_stiffness"] * part["shear_stiffness"] / (2 * part["shear_stiffness"])
    if hertz:  # physics.md 7.2, two bodies of the same material
        e, nu = part["young_modulus"], part["poisson_ratio"]
        e_star = 1.0 / ((1 - nu * nu) / e + (1 - nu * nu) / e)
        g_star = 1.0 / (2 * (2 - nu) * (1 + nu) / e + 2 * (2 - nu) * (1 + nu) / e)
    bodies = []
    for sp in scene["particles"]:
        r = sp["radius"]
        m = part["density"] * 4.0 / 3.0 * math.pi * r * r * r
        bodies.append({"x": [float(c) for c in sp.get("position", [0, 0, 0])],
                       "v": [float(c) for c in sp.get("velocity", [0, 0, 0])],
                       "w": [float(c) for c in sp.get("angular_velocity", [0, 0, 0])],
                       "R": r, "m": m, "I": 0.4 * m * r * r, "fixed": sp.get("fixed", False)})
    history = {}
    rows = []
    for step in range(scene["steps"]):
        force = [[0.0] * 3 for _ in bodies]
        torque = [[0.0] * 3 for _ in bodies]
        contacts = 0
        for i in range(len(bodies)):
            for j in range(i + 1, len(bodies)):
                b1, b2 = bodies[i], bodies[j]
                d = sub(b2["x"], b1["x"])
                dist = norm(d)
                un = b1["R"] + b2["R"] - dist
                if un < 0:
                    history.pop((i, j), None)
                    continue
                n = mul(1 / dist, d)
                c = add(b1["x"], mul(b1["R"] - un / 2, n))
                h = history.get((i, j))
                fs, mr = [0.0] * 3, [0.0] * 3
                if h is not None:  # step 2: carry Fs and Mr into the new tangent plane
                    fs, mr, n_old = h["fs"], h["mr"], h["n"]
                    tilt = cross(n_old, n)
                    twist = mul(dt * 0.5 * dot(add(b1["w"], b2["w"]), n_old), n_old)
                    fs = sub(fs, cross(fs, tilt))
                    fs = sub(fs, cross(fs, twist))
                    if variant == "mr_twist_n_new":
                        twist = mul(dt * 0.5 * dot(add(b1["w"], b2["w"]), n), n)
                    if variant != "mr_no_rotation":
                        if variant != "mr_no_tilt":
                            mr = sub(mr, cross(mr, tilt))
                        if variant != "mr_no_twist":
                            mr = sub(mr, cross(mr, twist))
                    if variant == "mr_project":
                        mr = sub(mr, mul(dot(mr, n), n))
                vr = sub(add(b2["v"], cross(b2["w"], sub(c, b2["x"]))), add(b1["v"], cross(b1["w"], sub(c, b1["x"]))))
                dus = mul(dt, sub(vr, mul(dot(vr, n), n)))
                r_star = b1["R"] * b2["R"] / (b1["R"] + b2["R"])
                if hertz:
                    fn = 4.0 / 3.0 * e_star * math.sqrt(r_star) * un ** 1.5
                    kt = 8 * g_star * math.sqrt(r_star * (h["un"] if variant == "kt_old_un" and h else un))
                else:
                    fn, kt = kn * un, ks
                fs = sub(fs, mul(kt, dus))
                cap = mu * max(fn, 0.0)
                if norm(fs) > cap:
                    fs = mul(cap / norm(fs), fs)
                if rolling:  # physics.md 7.1
                    kr = ep["stiffness_factor"] * ks * (r_star * r_star if variant == "kr_pfc" else b1["R"] * b2["R"])
                    wr = sub(b2["w"], b1["w"])
                    nb = h["n"] if variant == "bend_n_old" and h else n
                    mr = sub(mr, mul(kr * dt, sub(wr, mul(dot(wr, nb), nb))))
                    cap_r = ep["friction"] * (r_star if variant == "cap_pfc" else min(b1["R"], b2["R"])) * max(fn, 0.0)
                    if norm(mr) > cap_r:
                        mr = mul(cap_r / norm(mr), mr)
                history[(i, j)] = {"fs": fs, "mr": mr, "n": n, "un": un}
                f2 = add(mul(fn, n), fs)  # on body 2; body 1 gets -f2
                force[j] = add(force[j], f2)
                force[i] = sub(force[i], f2)
                torque[j] = add(torque[j], cross(sub(c, b2["x"]), f2))
                torque[i] = sub(torque[i], cross(sub(c, b1["x"]), f2))
                torque[j] = add(torque[j], mr)
                torque[i] = sub(torque[i], mr)
                contacts += 1
        row = {"contacts": contacts}
        for k in scene.get("record_particles", []):
            b = bodies[k]
            for q, vec in (("", b["x"]), ("v", b["v"]), ("w", b["w"]), ("f", force[k]), ("t", torque[k])):
                for a, val in zip("xyz", vec):
                    row[f"p{k}_{q}{a}"] = val
        rows.append(row)
        for k, b in enumerate(bodies):  # leapfrog, "yade" local damping; fixed bodies keep v, w
            if not b["fixed"]:
                acc = [force[k][q] / b["m"] + g[q] for q in range(3)]
                ang = [torque[k][q] / b["I"] for q in range(3)]
                for q in range(3):
                    if alpha:
                        acc[q] *= 1 - alpha * math.copysign(1.0, acc[q] * (b["v"][q] + 0.5 * dt * acc[q]))
                        ang[q] *= 1 - alpha * math.copysign(1.0, ang[q] * (b["w"][q] + 0.5 * dt * ang[q]))
                b["v"] = add(b["v"], mul(dt, acc))
                b["w"] = add(b["w"], mul(dt, ang))
            b["x"] = add(b["x"], mul(dt, b["v"]))
    return rows


def main(argv):
    variant = ""
    if len(argv) == 4 and argv[2] == "--variant" and argv[3] in VARIANTS:
        variant = argv[3]
    elif len(argv) != 2:
        refuse("usage: contract_reference.py SCENE.toml YADE_SERIES.csv [--variant " + "|".join(VARIANTS) + "]")
    with open(argv[0], "rb") as f:
        doc = tomllib.load(f)
    rows = run(doc, variant)
    with open(argv[1]) as f:
        yade = list(csv.DictReader(f))
    if len(yade) != len(rows):
        refuse("the YADE series has another number of rows (record_interval must be 1)")
    worst = 0.0
    contacts_differ = sum(1 for r, y in zip(rows, yade) if r["contacts"] != int(float(y["contacts"])))
    for k in doc["scene"].get("record_particles", []):
        for q in ("", "v", "w", "f", "t"):
            diff = signal = 0.0
            for a in "xyz":
                key = f"p{k}_{q}{a}"
                x0 = rows[0][key] if q == "" else 0.0
                for r, y in zip(rows, yade):
                    diff = max(diff, abs(r[key] - float(y[key])))
                    signal = max(signal, abs(r[key] - x0))
            metric = diff / max(signal, FLOOR[q])
            worst = max(worst, metric)
            print(f"p{k} {q or 'x'}: max |reference - YADE| {diff:.3e}, signal {signal:.3e}, metric {metric:.2e}")
    print(f"worst metric {worst:.2e}{' (variant ' + variant + ')' if variant else ''}; "
          f"rows with another contact count: {contacts_differ}")


main(sys.argv[1:])
