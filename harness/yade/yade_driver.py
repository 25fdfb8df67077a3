"""silodem's YADE driver: runs one translated case (JSON written by the YADE backend) and writes a
LAMMPS-style text dump (id mass radius x y z vx vy vz fx fy fz) that the harness reads like every
other code's. Run as a module under the system Python, never through the `yade` launcher, which
opens network ports on all interfaces:
    PYTHONPATH=/usr/lib/x86_64-linux-gnu/yade-double/py /usr/bin/python3.11 yade_driver.py case.json
Mapping (../shared/notes/reference-codes.md §2): ViscElMat(kn=k_i, cn=c_i, ks=cs=0, frictionAngle=0)
per particle type — YADE combines them in series like (11) — with Law2_ScGeom_ViscElPhys_Basic,
which clamps the normal force at zero (always); fixed wall spheres with a collision mask so they do
not interact with each other; NewtonIntegrator without numerical damping. YADE's leapfrog keeps
half-step velocities: the driver starts it from v0 - dt/2 g (assuming no contact force acts at t = 0)
and dumps the full-step velocity as the mean of the two half-step velocities around each step, so a
frame holds the same state LAMMPS dumps.
"""
import json
import sys

import yade  # noqa: F401  (initialises YADE)
import yade.config
from yade import *  # noqa: F401,F403
from yade import utils
from yade.minieigenHP import Vector3

case = json.load(open(sys.argv[1]))
materials = [O.materials.append(ViscElMat(kn=t["k"], cn=t["c"], ks=0.0, cs=0.0, frictionAngle=0.0,
                                          density=t["density"])) for t in case["types"]]
tags = []
for b in case["balls"]:
    body = utils.sphere(tuple(b["x"]), b["radius"], material=materials[b["type"] - 1], fixed=b["fixed"],
                        mask=(3 if b["fixed"] else 1))
    bid = O.bodies.append(body)
    if not b["fixed"]:
        O.bodies[bid].state.vel = Vector3(*b["v"])
        O.bodies[bid].state.blockedDOFs = "XYZ"  # translations only (no torque arises without friction)
    tags.append(b["tag"])

out = open("dump.txt", "w")
every = int(case["dump_interval"])
dt = case["dt"]
gravity = Vector3(*case["gravity"])

# YADE's leapfrog keeps v(t - dt/2). Starting it from v0 - dt/2 g makes its first half step land
# where velocity Verlet's does (no contact forces act at the start in these cases).
for bid, b in enumerate(case["balls"]):
    if not b["fixed"]:
        O.bodies[bid].state.vel = Vector3(*b["v"]) - 0.5 * dt * gravity


def snapshot():
    return [(Vector3(O.bodies[i].state.pos), Vector3(O.bodies[i].state.vel)) for i in range(len(tags))]


def write_frame(step, states_before, states_after):
    """Frame n: x_n, the full-step velocity v_n = (v_{n-1/2} + v_{n+1/2})/2 (exact for leapfrog), and the
    force the step used, f_n — the same state LAMMPS dumps at step n."""
    out.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS mm mm mm\n0 0\n0 0\n0 0\n"
              "ITEM: ATOMS id mass radius x y z vx vy vz fx fy fz\n" % (step, len(tags)))
    lines = []
    for bid, tag in enumerate(tags):
        b = O.bodies[bid]
        x = states_before[bid][0]
        v = 0.5 * (states_before[bid][1] + states_after[bid][1])
        f = O.forces.f(bid)
        lines.append("%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n" % (
            tag, b.state.mass, b.shape.radius, x[0], x[1], x[2], v[0], v[1], v[2], f[0], f[1], f[2]))
    out.writelines(lines)


before = None


def after_step():
    """Runs after NewtonIntegrator in every iteration: positions are x_{n+1}, velocities v_{n+1/2},
    forces f_n."""
    global before
    now = snapshot()
    step = O.iter  # the iteration that has just run, counted from 0
    if step % every == 0:
        write_frame(step, before, now)
    before = now


O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()], avoidSelfInteractionMask=2, verletDist=case["skin"]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_ViscElMat_ViscElMat_ViscElPhys()],
                    [Law2_ScGeom_ViscElPhys_Basic()]),
    NewtonIntegrator(gravity=gravity, damping=0.0),
    PyRunner(iterPeriod=1, initRun=True, command="after_step()"),
]
O.dt = dt
before = snapshot()
# One iteration more than the other codes, so frame `steps` (which needs that iteration's forces) exists.
O.run(int(case["steps"]) + 1, True)
out.close()
print("YADE", yade.config.version)
