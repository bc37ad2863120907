"""Ctrl-C, memory over many renders, threads."""
import json
import os
import signal
import subprocess
import sys
import threading

import numpy as np
import pytest

import wavefront as wf
from conftest import CORNELL


def test_keyboard_interrupt_ends_the_render_within_a_pass(renderer, cornell):
    small = dict(width=16, spp=2, max_depth=3, seed=4)
    before = renderer.render(cornell, **small).image
    waves, at_signal = [], []
    started = threading.Event()

    def progress(done, total, seconds):
        waves.append(done)
        started.set()

    def interrupt():
        started.wait()
        os.kill(os.getpid(), signal.SIGINT)  # Python's handler: KeyboardInterrupt
        # Counted after the signal: waves the render finished while this thread waited to run
        # (a busy machine) came before it, and must not count against the render.
        at_signal.append(len(waves))

    sender = threading.Thread(target=interrupt)
    sender.start()
    with pytest.raises(KeyboardInterrupt):
        renderer.render(cornell, width=32, spp=1 << 20, max_depth=4, progress=progress)
    sender.join()
    # The wave in flight when the signal came may finish; no further one starts.
    assert len(waves) - at_signal[0] <= 2, (waves, at_signal)
    assert waves[-1] < 1 << 20
    # The renderer goes on as if nothing had happened.
    assert np.array_equal(renderer.render(cornell, **small).image, before)


def test_an_exception_in_progress_stops_the_render(renderer, cornell):
    def progress(done, total, seconds):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        renderer.render(cornell, width=16, spp=4096, max_depth=2, progress=progress)
    assert renderer.render(cornell, width=8, spp=1, max_depth=2).spp == 1


# Run in a fresh interpreter, validation on: 50 renders with new seeds (the kept renderer) and
# some with alternating settings (a renderer made and freed each time).
MEMORY_SCRIPT = r"""
import json, sys
import wavefront as wf

def rss():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096

r = wf.Renderer(validation=True)
scene = r.load(sys.argv[1])
sizes, allocations = [], []
for i in range(70):
    options = dict(width=16, max_depth=3, seed=i, aov=("albedo",))
    if i >= 50:
        options["spp"] = 1 + i % 2  # other settings: another renderer
    out = r.render(scene, **options)
    sizes.append(rss())
    allocations.append(wf.live_device_allocations())
messages = r.validation_messages
r.close()
print(json.dumps(dict(rss=sizes, allocations=allocations, messages=messages,
                      after_close=wf.live_device_allocations())))
"""


def test_memory_is_flat_and_device_memory_released():
    result = subprocess.run([sys.executable, "-c", MEMORY_SCRIPT, str(CORNELL)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    rss, allocations = data["rss"], data["allocations"]
    # Warm-up (first pipelines, caches) is over by render 10; from there, flat. The first
    # renders of the other settings compile their pipelines (lavapipe's code stays); the
    # alternation after them, a renderer made and freed each time, is flat again.
    for first, last in ((10, 50), (54, 70)):
        growth = max(rss[first:last]) - rss[first]
        assert growth < 3 << 20, f"resident memory grew {growth / 2**20:.1f} MiB: {rss}"
    assert len(set(allocations[1:50])) == 1, allocations  # the kept renderer's buffers
    assert max(allocations[50:]) == allocations[1], allocations  # one renderer at a time
    assert data["after_close"] == 0
    assert data["messages"] == 0
    # Objects left at vkDestroyDevice would be reported here, after close().
    assert "validation" not in result.stderr.lower(), result.stderr


def test_one_renderer_shared_by_threads(renderer, cornell):
    options = dict(width=12, spp=2, max_depth=3)
    expected = {seed: renderer.render(cornell, seed=seed, **options).image for seed in range(4)}
    results = {}

    def work(seed):
        results[seed] = renderer.render(cornell, seed=seed, **options).image

    threads = [threading.Thread(target=work, args=(seed,)) for seed in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(results[s], expected[s]) for s in range(4))


def test_exit_without_close_is_clean():
    code = ("import wavefront as wf, sys\n"
            "r = wf.Renderer()\n"
            "s = r.load(sys.argv[1])\n"
            "out = r.render(s, width=8, spp=1, max_depth=2)\n"
            "keep = (r, s, out)\n")
    result = subprocess.run([sys.executable, "-c", code, str(CORNELL)], capture_output=True,
                            text=True)
    assert result.returncode == 0, result.stderr
