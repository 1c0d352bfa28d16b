"""The GIL is released while solving, Ctrl-C stops a long batch, and every
docstring example runs."""

import doctest
import importlib
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import lcpbatch


def slow_batch(b=2048):
    # Enumeration of n = 12 without prediction visits 4096 bases per problem.
    rng = np.random.default_rng(10)
    A = rng.standard_normal((b, 12, 12))
    return A @ A.transpose(0, 2, 1) + np.eye(12), rng.standard_normal((b, 12))


def test_the_gil_is_released_while_solving():
    M, q = slow_batch(1024)
    s = lcpbatch.Solver(backend="cpu", method="enum", predict=False, threads=1)
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=count)
    t.start()
    start = time.perf_counter()
    s.solve(M, q)
    elapsed = time.perf_counter() - start
    done.set()
    t.join()
    during = [x for x in ticks if start <= x <= start + elapsed]
    # The other thread ran all along (with the GIL held it would stall).
    assert elapsed > 0.1 and len(during) > 0.3 * elapsed / 0.002, (elapsed, len(during))


@pytest.mark.skipif(sys.platform == "win32", reason="SIGINT to a child process")
def test_ctrl_c_stops_a_long_batch():
    code = textwrap.dedent(
        """
        import sys, time, numpy as np, lcpbatch
        sys.path.insert(0, %r)
        from test_runtime import slow_batch
        M, q = slow_batch(40 * 1024)   # about 40 chunks of ~0.7 s
        s = lcpbatch.Solver(backend="cpu", method="enum", predict=False)
        print("solving", flush=True)
        t = time.perf_counter()
        try:
            s.solve(M, q)
            print("finished", flush=True)
        except KeyboardInterrupt:
            print("interrupted after %%.1f s" %% (time.perf_counter() - t), flush=True)
        """ % os.path.dirname(__file__)
    )
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "solving"
    time.sleep(1.5)
    sent = time.perf_counter()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    waited = time.perf_counter() - sent
    assert out.startswith("interrupted"), out
    assert waited < 10, f"stopped {waited:.1f} s after Ctrl-C"


def test_a_forked_child_solves_on_threads_of_its_own():
    # Python's multiprocessing forks on Linux: the child inherits the
    # parent's thread pools but not their threads, and must not wait for them.
    code = textwrap.dedent(
        """
        import os, numpy as np, lcpbatch
        rng = np.random.default_rng(3)
        A = rng.standard_normal((2000, 4, 4))
        M = A @ A.transpose(0, 2, 1) + np.eye(4)
        q = rng.standard_normal((2000, 4))
        first = lcpbatch.Solver(backend="cpu", threads=2).solve(M, q)
        pid = os.fork()
        if pid == 0:
            again = lcpbatch.Solver(backend="cpu", threads=2).solve(M, q)
            os._exit(0 if np.array_equal(again.z, first.z) else 3)
        _, status = os.waitpid(pid, 0)
        print("child", os.waitstatus_to_exitcode(status), flush=True)
        """
    )
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, err = p.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)  # the child too
        pytest.fail("the forked child did not finish its solve in 60 s")
    assert out.strip() == "child 0", out + err


@pytest.mark.parametrize("module", ["lcpbatch", "lcpbatch._results", "lcpbatch._solver", "lcpbatch._friction", "lcpbatch._worlds"])
def test_docstring_examples_run(module):
    os.environ.setdefault("XDG_RUNTIME_DIR", "/tmp")
    result = doctest.testmod(importlib.import_module(module), verbose=False)
    assert result.attempted > 0 and result.failed == 0, result


def test_the_distributed_extra_is_named_when_dask_is_missing():
    code = (
        "import sys; sys.modules['distributed'] = None\n"
        "try:\n    import lcpbatch.distributed\nexcept ImportError as e:\n    print(e)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60).stdout
    assert "pip install 'lcpbatch[distributed]'" in out, out
