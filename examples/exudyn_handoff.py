"""
Hand-off from Exudyn: any mechanism
===================================

Wear of a joint in a mechanism jointwear does not build in, built in Exudyn.

jointwear builds a few mechanisms itself (``mechanism.type``); for any other one,
build it in a multibody code, here Exudyn, with an ideal joint where the
clearance will be, and hand jointwear one period of that joint's motion:

1. integrate the mechanism over one period of its steady motion (start it from a
   consistent kinematic state, or integrate until the transient has died out);
2. sample, at the start of each step, the force of the pin on the bushing and
   the angles of the two bodies that carry pin and bushing;
3. take the force into the **bushing body's frame**: its azimuth is the global
   direction of the force minus the bushing body's angle;
4. the relative rotation of each step is the **pin body's angle increment minus
   the bushing body's angle increment** (``R_b |relative rotation|`` is the
   sliding distance of the step);
5. ``jointwear.mechanism.LoadCycle.from_arrays(load, azimuth, relative_rotation,
   period=..., time=...)`` -> ``jointwear.Simulation(config, load_cycle=cycle).run()``.

The same cycle written by :func:`jointwear.workflows.dynamics.write_csv` is a
load-history file (columns ``time [s], force_x [N], force_y [N], rotation [rad]``
in the bushing frame, then diagnostics), which a configuration reads back with::

    [mechanism]
    type = "load-history"
    file = "five_bar_joint.csv"

so the wear runs from the command line (``jointwear run``) without Exudyn.

The mechanism here is a five-bar linkage driven by two cranks at a 1:2 speed
ratio (crank 1 at 120 rpm counter-clockwise, crank 2 at 240 rpm clockwise), a
1 kg tool pressed down with 60 N at the joint P between the two couplers; that
joint has the clearance, the pin on coupler 1 and the bushing in coupler 2. The motion repeats
after one turn of crank 1. A contact law of one's own works the same way as a
mechanism of one's own: any function ``pressure(penetration)``.

Run: ``python examples/exudyn_handoff.py [--figure five_bar.png] [--csv five_bar.csv]``
(needs ``exudyn``; the figure needs ``matplotlib``).
"""

from __future__ import annotations

import argparse
import math
import tempfile
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

import jointwear as jw
from jointwear.mechanism import LoadCycle
from jointwear.mechanism.stage import load_cycle
from jointwear.workflows.dynamics import write_csv

FloatArray = NDArray[np.float64]

# five-bar geometry [m]: ground pivots A0 = (0, 0) and E0 = (D, 0), cranks A0-A
# and E0-E, couplers A-P and E-P
D, CRANK_1, CRANK_2, COUPLER_1, COUPLER_2 = 0.15, 0.04, 0.03, 0.13, 0.13
CRANK_MASS, COUPLER_MASS, TOOL_MASS = 0.2, 0.4, 1.0  # [kg], links uniform
OMEGA = 120 * 2 * math.pi / 60  # crank 1 [rad/s]; crank 2 turns at -2 OMEGA
CRANK_2_START = math.pi  # crank 2 angle at t = 0 [rad]
GRAVITY = 9.81  # along -y [m/s^2]
TOOL_FORCE = 60.0  # process force on the tool, along -y [N]
STEPS = 180  # jointwear steps per period
SUBSTEPS = 4  # Exudyn time steps per jointwear step


def perpendicular(v: FloatArray) -> FloatArray:
    """``v`` turned by +90 deg; ``omega x r`` in the plane is ``omega * perpendicular(r)``."""
    return np.array([-v[1], v[0]])


def initial_state() -> dict[str, tuple[FloatArray, FloatArray, float, float]]:
    """Exact positions and velocities of the driven five-bar at t = 0.

    Returns
    -------
    dict
        Per body: (point the body starts from [m], its velocity [m/s], body angle
        [rad], angular velocity [rad/s]); the points are A0, E0, A and E.
    """
    e0 = np.array([D, 0.0])
    a = CRANK_1 * np.array([1.0, 0.0])
    e = e0 + CRANK_2 * np.array([math.cos(CRANK_2_START), math.sin(CRANK_2_START)])
    va, ve = OMEGA * perpendicular(a), -2 * OMEGA * perpendicular(e - e0)
    # P: the upper intersection of the circles about A (radius l_AP) and E (l_EP)
    u = e - a
    span = float(np.hypot(*u))
    along = (COUPLER_1**2 - COUPLER_2**2 + span**2) / (2 * span)
    p = a + along * u / span + math.sqrt(COUPLER_1**2 - along**2) * perpendicular(u) / span
    # rigid couplers: (P - A) . (vP - vA) = 0 and (P - E) . (vP - vE) = 0
    vp = np.linalg.solve(np.array([p - a, p - e]), np.array([(p - a) @ va, (p - e) @ ve]))

    def rate(r: FloatArray, v: FloatArray) -> float:
        return float(r[0] * v[1] - r[1] * v[0]) / float(r @ r)

    return {
        "crank 1": (np.zeros(2), np.zeros(2), 0.0, OMEGA),
        "crank 2": (e0, np.zeros(2), CRANK_2_START, -2 * OMEGA),
        "coupler 1": (a, va, math.atan2(*(p - a)[::-1]), rate(p - a, vp - va)),
        "coupler 2": (e, ve, math.atan2(*(p - e)[::-1]), rate(p - e, vp - ve)),
    }


def five_bar_in_exudyn() -> dict[str, FloatArray]:
    """Integrate the five-bar over one period in Exudyn.

    Returns
    -------
    dict of str to ndarray, shape (STEPS + 1,)
        ``time`` [s]; ``force_x``, ``force_y``: force of the pin (coupler 1) on the
        bushing (coupler 2) at P, global frame [N]; ``pin_angle``,
        ``bushing_angle``: angles of couplers 1 and 2 [rad].
    """
    import exudyn as exu
    from exudyn import itemInterface as ii

    period = 2 * math.pi / OMEGA
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground_coordinate = mbs.AddMarker(
        ii.MarkerNodeCoordinate(nodeNumber=mbs.AddNode(ii.NodePointGround()), coordinate=0)
    )
    ground = mbs.AddObject(ii.ObjectGround())
    state = initial_state()

    def add_link(name: str, length: float, mass: float, tool: float = 0.0):
        """A straight link from its start point along its angle, tool mass at its end."""
        start, velocity, angle, rate = state[name]
        # centre of mass of link + tool, its inertia about that centre (Steiner)
        centre = (mass * length / 2 + tool * length) / (mass + tool)
        inertia = mass * length**2 / 12 + mass * (length / 2 - centre) ** 2
        inertia += tool * (length - centre) ** 2
        axis = np.array([math.cos(angle), math.sin(angle)])
        position = start + centre * axis
        node = mbs.AddNode(
            ii.NodeRigidBody2D(
                referenceCoordinates=[*position, angle],
                initialVelocities=[*(velocity + rate * centre * perpendicular(axis)), rate],
            )
        )
        body = mbs.AddObject(
            ii.ObjectRigidBody2D(mass=mass + tool, inertia=inertia, nodeNumber=node)
        )
        mbs.AddLoad(
            ii.LoadMassProportional(
                markerNumber=mbs.AddMarker(ii.MarkerBodyMass(bodyNumber=body)),
                loadVector=[0.0, -GRAVITY, 0.0],
            )
        )
        ends = [
            mbs.AddMarker(ii.MarkerBodyPosition(bodyNumber=body, localPosition=[x, 0.0, 0.0]))
            for x in (-centre, length - centre)
        ]
        return node, ends

    crank_1, (a0, a) = add_link("crank 1", CRANK_1, CRANK_MASS)
    crank_2, (e0, e) = add_link("crank 2", CRANK_2, CRANK_MASS)
    coupler_1, (a_1, p_pin) = add_link("coupler 1", COUPLER_1, COUPLER_MASS)
    coupler_2, (e_2, p_bushing) = add_link("coupler 2", COUPLER_2, COUPLER_MASS, TOOL_MASS)

    def pivot(x: float) -> int:
        return mbs.AddMarker(ii.MarkerBodyPosition(bodyNumber=ground, localPosition=[x, 0, 0]))

    for pair in ([pivot(0.0), a0], [pivot(D), e0], [a, a_1], [e, e_2]):
        mbs.AddObject(ii.ObjectJointRevolute2D(markerNumbers=pair))
    # the clearance joint, ideal here: the Lagrange multiplier lambda of Exudyn's
    # revolute joint is the force on the body of its first marker, so with the pin
    # first, the force of the pin on the bushing is -lambda
    joint = mbs.AddObject(ii.ObjectJointRevolute2D(markerNumbers=[p_pin, p_bushing]))
    mbs.AddLoad(ii.LoadForceVector(markerNumber=p_bushing, loadVector=[0.0, -TOOL_FORCE, 0.0]))
    # drives: node angle coordinates are increments from the start angle
    for node, speed in ((crank_1, OMEGA), (crank_2, -2 * OMEGA)):
        angle = mbs.AddMarker(ii.MarkerNodeCoordinate(nodeNumber=node, coordinate=2))
        mbs.AddObject(
            ii.ObjectConnectorCoordinate(
                markerNumbers=[ground_coordinate, angle],
                offsetUserFunction=lambda mbs, t, item, offset, speed=speed: speed * t,
            )
        )

    def multipliers(mbs, t, sensor_numbers, factors, configuration):
        lagrange = mbs.systemData.GetAECoordinates(configuration)
        return [lagrange[i] for i in mbs.systemData.GetObjectLTGAE(joint)]

    sensors = [
        mbs.AddSensor(
            ii.SensorUserFunction(
                sensorNumbers=[], sensorUserFunction=multipliers, storeInternal=True
            )
        ),
        *(
            mbs.AddSensor(
                ii.SensorNode(
                    nodeNumber=node,
                    outputVariableType=exu.OutputVariableType.Rotation,
                    storeInternal=True,
                )
            )
            for node in (coupler_1, coupler_2)
        ),
    ]
    mbs.Assemble()
    settings = exu.SimulationSettings()
    settings.timeIntegration.endTime = period
    settings.timeIntegration.numberOfSteps = STEPS * SUBSTEPS
    settings.timeIntegration.verboseMode = 0
    # below 1: numerical damping keeps the index-3 multipliers from drifting
    settings.timeIntegration.generalizedAlpha.spectralRadius = 0.6
    settings.solution.file.write = False
    settings.solution.sensors.writePeriod = period / STEPS
    mbs.SolveDynamic(settings)

    force, pin, bushing = (mbs.GetSensorStoredData(s) for s in sensors)
    return {
        "time": force[:, 0],
        "force_x": -force[:, 1],
        "force_y": -force[:, 2],
        "pin_angle": pin[:, 3],
        "bushing_angle": bushing[:, 3],
    }


def load_cycle_of(run: dict[str, FloatArray]) -> LoadCycle:
    """The joint's load cycle: force in the bushing frame, relative rotation per step."""
    period = 2 * math.pi / OMEGA
    # samples k = 0 .. N: step k starts at sample k and ends at sample k + 1
    fx, fy = run["force_x"][:-1], run["force_y"][:-1]
    azimuth = np.arctan2(fy, fx) - run["bushing_angle"][:-1]
    relative_rotation = np.diff(run["pin_angle"]) - np.diff(run["bushing_angle"])
    return LoadCycle.from_arrays(
        np.hypot(fx, fy),
        azimuth,
        relative_rotation,
        period=period,
        time=run["time"][:-1],
        mechanism="exudyn",
        joint="coupler-coupler",
    )


def read_back(path: Path, cycle: LoadCycle) -> None:
    """Read the CSV as ``[mechanism] type = "load-history"`` does and compare."""
    config = jw.load_config(
        overrides={"mechanism.type": "load-history", "mechanism.file": str(path)}
    )
    try:
        back = load_cycle(config)
    except ModuleNotFoundError as missing:
        # a jointwear without the load-history reader still writes the file
        print(f"not read back: {missing}")
        return
    load = float(np.max(np.abs(back.load - cycle.load)))
    rotation = float(np.max(np.abs(back.relative_rotation - cycle.relative_rotation)))
    print(
        f"read back as load-history: load within {load:.1e} N, rotation within {rotation:.1e} rad"
    )


def stiffening_foundation(penetration: FloatArray) -> FloatArray:
    """A foundation that stiffens with compression, p = k d (1 + d / d0) [Pa]."""
    return 1.5e11 * penetration * (1 + penetration / 5e-6)


def main(figure: str | None = None, csv_path: str | None = None) -> tuple[LoadCycle, dict]:
    """Build, hand off, wear; print a summary, optionally write the CSV.

    Returns the load cycle and the wear results by contact model.
    """
    run = five_bar_in_exudyn()
    cycle = load_cycle_of(run)
    # started from the exact kinematic state, the force after one period is the
    # force at t = 0 again: no transient has to be integrated away
    force = np.hypot(run["force_x"], run["force_y"])
    closure = np.hypot(
        run["force_x"][-1] - run["force_x"][0], run["force_y"][-1] - run["force_y"][0]
    )
    print(f"Exudyn: force after one period repeats to {closure / force.max():.1e} of its peak")
    summary = cycle.summary()
    print(
        f"five-bar joint P over {cycle.period:.3g} s, {cycle.steps} steps: load "
        f"{summary['load_min_n']:.1f}..{summary['load_max_n']:.1f} N, azimuth on the bushing "
        f"{summary['azimuth_min_deg']:.0f}..{summary['azimuth_max_deg']:.0f} deg, "
        f"relative rotation {cycle.total_relative_rotation:.3f} rad per period"
    )

    with tempfile.TemporaryDirectory() as scratch:
        path = Path(csv_path) if csv_path else Path(scratch) / "five_bar_joint.csv"
        write_csv(path, cycle)
        print(f"load history written: {path.name}, {len(path.read_text().splitlines())} lines")
        read_back(path, cycle)

    config = jw.load_config(
        overrides={
            "contact.nodes": 360,
            "simulation.steps_per_revolution": cycle.steps,
            "simulation.revolutions": 20000,
            "simulation.update_contour": True,
            "simulation.update_every": 2000,
        }
    )
    results = {}
    for name, model in (("winkler", "asymmetric-winkler"), ("custom", stiffening_foundation)):
        results[name] = jw.Simulation(config, contact_model=model, load_cycle=cycle).run()
        wear = results[name].summary()
        print(
            f"{name:8s}: peak {wear['peak_wear_depth_m'] * 1e6:6.2f} um, width "
            f"{wear['wear_width_deg']:5.1f} deg, mass {wear['wear_mass_kg'] * 1e6:.3f} mg "
            f"after {wear['revolutions']} periods"
        )
    return cycle, results


def plot(cycle: LoadCycle, wear_depth: FloatArray):
    """Load on the bushing (its own frame) over the period, and the wear it causes."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(9, 4), layout="constrained")
    left = fig.add_subplot(1, 2, 1, projection="polar")
    closed = np.append(np.arange(cycle.steps), 0)
    left.plot(cycle.azimuth[closed], cycle.load[closed])
    left.set_title("force of the pin on the bushing [N]\n(bushing frame, coupler 2)")
    right = fig.add_subplot(1, 2, 2)
    nodes = np.degrees(2 * np.pi * np.arange(wear_depth.size) / wear_depth.size)
    right.plot(nodes, wear_depth * 1e6)
    right.set_xlabel("angle on the bushing [deg]")
    right.set_ylabel("wear depth [um]")
    right.set_title("wear after 20000 periods (Winkler)")
    return fig


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description="Hand-off from Exudyn")
    parser.add_argument("--figure", help="write the figure to this file")
    parser.add_argument("--csv", help="write the load history to this file")
    # parse_known_args: the test suite runs this module with pytest's own arguments
    arguments, _ = parser.parse_known_args()
    cycle, results = main(arguments.figure, arguments.csv)
    figure = plot(cycle, results["winkler"].wear_depth)
    if arguments.figure:
        figure.savefig(arguments.figure, dpi=120)
        print(f"figure written: {arguments.figure}")
