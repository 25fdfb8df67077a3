"""silodem's YADE driver: runs one translated case (JSON written by the YADE backend) and writes a
LAMMPS-style text dump (id mass radius x y z vx vy vz fx fy fz fixed [omegax omegay omegaz]) that the
harness reads like every other code's. Run as a module under the system Python, never through the
`yade` launcher, which opens network ports on all interfaces:
    PYTHONPATH=/usr/lib/x86_64-linux-gnu/yade-double/py /usr/bin/python3.11 yade_driver.py case.json
Mapping (docs/reference-codes.md, Measured facts: YADE, and the sub-models by code):
- law "viscoelastic": ViscElMat(kn=k_i, cn=c_i, ks, cs) per particle type, which YADE combines in
  series like (11), with Law2_ScGeom_ViscElPhys_Basic (normal force clamped at zero; the Coulomb
  cap acts on the tangential spring alone and the tangential dashpot drops out while sliding).
- law "hertz_mindlin": FrictMat(young, poisson) per type, Ip2_FrictMat_FrictMat_MindlinPhys with
  betan, betas per type pair, Law2_ScGeom_MindlinPhys_Mindlin; slip velocity at the contact point
  (Ig2 avoidGranularRatcheting=False) or, for radius lever arms, YADE's default (radii, and the
  translational part scaled by (R1+R2)/(R1+R2-delta)).
- law "moment" (silodem's EPSD rolling spring, undamped cases only): CohFrictMat(young, poisson, alphaKr,
  etaRoll, momentRotationLaw) per type, Ig2_Sphere_Sphere_ScGeom6D (slip velocity at the contact point),
  Ip2_CohFrictMat_CohFrictMat_CohFrictPhys without cohesion, Law2_ScGeom6D_CohFrictPhys_CohesionMoment in its
  incremental form with the moment law on uncohesive contacts: normal k_n delta, incremental shear force
  capped at F_n tan(phi), incremental bending moment capped at min(etaRoll_i R_i) |F_n|, no twist.
- friction per type pair through a MatchMaker listing every pair.
Fixed wall spheres carry a collision mask so they do not interact with each other; NewtonIntegrator
without numerical damping (its default is 0.2). YADE's leapfrog keeps half-step velocities and spins:
the driver starts it from v0 - dt/2 (g + f0/m) and w0 - dt/2 t0/I, and dumps full-step values as
the mean of the two half-step values around each step, so a frame holds the same state LAMMPS dumps.
Stages (translation.hpp): gate balls erased, leavers erased every OUTFLOW_EVERY steps, closure by
blocking the slab's mobile balls, released drops appended at their steps, moving walls given their
velocity (a fixed body keeps it and is moved by it), walls oscillating by a law placed at each step. An event on a frame's
step shows in that frame's forces (LAMMPS's frame holds the forces from before it).
"""
import array
import json
import math
import sys

import yade  # noqa: F401  (initialises YADE)
import yade.config
from yade import *  # noqa: F401,F403
from yade import utils
from yade.minieigenHP import Vector3

case = json.load(open(sys.argv[1]))


def read_balls(case):
    """The balls from balls.bin, columns of raw little-endian numbers written by the backend
    (yade_backend.cpp): tag int64, type int32, fixed uint8, radius, then x, v, w as 3 float64 each."""
    n = case["ball_count"]
    raw = open(case["balls_file"], "rb").read()
    if len(raw) != n * (8 + 4 + 1 + 8 + 72):
        raise SystemExit("yade_driver: %s has %d bytes, not the %d of %d balls" % (case["balls_file"], len(raw),
                                                                                n * 93, n))
    at = 0

    def column(code, size, count):
        nonlocal at
        values = array.array(code)
        values.frombytes(raw[at:at + size * count])
        at += size * count
        return values
    tag, typ, fixed, radius = column("q", 8, n), column("i", 4, n), column("B", 1, n), column("d", 8, n)
    x, v, w = column("d", 8, 3 * n), column("d", 8, 3 * n), column("d", 8, 3 * n)
    return [{"tag": tag[i], "type": typ[i], "fixed": bool(fixed[i]), "radius": radius[i],
             "x": list(x[3 * i:3 * i + 3]), "v": list(v[3 * i:3 * i + 3]), "w": list(w[3 * i:3 * i + 3])}
            for i in range(n)]


case["balls"] = read_balls(case)
rotation = bool(case.get("rotation", False))
planar = bool(case.get("planar", False))


def pair_matcher(key):
    """A MatchMaker over material ids (type - 1) holding every type pair's value of `key`."""
    return MatchMaker(matches=[(p["a"] - 1, p["b"] - 1, p[key]) for p in case["pairs"]])


if case.get("law", "viscoelastic") == "hertz_mindlin":
    materials = [O.materials.append(FrictMat(young=t["young"], poisson=t["poisson"], frictionAngle=0.0,
                                             density=t["density"])) for t in case["types"]]
    geometry = Ig2_Sphere_Sphere_ScGeom(avoidGranularRatcheting=bool(case.get("radius_lever_arms", False)))
    physics = Ip2_FrictMat_FrictMat_MindlinPhys(betan=pair_matcher("betan"), betas=pair_matcher("betas"),
                                                frictAngle=pair_matcher("friction_angle"))
    law = Law2_ScGeom_MindlinPhys_Mindlin()
elif case.get("law") == "moment":
    materials = [O.materials.append(CohFrictMat(young=t["young"], poisson=t["poisson"], frictionAngle=0.0,
                                                density=t["density"], isCohesive=False, normalCohesion=0.0,
                                                shearCohesion=0.0, momentRotationLaw=True, alphaKr=t["alpha_kr"],
                                                alphaKtw=0.0, etaRoll=t["eta_roll"])) for t in case["types"]]
    geometry = Ig2_Sphere_Sphere_ScGeom6D(avoidGranularRatcheting=False)
    physics = Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(frictAngle=pair_matcher("friction_angle"))
    law = Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=True, always_use_moment_law=True)
else:
    materials = [O.materials.append(ViscElMat(kn=t["k"], cn=t["c"], ks=t.get("ks", 0.0), cs=t.get("cs", 0.0),
                                              frictionAngle=0.0, density=t["density"])) for t in case["types"]]
    geometry = Ig2_Sphere_Sphere_ScGeom()
    physics = Ip2_ViscElMat_ViscElMat_ViscElPhys(frictAngle=pair_matcher("friction_angle"))
    law = Law2_ScGeom_ViscElPhys_Basic()
tag_of, body_of, alive, fixed = {}, {}, set(), set()


def add_ball(b):
    body = utils.sphere(tuple(b["x"]), b["radius"], material=materials[b["type"] - 1], fixed=b["fixed"],
                        mask=(3 if b["fixed"] else 1))
    bid = O.bodies.append(body)
    if not b["fixed"]:
        state = O.bodies[bid].state
        state.vel = Vector3(*b["v"])
        if not rotation:
            state.blockedDOFs = "XYZ"  # translations only (no torque arises without friction)
        if planar:
            # silodem's planar mode: no motion along y, spin about y alone (Particles::keep_in_plane).
            state.blockedDOFs = "yXYZ" if not rotation else "yXZ"
            k = case["inertia_factor"] * state.mass * b["radius"] ** 2
            state.inertia = Vector3(k, k, k)
    else:
        fixed.add(bid)
    tag_of[bid] = b["tag"]
    body_of[b["tag"]] = bid
    alive.add(bid)
    return bid


initial_bodies = [add_ball(b) for b in case["balls"]]

out = open("dump.txt", "w")
every = int(case["dump_interval"])
dt = case["dt"]
gravity = Vector3(*case["gravity"])


def snapshot():
    return {i: (Vector3(O.bodies[i].state.pos), Vector3(O.bodies[i].state.vel), Vector3(O.bodies[i].state.angVel))
            for i in alive}


def write_frame(step, states_before):
    """Frame n: x_n, the full-step velocity v_n = (v_{n-1/2} + v_{n+1/2})/2 (exact for leapfrog), likewise
    the spin, and the force the step used, f_n — the same state LAMMPS dumps at step n. Called after iteration n."""
    out.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS mm mm mm\n0 0\n0 0\n0 0\n"
              "ITEM: ATOMS id mass radius x y z vx vy vz fx fy fz fixed%s\n"
              % (step, len(states_before), " omegax omegay omegaz" if rotation else ""))
    lines = []
    for bid in sorted(states_before):
        b = O.bodies[bid]
        x, v_before, w_before = states_before[bid]
        # Frame 0 holds v_0 as given (iteration 0 started from it), and f_0 without the half-kick force.
        v = 0.5 * (v_before + b.state.vel) if bid in alive and bid not in half_kick else v_before
        f = O.forces.f(bid) - half_kick[bid][0] if bid in half_kick else O.forces.f(bid)
        line = "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d" % (
            tag_of[bid], b.state.mass, b.shape.radius, x[0], x[1], x[2], v[0], v[1], v[2], f[0], f[1], f[2],
            1 if bid in fixed else 0)
        if rotation:
            w = 0.5 * (w_before + b.state.angVel) if bid in alive and bid not in half_kick else w_before
            line += " %.17g %.17g %.17g" % (w[0], w[1], w[2])
        lines.append(line + "\n")
    out.writelines(lines)


def apply_event(ev):
    """A stage event at the top of its step (run/stages.cpp): gate balls erased, or the mobile balls in
    the outlet slab stopped and blocked (wall balls from then on), or a released drop created at its release point."""
    if ev["type"] == "insert":
        bid = add_ball(ev["ball"])
        # The leapfrog keeps v(t - dt/2): released free of contacts, it starts at v0 - dt/2 g.
        O.bodies[bid].state.vel = Vector3(*ev["ball"]["v"]) - 0.5 * dt * gravity
        return
    if ev["type"] == "move_wall":
        # A fixed body keeps the velocity it is given, and NewtonIntegrator moves it by v dt each
        # iteration after the forces: where silodem places a moving wall before the next step's forces.
        for tag in ev["tags"]:
            O.bodies[body_of[tag]].state.vel = Vector3(*ev["velocity"])
        return
    if ev["type"] == "open_outlet":
        for tag in ev["tags"]:
            bid = body_of[tag]
            O.bodies.erase(bid)
            alive.discard(bid)
            fixed.discard(bid)
        return
    c, h, r = Vector3(*ev["centre"]), 0.5 * ev["thickness"], 0.5 * ev["diameter"]
    for bid in list(alive - fixed):
        d = O.bodies[bid].state.pos - c
        if abs(d[2]) <= h and (d[0] ** 2 + d[1] ** 2) ** 0.5 <= r:
            O.bodies[bid].state.vel = Vector3(0, 0, 0)
            O.bodies[bid].state.angVel = Vector3(0, 0, 0)
            O.bodies[bid].state.blockedDOFs = "xyzXYZ"
            fixed.add(bid)


def remove_leavers():
    """Outflow by removal: mobile balls whose centre is below the outflow height are erased."""
    for bid in list(alive - fixed):
        if O.bodies[bid].state.pos[2] < outflow_z:
            O.bodies.erase(bid)
            alive.discard(bid)


contact_engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()], avoidSelfInteractionMask=2, verletDist=case["skin"]),
    InteractionLoop([geometry], [physics], [law]),
]
# silodem's step 0 (velocity Verlet): f_0 from x_0 with the springs of the contacts present grown by one
# step at v_0, w_0 for that evaluation only (it is not committed: the springs hold sum v_(k-1/2) dt from step
# 1 on), then v_1/2 = v_0 + dt/2 (g + f_0/m). YADE's iteration 0 grows the springs at its stored velocity,
# keeps them, and kicks by a whole dt (g + F/m). So the stored velocity is v_0 itself, and an engine
# between the contact loop and the integrator, in iteration 0 alone, reads f_0, adds -(f_0 + m g)/2
# (torque -t_0/2) to halve the kick, and empties the springs again (a translated start has no history).
INCREMENTAL_STATE = ("shearForce", "shearElastic", "moment_bending", "moment_twist")


def add_half_kick():
    for bid in half_kick:
        state = O.bodies[bid].state
        half_kick[bid] = (-0.5 * (O.forces.f(bid) + state.mass * gravity), -0.5 * O.forces.t(bid))
        O.forces.addF(bid, half_kick[bid][0])
        if rotation:
            O.forces.addT(bid, half_kick[bid][1])
    for i in O.interactions:
        for name in INCREMENTAL_STATE:
            if hasattr(i.phys, name):
                setattr(i.phys, name, Vector3(0, 0, 0))
    kick_engine.dead = True


for bid, b in zip(initial_bodies, case["balls"]):
    if rotation and not b["fixed"]:
        O.bodies[bid].state.angVel = Vector3(*b.get("w", [0.0, 0.0, 0.0]))
half_kick = {bid: None for bid, b in zip(initial_bodies, case["balls"]) if not b["fixed"]}  # id: (force, torque) added
kick_engine = PyRunner(iterPeriod=1, initRun=True, command="add_half_kick()")
O.engines = contact_engines + [kick_engine, NewtonIntegrator(gravity=gravity, damping=0.0)]
O.dt = dt


def end_half_kick():
    """After iteration 0 (and its frame): the added force no longer enters the frames."""
    half_kick.clear()


# A PyRunner after NewtonIntegrator acts between iterations: after iteration s the state is x_{s+1},
# v_{s+1/2} with forces f_s, which is where frame s is written and where step s+1 begins (stage events,
# outflow checks every OUTFLOW_EVERY steps, the snapshot frame s+1 will need). Step s (absolute, as the
# dumps count) is the (s - start)-th iteration of this run.
OUTFLOW_EVERY = int(case.get("outflow_every_steps", 1))
start, end = int(case["start_step"]), int(case["steps"])
events = sorted(case["events"], key=lambda e: e["step"])
outflow_z = case.get("outflow_below_z")
before = None
step = start


# Walls moving by a law (motion/motion_law.hpp): from t0 on, a turn by W (t - t0) about the axis n
# through c plus a shift A (sin(w (t - t0) + phi) - sin phi) e; the velocity is the rigid body's,
# W n x (x - c - shift) + shift rate, and every ball spins at W n. silodem places such a wall at its
# step-end pose before the step's forces; here each ball is put at the pose of time n dt with that
# pose's velocity and spin before iteration n's forces (NewtonIntegrator's move of a fixed body by
# v dt is overwritten), as LAMMPS's fix move does.
motions = [dict(m, origin={tag: None for tag in m["tags"]}) for m in case.get("motions", [])]


def turned(x, axis, angle):
    """x turned by angle about the unit axis (Rodrigues)."""
    c, s = math.cos(angle), math.sin(angle)
    return x * c + axis.cross(x) * s + axis * (axis.dot(x) * (1.0 - c))


def place_moving_walls(n):
    t = n * dt
    for m in motions:
        s = t - m["start_time"]
        a = v = angle = spin = 0.0
        if s >= 0.0:
            w = 2.0 * math.pi * m["frequency"]
            a = m["amplitude"] * (math.sin(w * s + m["phase"]) - math.sin(m["phase"]))
            v = m["amplitude"] * w * math.cos(w * s + m["phase"])
            spin = m["angular_speed"]
            angle = spin * s
        e, c, axis = Vector3(*m["direction"]), Vector3(*m["centre"]), Vector3(*m["axis"])
        for tag, origin in m["origin"].items():
            state = O.bodies[body_of[tag]].state
            if origin is None:
                origin = m["origin"][tag] = Vector3(state.pos)
            arm = turned(origin - c, axis, angle)  # exactly origin - c at angle 0
            state.pos = c + arm + a * e
            state.vel = (spin * axis).cross(arm) + v * e
            state.angVel = spin * axis


def begin_step(n):
    global before
    while events and events[0]["step"] == n:
        apply_event(events.pop(0))
    place_moving_walls(n)
    if outflow_z is not None and n % OUTFLOW_EVERY == 0:
        remove_leavers()
    if n % every == 0:
        before = snapshot()


def after_iteration():
    global step
    if step % every == 0:
        write_frame(step, before)
    end_half_kick()
    step += 1
    begin_step(step)


O.engines = O.engines + [PyRunner(iterPeriod=1, initRun=True, command="after_iteration()")]
begin_step(start)
# Frame `end` needs iteration `end` (its forces and v_{end+1/2}): one iteration past the end then.
O.run(end - start + (1 if end % every == 0 else 0), True)
out.close()
print("YADE", yade.config.version)
