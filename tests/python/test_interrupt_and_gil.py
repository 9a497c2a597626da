"""Runs release the GIL, and Ctrl-C (SIGINT, as a terminal or a notebook's "interrupt kernel"
sends it) stops a run at its next output row with the partial result kept, as the command line
keeps it."""

import os
import signal
import threading
import time

import pytest

import rollerdyn as rd
from conftest import model


def interrupt_after(seconds):
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_ctrl_c_keeps_the_partial_run():
    scene = rd.Scene.load(model("balanced-4cart.yaml")).with_({"simulation.t_end": 2000})
    interrupt_after(0.5)
    started = time.monotonic()
    with pytest.raises(rd.RunInterrupted) as e:
        rd.simulate(scene)
    assert time.monotonic() - started < 30  # stopped, not run to the end (2000 s take minutes)
    assert isinstance(e.value, KeyboardInterrupt)
    r = e.value.result
    assert not r.complete
    assert r.status.startswith("interrupted at t = ")
    assert r.summary["complete"] is False and r.summary["status"] == r.status
    t_last = r.timeseries["t"].iloc[-1]
    assert 0 < t_last < 2000 and len(r.reactions) == len(r.timeseries)


def test_ctrl_c_stops_a_sweep_and_keeps_the_points_done():
    scene = rd.Scene.load(model("balanced-4cart.yaml")).with_({"simulation.t_end": 20})
    interrupt_after(1.0)
    with pytest.raises(rd.RunInterrupted) as e:
        rd.sweep(scene, {"crank.offset_deg": "0:90:10"}, threads=1)
    df = e.value.result
    assert len(df) == 10
    assert (df["status"] == "not run (interrupted)").any()
    assert not (df["status"] == "completed").all()


def test_the_gil_is_released_during_a_run():
    """Another Python thread keeps running while a simulation runs (it could not if the run held
    the GIL: the ticks would stop for the whole run)."""
    ticks, done = [], threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        t0 = time.perf_counter()
        rd.simulate(rd.Scene.load(model("balanced-4cart.yaml")).with_({"simulation.t_end": 20}))
        t1 = time.perf_counter()
    finally:
        done.set()
        ticker.join()
    during = [t for t in ticks if t0 < t < t1]
    assert t1 - t0 > 0.05
    # Ticks all through the run: no gap longer than half of it.
    edges = [t0, *during, t1]
    assert max(b - a for a, b in zip(edges, edges[1:])) < 0.5 * (t1 - t0), (len(during), t1 - t0)
