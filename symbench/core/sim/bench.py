"""`symbench bench sim`: controlled control steps per second against raw `mj_step`.

Both are measured in one run on the same model: first the controlled loop (gait planner,
whole-body QP, dm-control environment step, recording), then, from the state the controlled
run ended in (same contacts, magnets on, the last servo command held), `mj_step` alone.
"""

from __future__ import annotations

import json
import platform
import time

import click

RAW_STEPS = 5000


def measure(robot: str, inclination: float = 90.0, seconds: float = 2.0) -> dict:
    import mujoco

    from symbench.core.scenario import Scenario
    from symbench.core.sim.rollout import run_climb
    from symbench.core.sim.setup import Climb

    climb = Climb.from_scenario(Scenario(robot, inclination_deg=inclination, seconds=seconds))
    last = {}

    def keep(out, physics) -> None:
        last["physics"] = physics

    rollout = run_climb(climb, seconds, on_step=keep)
    physics = last["physics"]
    dt = physics.model.ptr.opt.timestep
    steps = round(rollout.metrics["sim_seconds"] / dt)
    controlled = steps / rollout.metrics["wall_seconds"]
    model = physics.model.ptr
    data = mujoco.MjData(model)
    source = physics.data.ptr
    data.qpos[:], data.qvel[:], data.ctrl[:] = source.qpos, source.qvel, source.ctrl
    data.time = source.time
    mujoco.mj_forward(model, data)
    contacts_before = data.ncon
    start = time.perf_counter()
    mujoco.mj_step(model, data, RAW_STEPS)
    raw = RAW_STEPS / (time.perf_counter() - start)
    return {
        "robot": robot,
        "inclination_deg": inclination,
        "timestep_s": dt,
        "control_period_s": dt,
        "controlled_steps_per_s": controlled,
        "raw_mj_step_per_s": raw,
        "ratio": controlled / raw,
        "controlled_real_time_factor": controlled * dt,
        "raw_real_time_factor": raw * dt,
        "contacts": {"controlled_end": contacts_before, "raw_end": int(data.ncon)},
        "attached": rollout.attached,
        "nv": int(model.nv),
        "machine": platform.processor() or platform.machine(),
        "threads": 1,
    }


@click.command("sim")
@click.option("--robot", required=True, help="Registered robot, e.g. hexa.")
@click.option("--inclination", type=float, default=90.0, show_default=True)
@click.option("--seconds", type=float, default=2.0, show_default=True,
              help="Simulated seconds of the controlled run.")
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def bench_sim(robot: str, inclination: float, seconds: float, as_json: bool) -> None:
    """Controlled control-steps/s vs raw mj_step steps/s, and their ratio."""
    result = measure(robot, inclination, seconds)
    if as_json:
        click.echo(json.dumps(result, indent=2))
        return
    click.echo(f"{robot} on {inclination:g} deg, control at {1 / result['timestep_s']:.0f} Hz")
    click.echo(f"  controlled: {result['controlled_steps_per_s']:9.0f} steps/s "
               f"({result['controlled_real_time_factor']:.1f}x real time)")
    click.echo(f"  raw mj_step: {result['raw_mj_step_per_s']:8.0f} steps/s "
               f"({result['raw_real_time_factor']:.1f}x real time)")
    click.echo(f"  ratio: {result['ratio']:.3f}")
