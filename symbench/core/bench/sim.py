"""`symbench bench sim`: the controlled simulation against raw `mj_step`, in one run.

First the controlled loop (gait planner, whole-body QP, servo commands, recording, the
dm-control task's step), then, from the state the controlled run ended in (same contacts,
magnets on, the last servo command held), `mj_step` alone on the same model. The ratio
compares simulated time per wall second; with the controller at every physics step (the
default) that is the ratio of controlled control steps to raw steps per second. The same
ratio from process CPU time is reported beside it (`cpu_ratio`).
"""

from __future__ import annotations

import json
import platform
import time

import click

from symbench.core.common.cli_types import INCLINATION, POSITIVE

RAW_STEPS = 5000


def measure(
    robot: str, inclination: float = 90.0, seconds: float = 2.0, control_period: float | None = None
) -> dict:
    import mujoco

    from symbench.core.sim.climb.rollout import run_climb
    from symbench.core.sim.scene.scenario import Scenario
    from symbench.core.sim.scene.setup import Climb

    climb = Climb.from_scenario(Scenario(robot, inclination_deg=inclination, seconds=seconds))
    last = {}

    def keep(physics) -> None:
        last["physics"] = physics

    rollout = run_climb(climb, seconds, on_finish=keep, control_period=control_period)
    physics = last["physics"]
    model, source = physics.model.ptr, physics.data.ptr
    dt = model.opt.timestep
    steps = round(rollout.metrics["sim_seconds"] / dt)
    period = rollout.metrics["control_period"]
    wall = rollout.metrics["wall_seconds"]
    cpu = rollout.metrics["cpu_seconds"]
    data = mujoco.MjData(model)
    data.qpos[:], data.qvel[:], data.ctrl[:] = source.qpos, source.qvel, source.ctrl
    data.time = source.time
    mujoco.mj_forward(model, data)
    contacts = data.ncon
    start, start_cpu = time.perf_counter(), time.process_time()
    mujoco.mj_step(model, data, RAW_STEPS)
    raw = RAW_STEPS / (time.perf_counter() - start)
    raw_cpu = RAW_STEPS / (time.process_time() - start_cpu)
    return {
        "robot": robot,
        "inclination_deg": inclination,
        "timestep_s": dt,
        "control_period_s": period,
        "control_steps_per_s": steps * dt / period / wall,
        "controlled_physics_steps_per_s": steps / wall,
        "raw_mj_step_per_s": raw,
        "ratio": steps / wall / raw,
        "controlled_real_time_factor": steps * dt / wall,
        "raw_real_time_factor": raw * dt,
        # the same from this process's CPU time: on a machine shared with other work, wall
        # time charges the controlled loop for more of the others' time than raw mj_step
        "controlled_cpu_physics_steps_per_s": steps / cpu,
        "raw_cpu_mj_step_per_s": raw_cpu,
        "cpu_ratio": steps / cpu / raw_cpu,
        "contacts": {"controlled_end": int(contacts), "raw_end": int(data.ncon)},
        "attached": rollout.attached,
        "nv": int(model.nv),
        "machine": platform.processor() or platform.machine(),
        "threads": 1,
    }


@click.command("sim")
@click.option("--robot", required=True, help="Registered robot, e.g. hexa.")
@click.option("--inclination", type=INCLINATION, default=90.0, show_default=True)
@click.option(
    "--seconds",
    type=POSITIVE,
    default=2.0,
    show_default=True,
    help="Simulated seconds of the controlled run.",
)
@click.option(
    "--control-period",
    type=POSITIVE,
    default=None,
    help="Seconds between whole-body QP solves [default: every physics step, 1 ms].",
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def bench_sim(
    robot: str, inclination: float, seconds: float, control_period: float | None, as_json: bool
) -> None:
    """Controlled vs raw mj_step steps per second on one core, and their ratio."""
    r = measure(robot, inclination, seconds, control_period)
    if as_json:
        click.echo(json.dumps(r, indent=2))
        return
    click.echo(
        f"{robot} on {inclination:g} deg, physics {1 / r['timestep_s']:.0f} Hz, "
        f"whole-body controller every {r['control_period_s'] * 1000:g} ms"
    )
    click.echo(
        f"  controlled:  {r['control_steps_per_s']:8.0f} control steps/s, "
        f"{r['controlled_physics_steps_per_s']:8.0f} physics steps/s "
        f"({r['controlled_real_time_factor']:.1f}x real time)"
    )
    click.echo(
        f"  raw mj_step: {r['raw_mj_step_per_s']:8.0f} steps/s "
        f"({r['raw_real_time_factor']:.1f}x real time)"
    )
    click.echo(f"  ratio (simulated time per wall second): {r['ratio']:.3f}")
    click.echo(f"  ratio of CPU time (less distorted on a busy machine): {r['cpu_ratio']:.3f}")
