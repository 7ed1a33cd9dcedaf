"""MuJoCo's free rigid body driven from Python, through a Node server of its WebAssembly build.

The shape many engine wrappers take: the engine lives in another runtime, and a small server beside
the wrapper answers one step per line. Here the server is mujoco_step_server.mjs, which steps with
mujoco_free_body.mjs's mj_step (npm mujoco-js 0.0.7, which `./geomech test` installs beside them):

    ./geomech check examples/engines/mujoco_through_python.py

The two lines below name the files this wrapper is made of, so that behind the sandbox
(`--untrusted`) they are shown with it; the package mujoco_free_body.mjs names (`// geomech: npm
mujoco-js`) is shown from a folder the grader trusts (GEOMECH_LIBRARY_ROOTS). Trusted or untrusted,
the verdicts are those of mujoco_free_body.mjs (ctest engines.mujoco.python_wrapper).
"""
# geomech: beside mujoco_step_server.mjs
# geomech: beside mujoco_free_body.mjs
import json
import os
import shutil
import subprocess

description = "MuJoCo 3 (npm mujoco-js 0.0.7, WebAssembly) free rigid body, mj_step, from Python through Node"

_HERE = os.path.dirname(os.path.abspath(__file__))
_server = {"pid": None, "process": None}


def _node():
    """One Node server per process: a check's session is a fork of this one, and a pipe is not shared."""
    if _server["pid"] != os.getpid():
        # GEOMECH_NODE: the Node the suite uses (set inside the sandbox too); else Node on PATH.
        node = os.environ.get("GEOMECH_NODE") or shutil.which("node") or "/usr/bin/node"
        _server["process"] = subprocess.Popen([node, os.path.join(_HERE, "mujoco_step_server.mjs")],
                                              stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        _server["pid"] = os.getpid()
    return _server["process"]


def _number(v):
    return float(v) if isinstance(v, str) else v  # "NaN", "Infinity", "-Infinity" from the server


def _step(integrator, I, x, h):
    node = _node()
    node.stdin.write(json.dumps({"integrator": integrator, "I": [float(c) for c in I],
                                 "q": [float(c) for c in x["q"]], "Omega": [float(c) for c in x["Omega"]],
                                 "h": float(h)}) + "\n")
    node.stdin.flush()
    line = node.stdout.readline()
    if not line:
        raise RuntimeError("the Node server of MuJoCo ended (exit status %s)" % node.poll())
    reply = json.loads(line)
    if "error" in reply:
        raise ValueError(reply["error"])
    return {"q": [_number(c) for c in reply["q"]], "Omega": [_number(c) for c in reply["Omega"]]}


def _integrator(name, integrator, claims):
    class Step:
        state = "quaternion_wxyz Omega"
        precision = "double"
        precision_reason = "MuJoCo's mjtNum is double, in its WebAssembly build too"

        @staticmethod
        def rigid_body_step(I, x, h):
            return _step(integrator, I, x, h)

    Step.name, Step.claims = name, claims
    return Step


# Claims as mujoco_free_body.mjs makes them (MuJoCo's documentation, "Numerical integration").
INTEGRATORS = [_integrator("mujoco_euler", "Euler", {"order": 1}),
               _integrator("mujoco_rk4", "RK4", {"order": 4})]
