"""What a newcomer meets first: the keyword ``method=`` (and ``solver=``, its
deprecated old name), no environment noise on stderr, device trouble told
once, and ``help()`` that lists every allowed value and every result field."""

import inspect
import os
import pydoc
import re
import subprocess
import sys
import warnings

import numpy as np
import pytest

import lcpbatch

M = np.array([[[2.0, 1.0], [1.0, 2.0]]])
Q = np.array([[-5.0, -6.0]])


def help_text(obj) -> str:
    """What ``help(obj)`` prints."""
    return pydoc.render_doc(obj, renderer=pydoc.plaintext)


# --- method= and the deprecated solver= -------------------------------------


def test_method_chooses_the_algorithm():
    r = lcpbatch.solve(M, Q, method="lemke", backend="cpu", predict=False)
    assert r.path.tolist() == ["lemke"] and r.pivots[0] > 0
    s = lcpbatch.Solver(backend="cpu", method="pgs")
    assert s.settings["method"] == "pgs" and "solver" not in s.settings
    assert s.solve(M, Q).path.tolist() == ["pgs"]


@pytest.mark.parametrize(
    "call",
    [
        lambda: lcpbatch.Solver(backend="cpu", solver="lemke").solve(M, Q),
        lambda: lcpbatch.solve(M, Q, solver="lemke", backend="cpu"),
        lambda: lcpbatch.solve_scenes(
            dict(inv_mass=[1.0], inv_inertia=[[1.0, 1.0, 1.0]], position=[[0, 1, 0]], velocity=[[0, -1, 0]]),
            dict(a=[0], point=[[0, 0, 0]], normal=[[0, 1, 0]]), solver="lemke", backend="cpu"),
    ],
    ids=["Solver", "solve", "solve_scenes"],
)
def test_solver_keyword_still_works_with_a_deprecation_warning(call):
    with pytest.warns(DeprecationWarning, match=r"solver= is deprecated; use method=") as caught:
        r = call()
    # The warning points at the caller's line (this file), not into lcpbatch.
    assert [os.path.basename(w.filename) for w in caught if w.category is DeprecationWarning] == [
        os.path.basename(__file__)
    ]
    paths = r.path.tolist()
    assert paths and set(paths) <= {"lemke", "single_contact", "separating", "predicted_basis"}


def test_solver_alias_gives_the_same_solver_as_method():
    with pytest.warns(DeprecationWarning):
        old = lcpbatch.Solver(backend="cpu", solver="enum", predict=False)
    new = lcpbatch.Solver(backend="cpu", method="enum", predict=False)
    assert old.settings == new.settings
    a, b = old.solve(M, Q), new.solve(M, Q)
    np.testing.assert_array_equal(a.z, b.z)
    assert a.path.tolist() == b.path.tolist() == ["enumerated_cpu"]


def test_method_and_a_different_solver_is_an_error():
    with pytest.raises(TypeError, match="give method= only"), pytest.warns(DeprecationWarning):
        lcpbatch.Solver(method="lemke", solver="pgs")


def test_a_bad_method_names_the_keyword_and_the_values():
    with pytest.raises(ValueError, match=r"method: 'simplex' is not one of 'auto', 'enum', 'lemke', 'pgs'"):
        lcpbatch.Solver(method="simplex")
    with pytest.raises(ValueError, match=r"friction_method: 'x' is not one of 'auto', 'nsgs', 'newton', "
                                         r"'prox', 'jacobi', 'pgs', 'apgd'"):
        lcpbatch.Solver(friction_method="x")


@pytest.mark.parametrize("method", ["auto", "nsgs", "newton", "jacobi", "pgs", "apgd"])
def test_every_friction_method_the_docs_list_is_accepted(method):
    W = np.eye(3)[None]
    q = np.array([[-1.0, 0.1, 0.0]])
    r = lcpbatch.solve_friction(W, q, 0.5, method=method, backend="cpu")
    assert r.ok.all(), (method, r.status_names())


# --- the environment ---------------------------------------------------------


def run_python(code: str, env: dict) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=600)


def test_no_xdg_runtime_dir_noise_and_the_variable_is_set_for_the_process():
    env = {k: v for k, v in os.environ.items() if k != "XDG_RUNTIME_DIR"}
    code = (
        "import os, numpy as np, lcpbatch\n"
        "print(os.environ['XDG_RUNTIME_DIR'])\n"
        "lcpbatch.adapters()\n"
        "r = lcpbatch.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]))\n"
        "assert r.ok.all()\n"
    )
    out = run_python(code, env)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip(), "XDG_RUNTIME_DIR not set by the package"
    assert "XDG_RUNTIME_DIR" not in out.stderr, out.stderr
    # A value the user set is kept.
    env["XDG_RUNTIME_DIR"] = "/nonexistent-runtime-dir"
    out = run_python("import os, lcpbatch; print(os.environ['XDG_RUNTIME_DIR'])", env)
    assert out.stdout.strip() == "/nonexistent-runtime-dir", out.stderr


def test_device_trouble_is_told_once_as_the_warning_not_on_stderr():
    code = (
        "import warnings, numpy as np, lcpbatch\n"
        "with warnings.catch_warnings(record=True) as caught:\n"
        "    warnings.simplefilter('always')\n"
        "    s = lcpbatch.Solver(backend='gpu', adapter='no-such-adapter-anywhere')\n"
        "    r = s.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]))\n"
        "    r = s.solve(np.array([[[2.0, 1.0], [1.0, 2.0]]]), np.array([[-5.0, -6.0]]))\n"
        "print(sum(w.category is lcpbatch.DeviceWarning for w in caught))\n"
        "print(r.report.fallback is not None)\n"
    )
    out = run_python(code, dict(os.environ))
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["1", "True"], out.stdout
    assert "solving on the CPU" not in out.stderr and "warning: GPU" not in out.stderr, out.stderr


# --- help() -------------------------------------------------------------------

SETTING_VALUES = {
    "backend": ["auto", "cpu", "gpu"],
    "method": ["auto", "enum", "enumeration", "lemke", "pgs"],
    "precision": ["auto", "f32", "f64"],
    "api": ["auto", "vulkan", "gl", "metal", "dx12"],
    "friction_method": ["auto", "nsgs", "newton", "prox", "jacobi", "pgs", "apgd"],
}


def test_the_values_listed_are_the_values_accepted():
    # Every value the docs list is accepted (a solver is built with it, the
    # GPU ones on the CPU when there is no GPU)...
    for setting, values in SETTING_VALUES.items():
        for v in values:
            if setting in ("backend", "precision", "api"):
                continue  # these may open a device; checked by the words below
            lcpbatch.Solver(backend="cpu", **{setting: v})
    # ...and a word outside them is refused, naming every listed value.
    for setting, values in SETTING_VALUES.items():
        with pytest.raises(ValueError) as e:
            lcpbatch.Solver(**{setting: "no-such-value"})
        listed = re.findall(r"'([a-z0-9_]+)'", str(e.value).split("is not one of", 1)[1])
        assert set(listed) <= set(values), (setting, listed)
        assert set(values) - {"enumeration"} <= set(listed), (setting, listed)


@pytest.mark.parametrize("fn", [lcpbatch.Solver, lcpbatch.solve, lcpbatch.solve_scenes,
                                lcpbatch.solve_friction, lcpbatch.simulate],
                         ids=lambda f: f.__name__)
def test_help_lists_every_setting_and_every_value(fn):
    text = help_text(fn)
    for name in inspect.signature(lcpbatch.Solver.__init__).parameters:
        if name != "self":
            assert f"``{name}``" in text, (fn.__name__, name)
    for setting, values in SETTING_VALUES.items():
        for v in values:
            assert f'"{v}"' in text, (fn.__name__, setting, v)
    assert "<settings>" not in text and "<fields>" not in text


def scene():
    bodies = dict(inv_mass=[1.0], inv_inertia=[[2.5, 2.5, 2.5]], position=[[0, 0.5, 0]],
                  velocity=[[0.3, -1.0, 0]])
    contacts = dict(a=[0], point=[[0, 0, 0]], normal=[[0, 1.0, 0]], restitution=0.5, mu=0.5)
    return bodies, contacts


def public_fields(result) -> set:
    names = {k for k in vars(result) if not k.startswith("_")}
    names |= {k for k, v in vars(type(result)).items()
              if not k.startswith("_") and isinstance(v, property)}
    return names


@pytest.mark.parametrize(
    "fn, make",
    [
        (lcpbatch.solve, lambda: lcpbatch.solve(M, Q, backend="cpu")),
        (lcpbatch.solve_scenes, lambda: lcpbatch.solve_scenes(*scene(), backend="cpu")),
        (lcpbatch.solve_friction, lambda: lcpbatch.solve_friction(np.eye(3)[None], Q[:, [0, 1, 1]], 0.5,
                                                                  backend="cpu")),
        (lcpbatch.simulate, lambda: lcpbatch.simulate(lcpbatch.World.generate("slide"), 0.01, 2, backend="cpu")),
    ],
    ids=["solve", "solve_scenes", "solve_friction", "simulate"],
)
def test_help_of_each_function_and_its_result_lists_every_result_field(fn, make):
    result = make()
    fields = public_fields(result)
    assert len(fields) >= 8
    for text in (help_text(fn), help_text(type(result))):
        missing = sorted(f for f in fields if f"``{f}``" not in text)
        assert not missing, (fn.__name__, missing)


def test_help_of_the_report_lists_every_figure_and_key():
    r = lcpbatch.solve(M, Q, backend="cpu").report
    text = help_text(lcpbatch.Report)
    for f in r.FIELDS + ("text",):
        assert f"``{f}``" in text, f
    for table in ("counts", "timings"):
        for key in getattr(r, table):
            assert f'"{key}"' in text, (table, key)
    for name in lcpbatch.PATH_NAMES:
        assert f'"{name}"' in text, name
    gpu_keys = ("chunks", "dispatches", "rounds", "tree_decided", "tree_undecided", "max_gpu_error",
                "max_velocity_deviation", "pack_seconds", "upload_seconds", "kernel_seconds",
                "readback_seconds")
    for key in gpu_keys:
        assert f'"{key}"' in text, key
    for kind in ("cpu", "hardware_gpu", "software_gpu"):
        assert f'"{kind}"' in text, kind


def test_help_of_world_kinds_names_every_generator():
    text = help_text(lcpbatch.World.kinds)
    for kind in lcpbatch.World.kinds():
        assert f'"{kind}"' in text, kind


def test_docs_cite_papers_or_readme_sections_not_seed_files():
    import lcpbatch._friction as fr
    import lcpbatch._scenes as sc
    import lcpbatch._worlds as wo

    for obj in (lcpbatch, lcpbatch.Solver, lcpbatch.solve, lcpbatch.solve_scenes, lcpbatch.solve_friction,
                lcpbatch.simulate, lcpbatch.World, lcpbatch.Report, fr, sc, wo):
        assert not re.search(r"[Ss]eed 00\d", help_text(obj)), obj


def test_help_warns_no_deprecation_and_the_method_default_is_auto():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        help_text(lcpbatch.solve)
        s = lcpbatch.Solver(backend="cpu")
    assert s.settings["method"] == "auto"
